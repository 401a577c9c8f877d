// The knowledge planner's own data as the program shows it (PlannerEntry::account): the look-ahead in
// report.json, check and on the console, its push order as arrows, where a failed search stood.

#include "planner_data.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace physltl::planners::knowledge {

using geometry::Vec2;

namespace {

using json = nlohmann::ordered_json;

// Pushes named on the console's line; the rest are counted.
constexpr std::size_t kPushesShown = 8;

std::vector<std::string> body_names(const scenario::World& world) {
  std::vector<std::string> names;
  for (const auto& b : world.movable_bodies) names.push_back(b.name);
  return names;
}

// "lookahead  2 pushes: M1 +x 4.2 m, M1 -y 1.8 m", or why there is no order.
std::string lookahead_line(const PushPlan& plan, const scenario::World& world) {
  std::string line = "lookahead  ";
  if (!plan.rule.applies) return line + "off: " + plan.rule.reason;
  const long long run_budget = lookahead::run_arrangements(world.planner.time_limit);
  if (!plan.found && plan.budget < run_budget && plan.outcome == "search limit") {
    return line + fmt::format("no push order within check's budget of {} arrangements (a run of {:g} s searches up to {}): {}",
                              plan.budget, world.planner.time_limit, run_budget, plan.rule.reason);
  }
  if (!plan.found) return line + fmt::format("no push order ({}, {} arrangements): {}", plan.outcome, plan.arrangements, plan.rule.reason);
  const std::vector<std::string> names = body_names(world);
  std::vector<std::string> shown;
  for (std::size_t i = 0; i < plan.pushes.size() && i < kPushesShown; ++i) shown.push_back(describe(plan.pushes[i], names));
  if (plan.pushes.size() > kPushesShown) shown.push_back(fmt::format("... {} more", plan.pushes.size() - kPushesShown));
  return line + fmt::format("{} push{}: {}", plan.pushes.size(), plan.pushes.size() == 1 ? "" : "es", fmt::join(shown, ", "));
}

json lookahead_json(const PushPlan& plan, const scenario::World& world) {
  json pushes = json::array();
  for (const PlannedPush& push : plan.pushes) {
    json ahead = json::array();
    for (int b : push.ahead) ahead.push_back(world.movable_bodies[static_cast<std::size_t>(b)].name);
    pushes.push_back({{"body", world.movable_bodies[static_cast<std::size_t>(push.body)].name},
                      {"ahead", ahead},
                      {"direction", direction_name(push)},
                      {"distance", push.distance},
                      {"from", {push.from.x(), push.from.y()}},
                      {"to", {push.to.x(), push.to.y()}}});
  }
  return {{"applies", plan.rule.applies},
          {"reason", plan.rule.reason},
          {"step", plan.rule.applies ? json(plan.rule.step) : json(nullptr)},
          {"outcome", plan.outcome},
          {"arrangements", plan.arrangements},
          {"arrangement_budget", plan.budget > 0 ? json(plan.budget) : json(nullptr)},
          {"pushes", pushes}};
}

json stage_json(const SearchEnd::Stage& stage) {
  return {{"automaton_state", stage.automaton_state}, {"object_facts", stage.facts}, {"moves_to_acceptance", stage.distance}};
}

json search_end_json(const SearchEnd& end, const scenario::World& world) {
  json lead = json::array();
  for (const auto& step : end.lead) lead.push_back({{"at", {step.point.x(), step.point.y()}}, {"automaton_state", step.automaton_state}});
  json stages = json::array();
  for (const auto& s : end.nodes_per_stage) {
    json entry = stage_json(s.stage);
    entry["nodes"] = s.nodes;
    entry["dropped_nodes"] = s.dropped;
    stages.push_back(std::move(entry));
  }
  return {{"frontier", stage_json(end.frontier)},
          {"lead", lead},
          {"body_move", end.body_move.empty() ? json(nullptr) : json(end.body_move)},
          {"nodes_per_stage", stages},
          {"order_push", end.order_push == 0 ? json(nullptr)
                                             : json{{"index", end.order_push}, {"of", end.order_pushes},
                                                    {"push", describe(end.unfinished_push, body_names(world))}}},
          {"expansions_since_progress", end.expansions_since_progress},
          {"widened", end.widened}};
}

planning::PlannerAccount preparation_account(const KnowledgePreparation& prepared, const scenario::World& world) {
  planning::PlannerAccount account;
  const PushPlan& plan = prepared.lookahead.plan;
  account.report["lookahead"] = lookahead_json(plan, world);
  // The main job names the look-ahead only for tasks that move bodies; check always says what it concluded.
  (prepared.task_names_bodies ? account.lines : account.details).push_back(lookahead_line(plan, world));
  return account;
}

planning::PlannerAccount search_account(const SearchReport& report, const scenario::World& world) {
  planning::PlannerAccount account;
  account.report["lookahead"] = nullptr;
  if (report.lookahead) {
    account.report["lookahead"] = lookahead_json(*report.lookahead, world);
    account.report["lookahead"]["replans"] = report.lookahead_replans;
    account.report["lookahead"]["primitive_controls"] = report.primitive_controls;
    for (const PlannedPush& push : report.lookahead->pushes) account.moves.push_back({push.from, push.to, Vec2(push.dx, push.dy), push.body});
    if (!report.lookahead->pushes.empty()) {
      account.moves_legend = fmt::format("look-ahead: {} push{}, arrows light (first) to dark (last)",
                                         report.lookahead->pushes.size(), report.lookahead->pushes.size() == 1 ? "" : "es");
    }
  }
  if (report.end) account.diagnosis["search_end"] = search_end_json(*report.end, world);
  return account;
}

}  // namespace

planning::PlannerAccount knowledge_account(const planning::PlannerData& data, const scenario::World& world) {
  if (const auto* prepared = dynamic_cast<const KnowledgePreparation*>(&data)) return preparation_account(*prepared, world);
  if (const auto* report = dynamic_cast<const SearchReport*>(&data)) return search_account(*report, world);
  return {};
}

}  // namespace physltl::planners::knowledge
