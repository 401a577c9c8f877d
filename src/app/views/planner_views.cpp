#include "planner_views.h"

#include <algorithm>

namespace physltl::app {
namespace {

// The arrows' colours, first move to last, and their heads.
constexpr render::Color kFirstMove{1.0f, 0.9f, 0.2f, 1.0f};
constexpr render::Color kLastMove{0.35f, 0.0f, 0.45f, 1.0f};
constexpr double kHeadLength = 0.12;  // m
constexpr double kShaftWidth = 0.012;  // m between the parallel lines that thicken a shaft

render::Color blend(const render::Color& a, const render::Color& b, float t) {
  return {a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b), 1.0f};
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
  const std::size_t n = account.moves.size();
  for (std::size_t i = 0; i < n; ++i) {
    const planning::PlannerAccount::Move& move = account.moves[i];
    const render::Color color = blend(kFirstMove, kLastMove, n > 1 ? static_cast<float>(i) / static_cast<float>(n - 1) : 1.0f);
    const geometry::Vec2 d = move.direction, side(-d.y(), d.x());
    for (int k = -1; k <= 1; ++k) moves.arrows.push_back({move.from + k * kShaftWidth * side, move.to + k * kShaftWidth * side, color});
    for (int s : {-1, 1}) moves.arrows.push_back({move.to, move.to - kHeadLength * d + s * 0.6 * kHeadLength * side, color});
  }
  if (n > 0) moves.legend = account.moves_legend;
  return moves;
}

}  // namespace physltl::app
