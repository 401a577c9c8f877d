#include "lookahead_summary.h"

#include <fmt/format.h>

namespace physltl::app {
namespace {

// Pushes named on the main job's line; the rest are counted.
constexpr std::size_t kPushesShown = 8;

std::vector<std::string> body_names(const scenario::World& world) {
  std::vector<std::string> names;
  for (const auto& b : world.movable_bodies) names.push_back(b.name);
  return names;
}

// The arrows' colours, first push to last, and their heads.
constexpr render::Color kFirstPush{1.0f, 0.9f, 0.2f, 1.0f};
constexpr render::Color kLastPush{0.35f, 0.0f, 0.45f, 1.0f};
constexpr double kHeadLength = 0.12;  // m
constexpr double kShaftWidth = 0.012;  // m between the parallel lines that thicken a shaft

render::Color blend(const render::Color& a, const render::Color& b, float t) {
  return {a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b), 1.0f};
}

}  // namespace

std::vector<render::SegmentOverlay> push_arrows(const planning::PushPlan& plan) {
  std::vector<render::SegmentOverlay> arrows;
  const std::size_t n = plan.pushes.size();
  for (std::size_t i = 0; i < n; ++i) {
    const planning::PlannedPush& push = plan.pushes[i];
    const render::Color color = blend(kFirstPush, kLastPush, n > 1 ? static_cast<float>(i) / static_cast<float>(n - 1) : 1.0f);
    const geometry::Vec2 d(push.dx, push.dy), side(-push.dy, push.dx);
    for (int k = -1; k <= 1; ++k) arrows.push_back({push.from + k * kShaftWidth * side, push.to + k * kShaftWidth * side, color});
    for (int s : {-1, 1}) arrows.push_back({push.to, push.to - kHeadLength * d + s * 0.6 * kHeadLength * side, color});
  }
  return arrows;
}

std::string push_arrows_legend(const planning::PushPlan& plan) {
  return fmt::format("look-ahead: {} push{}, arrows light (first) to dark (last)", plan.pushes.size(),
                     plan.pushes.size() == 1 ? "" : "es");
}

std::string lookahead_line(const planning::PushPlan& plan, const scenario::World& world) {
  if (!plan.rule.applies) return "off: " + plan.rule.reason;
  if (!plan.found) return fmt::format("no push order ({}, {} arrangements): {}", plan.outcome, plan.arrangements, plan.rule.reason);
  const std::vector<std::string> names = body_names(world);
  std::vector<std::string> shown;
  for (std::size_t i = 0; i < plan.pushes.size() && i < kPushesShown; ++i) shown.push_back(planning::describe(plan.pushes[i], names));
  if (plan.pushes.size() > kPushesShown) shown.push_back(fmt::format("... {} more", plan.pushes.size() - kPushesShown));
  return fmt::format("{} push{}: {}", plan.pushes.size(), plan.pushes.size() == 1 ? "" : "es", fmt::join(shown, ", "));
}

nlohmann::ordered_json lookahead_json(const planning::PushPlan& plan, const scenario::World& world) {
  nlohmann::ordered_json pushes = nlohmann::ordered_json::array();
  for (const planning::PlannedPush& push : plan.pushes) {
    nlohmann::ordered_json ahead = nlohmann::ordered_json::array();
    for (int b : push.ahead) ahead.push_back(world.movable_bodies[static_cast<std::size_t>(b)].name);
    pushes.push_back({{"body", world.movable_bodies[static_cast<std::size_t>(push.body)].name},
                      {"ahead", ahead},
                      {"direction", planning::direction_name(push)},
                      {"distance", push.distance},
                      {"from", {push.from.x(), push.from.y()}},
                      {"to", {push.to.x(), push.to.y()}}});
  }
  return {{"applies", plan.rule.applies},
          {"reason", plan.rule.reason},
          {"step", plan.rule.applies ? nlohmann::ordered_json(plan.rule.step) : nlohmann::ordered_json(nullptr)},
          {"outcome", plan.outcome},
          {"arrangements", plan.arrangements},
          {"pushes", pushes}};
}

}  // namespace physltl::app
