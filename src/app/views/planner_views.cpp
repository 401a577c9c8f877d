#include "planner_views.h"

#include <algorithm>

namespace physltl::app {
namespace {

// The arrows' colours, first move to last, and their heads.
constexpr render::Color kFirstMove{1.0f, 0.9f, 0.2f, 1.0f};
constexpr render::Color kLastMove{0.35f, 0.0f, 0.45f, 1.0f};
constexpr double kHeadLength = 0.12;  // m
constexpr double kShaftWidth = 0.012;  // m between the parallel lines that thicken a shaft

constexpr render::Color kMoveDone{0.6f, 0.6f, 0.6f, 1.0f};
constexpr render::Color kMoveUnderWay{0.9f, 0.1f, 0.1f, 1.0f};
constexpr double kNearEnd = 0.3;  // m: at most this far from a move's end, a body has carried it out
constexpr double kNearShare = 0.45;  // of the move's length: a body pushed halfway has not carried it out

render::Color blend(const render::Color& a, const render::Color& b, float t) {
  return {a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b), 1.0f};
}

render::Color planned_color(std::size_t move, std::size_t moves) {
  return blend(kFirstMove, kLastMove, moves > 1 ? static_cast<float>(move) / static_cast<float>(moves - 1) : 1.0f);
}

// A shaft of three parallel lines and a head.
void add_arrow(const planning::PlannerAccount::Move& move, const render::Color& color, std::vector<render::SegmentOverlay>& out) {
  const geometry::Vec2 d = move.direction, side(-d.y(), d.x());
  for (int k = -1; k <= 1; ++k) out.push_back({move.from + k * kShaftWidth * side, move.to + k * kShaftWidth * side, color});
  for (int s : {-1, 1}) out.push_back({move.to, move.to - kHeadLength * d + s * 0.6 * kHeadLength * side, color});
}

}  // namespace

planning::PlannerAccount account_of(const planning::PlannerEntry& planner, const planning::PlannerData* data,
                                    const scenario::World& world) {
  if (data == nullptr || !planner.account) return {};
  return planner.account(*data, world);
}

void add_planner_keys(nlohmann::ordered_json& report, const std::vector<std::string>& keys, const nlohmann::ordered_json& values) {
  for (const std::string& key : keys) report[key] = values.contains(key) ? values.at(key) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json refusals_json(const std::vector<std::pair<std::string, long long>>& counts) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const auto& [rule, count] : counts) json[rule] = count;
  return json;
}

PlannedMoves planned_moves(const planning::PlannerAccount& account) {
  PlannedMoves moves;
  moves.moves = account.moves;
  for (std::size_t i = 0; i < account.moves.size(); ++i) add_arrow(account.moves[i], planned_color(i, account.moves.size()), moves.arrows);
  if (!account.moves.empty()) moves.legend = account.moves_legend;
  return moves;
}

int PlannedMoves::carried_out(int done, const scenario::StateTrace& trace, std::size_t step) const {
  const std::size_t bodies = trace.front().movable_poses.size();
  for (; done < static_cast<int>(moves.size()); ++done) {
    const planning::PlannerAccount::Move& move = moves[static_cast<std::size_t>(done)];
    const double near = std::min(kNearEnd, kNearShare * (move.to - move.from).norm());
    const auto near_end = [&](std::size_t body) { return (trace.body_pose(body, step).position - move.to).norm() <= near; };
    bool there = move.body >= 0 && near_end(static_cast<std::size_t>(move.body));
    for (std::size_t body = 0; move.body < 0 && body < bodies && !there; ++body) there = near_end(body);
    if (!there) break;
  }
  return done;
}

std::vector<render::SegmentOverlay> PlannedMoves::arrows_after(int done, bool plan_ended) const {
  std::vector<render::SegmentOverlay> shown;
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const auto k = static_cast<std::size_t>(done);
    add_arrow(moves[i], i < k ? kMoveDone : i == k && !plan_ended ? kMoveUnderWay : planned_color(i, moves.size()), shown);
  }
  return shown;
}

std::string PlannedMoves::legend_after(int done, bool plan_ended) const {
  const auto n = static_cast<int>(moves.size());
  const std::string pushes = std::to_string(n) + (n == 1 ? " push" : " pushes");
  if (done >= n) return "look-ahead: " + std::to_string(n) + " of " + pushes + " carried out (grey)";
  if (plan_ended) return "look-ahead: " + std::to_string(done) + " of " + pushes + " carried out as planned (grey)";
  return "look-ahead: push " + std::to_string(done + 1) + " of " + std::to_string(n) + " under way (red), done grey";
}

}  // namespace physltl::app
