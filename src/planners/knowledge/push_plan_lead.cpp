#include "push_plan_lead.h"

#include <algorithm>
#include <cmath>

namespace physltl::planning {
namespace {

using lookahead::kDirections;
using lookahead::kDx;
using lookahead::kDy;

constexpr int kNever = std::numeric_limits<int>::max();
// A push is done when its body is this close to the place it goes to, along the push: a box 0.5 m wide
// has 5 cm to either side in a corridor of 0.6 m it turns into.
constexpr double kArrive = 0.04;  // m
// And this close across it, which pushing does not correct: a node whose body has drifted sideways ranks
// behind one on the line, by kDriftWeight metres of work per metre of drift. Pushing a line, the body
// that drifted most counts: the one in front must meet its place too.
constexpr double kAlign = 0.06;  // m
constexpr double kDriftWeight = 3.0;
// A node fits a push when every body is this close to where the push wants it (the pushed one to its
// line): further off, the next pushes of the order would not start from their places.
constexpr double kOnOrder = 0.10;  // m
// The robot goes straight for the body's side once this close to the push's line; else to the middle of
// the place behind the body first, so that it does not clip the body's corner on the way.
constexpr double kOnLine = 0.10;  // m
// The robot stands ready to push when it touches the body's side from behind, give or take this much,
// and no further to the side than this share of the body's half width.
constexpr double kReadyDepth = 0.12;  // m
constexpr double kReadyLateral = 0.5;
// Places ahead the robot aims at along its walk: two keep it off the corners of the places it turns at.
constexpr int kWalkAhead = 1;
// Getting ready to push, at the place behind the body, counts as this share of a step of walking.
constexpr double kGetReady = 0.5;
// A robot that cannot walk to its push along the lattice counts this many metres from it.
constexpr double kNoWay = 100.0;  // m

geometry::Vec2 direction_of(int d) { return {kDx[d], kDy[d]}; }

// Robot steps from every place to `goal` round the places held in `held`.
std::vector<int> walk_to(const lookahead::PushLattice& lattice, int goal, const std::vector<int>& held) {
  std::vector<int> steps(static_cast<std::size_t>(lattice.cells()), kNever);
  std::vector<bool> blocked(static_cast<std::size_t>(lattice.cells()), false);
  for (int c : held) blocked[static_cast<std::size_t>(c)] = true;
  if (goal < 0 || !lattice.robot_fits(goal) || blocked[static_cast<std::size_t>(goal)]) return steps;
  std::vector<int> queue{goal};
  steps[static_cast<std::size_t>(goal)] = 0;
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const int c = queue[i];
    for (int d = 0; d < kDirections; ++d) {
      if (!lattice.robot_passes(c, d)) continue;
      const int next = lattice.neighbour(c, d);
      if (blocked[static_cast<std::size_t>(next)] || steps[static_cast<std::size_t>(next)] != kNever) continue;
      steps[static_cast<std::size_t>(next)] = steps[static_cast<std::size_t>(c)] + 1;
      queue.push_back(next);
    }
  }
  return steps;
}

}  // namespace

PushPlanLead::PushPlanLead(const lookahead::PushLattice& lattice, const std::vector<int>& start_cells,
                           const std::vector<lookahead::PushStep>& steps, const knowledge::AbstractKnowledge& knowledge)
    : lattice_(lattice), robot_radius_(knowledge.robot.radius) {
  std::vector<int> cells = start_cells;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const lookahead::PushStep& step = steps[i];
    if (i == 0 || !lookahead::same_run(steps[i - 1], step)) {
      runs_.push_back({step.body, step.ahead, step.direction, step.from, step.to, cells, {}, 0.0});
    }
    runs_.back().to = step.to;
    cells[static_cast<std::size_t>(step.body)] = step.to;
    for (int k : step.ahead) cells[static_cast<std::size_t>(k)] = lattice.neighbour(cells[static_cast<std::size_t>(k)], step.direction);
  }
  for (Run& run : runs_) {
    run.walk = walk_to(lattice, lattice.neighbour(run.from, lookahead::opposite(run.direction)), run.before);
    run.length = (lattice.centre(run.to) - lattice.centre(run.from)).norm();
  }
  for (int j = static_cast<int>(runs_.size()) - 2; j >= 0; --j) {
    const Run& next = runs_[static_cast<std::size_t>(j) + 1];
    const Run& run = runs_[static_cast<std::size_t>(j)];
    const int robot_after = lattice.neighbour(run.to, lookahead::opposite(run.direction));
    const int walk = robot_after < 0 ? kNever : next.walk[static_cast<std::size_t>(robot_after)];
    runs_[static_cast<std::size_t>(j)].after =
        next.after + next.length + (walk == kNever ? kNoWay : (walk + kGetReady) * lattice.step());
  }
  for (int k : cells) end_positions_.push_back(lattice.centre(k));
  if (!runs_.empty() && !runs_.back().ahead.empty()) {
    // A line ends the order short of its places: the gaps between its bodies closed.
    const Run& last = runs_.back();
    std::vector<int> line{last.body};
    line.insert(line.end(), last.ahead.begin(), last.ahead.end());
    const std::vector<double> shortfalls = lattice.line_shortfalls(line, last.direction).value_or(std::vector<double>(last.ahead.size()));
    for (std::size_t i = 0; i < last.ahead.size(); ++i) {
      end_positions_[static_cast<std::size_t>(last.ahead[i])] -= shortfalls[i] * direction_of(last.direction);
    }
  }
}

const std::vector<int>& PushPlanLead::walk_behind(int j, int body_cell) const {
  const Run& run = runs_[static_cast<std::size_t>(j)];
  if (body_cell == run.from) return run.walk;
  auto& walk = walks_[{j, body_cell}];
  if (walk.empty()) {
    std::vector<int> held = run.before;
    held[static_cast<std::size_t>(run.body)] = body_cell;
    walk = walk_to(lattice_, lattice_.neighbour(body_cell, lookahead::opposite(run.direction)), held);
  }
  return walk;
}

geometry::Vec2 PushPlanLead::position(const physics::PhysicsState& state, int k) const {
  const auto b = static_cast<std::size_t>(lattice_.bodies()[static_cast<std::size_t>(k)]) + 1;  // the robot is body 0
  return {state.value(b, 0), state.value(b, 1)};
}

std::optional<PushPlanLead::Along> PushPlanLead::along(const physics::PhysicsState& state, int j) const {
  const double tolerance = kOnOrder;
  if (j == pushes()) {
    for (std::size_t k = 0; k < end_positions_.size(); ++k) {
      if ((position(state, static_cast<int>(k)) - end_positions_[k]).norm() > tolerance) return std::nullopt;
    }
    return Along{};
  }
  const std::vector<int>& places = runs_[static_cast<std::size_t>(j)].before;
  const auto moving = [&](int k) {
    const Run& run = runs_[static_cast<std::size_t>(j)];
    return k == run.body || std::find(run.ahead.begin(), run.ahead.end(), k) != run.ahead.end();
  };
  for (std::size_t k = 0; k < places.size(); ++k) {
    if (moving(static_cast<int>(k))) continue;
    if ((position(state, static_cast<int>(k)) - lattice_.centre(places[k])).norm() > tolerance) return std::nullopt;
  }
  const Run& run = runs_[static_cast<std::size_t>(j)];
  const geometry::Vec2 d = direction_of(run.direction);
  // How far body k has come along the push from its place before it, and how far off the push's line.
  const auto offset_of = [&](int k) -> std::optional<Along> {
    const geometry::Vec2 offset = position(state, k) - lattice_.centre(places[static_cast<std::size_t>(k)]);
    const double a = offset.dot(d);
    const double lateral = std::abs(offset.x() * d.y() - offset.y() * d.x());
    if (lateral > tolerance || a < -tolerance || a > run.length + tolerance) return std::nullopt;
    return Along{a, lateral};
  };
  std::optional<Along> pushed = offset_of(run.body);
  if (!pushed) return std::nullopt;
  for (int k : run.ahead) {
    const std::optional<Along> ahead = offset_of(k);
    if (!ahead) return std::nullopt;
    pushed->drift = std::max(pushed->drift, ahead->drift);
  }
  return pushed;
}

bool PushPlanLead::ready_to_push(const geometry::Vec2& robot, const geometry::Vec2& body, int j) const {
  const Run& run = runs_[static_cast<std::size_t>(j)];
  const geometry::Vec2 d = direction_of(run.direction);
  const geometry::Vec2 v = body - robot;
  const double touching = lattice_.half_along(run.body, run.direction) + robot_radius_;
  const double half_width = lattice_.half_along(run.body, lookahead::perpendicular(run.direction));
  const double depth = v.dot(d);
  const double lateral = std::abs(v.x() * d.y() - v.y() * d.x());
  return depth >= touching - kReadyDepth && depth <= touching + kReadyDepth && lateral <= kReadyLateral * half_width;
}

double PushPlanLead::robot_way(const geometry::Vec2& robot, const geometry::Vec2& body, int j) const {
  if (ready_to_push(robot, body, j)) return 0.0;
  const int cell = lattice_.robot_cell(robot);
  const int body_cell = lattice_.cell_at(body);
  if (cell < 0 || body_cell < 0) return kNoWay;
  const std::vector<int>& walk = walk_behind(j, body_cell);
  if (walk[static_cast<std::size_t>(cell)] == kNever) return kNoWay;
  return (walk[static_cast<std::size_t>(cell)] + kGetReady) * lattice_.step();
}

PushPlanLead::Progress PushPlanLead::progress(const physics::PhysicsState& state, int hint) const {
  // Off the order, every push is tried; on it, the next few: one motion may finish a push and start another.
  const int first = std::max(0, hint);
  const int last = hint < 0 ? pushes() : std::min(pushes(), hint + 2);
  Progress done_here;
  for (int j = first; j <= last; ++j) {
    const std::optional<Along> a = along(state, j);
    if (!a) continue;
    if (j == pushes()) return {j, 0.0};
    const Run& run = runs_[static_cast<std::size_t>(j)];
    const geometry::Vec2 body = position(state, run.body);
    const double left = std::abs(run.length - a->distance);
    const Progress here{j, run.after + left + kDriftWeight * a->drift + robot_way(state.robot_position(), body, j)};
    if (left > kArrive || a->drift > kAlign) return here;
    done_here = here;  // this push is done: the next may fit too
  }
  return done_here;
}

std::optional<PushPlanLead::Target> PushPlanLead::target(const physics::PhysicsState& state, int push) const {
  if (push < 0 || push >= pushes()) return std::nullopt;
  const Run& run = runs_[static_cast<std::size_t>(push)];
  const geometry::Vec2 d = direction_of(run.direction);
  const geometry::Vec2 robot = state.robot_position();
  const geometry::Vec2 body = position(state, run.body);
  const double touching = lattice_.half_along(run.body, run.direction) + robot_radius_;
  // Pushing: to where the robot stands behind the body on its place, which also steers the body back onto
  // the lattice's line.
  if (ready_to_push(robot, body, push)) return Target{lattice_.centre(run.to) - touching * d, true};
  const geometry::Vec2 behind = body - (touching + 0.02) * d;
  int cell = lattice_.robot_cell(robot);
  const int body_cell = lattice_.cell_at(body);
  if (cell < 0 || body_cell < 0) return std::nullopt;
  const std::vector<int>& walk = walk_behind(push, body_cell);
  const auto steps = [&](int c) { return c < 0 ? kNever : walk[static_cast<std::size_t>(c)]; };
  if (steps(cell) == kNever) {
    // The robot's nearest place is one a body holds, or off the walk: the neighbour nearest its push.
    int best = -1;
    for (int k = 0; k < kDirections; ++k) {
      const int n = lattice_.neighbour(cell, k);
      if (steps(n) != kNever && (best < 0 || steps(n) < steps(best))) best = n;
    }
    if (best < 0) return std::nullopt;
    cell = best;
  }
  for (int ahead = 0; ahead < kWalkAhead && steps(cell) > 0; ++ahead) {
    for (int k = 0; k < kDirections; ++k) {
      const int n = lattice_.neighbour(cell, k);
      if (lattice_.robot_passes(cell, k) && steps(n) == steps(cell) - 1) {
        cell = n;
        break;
      }
    }
  }
  const double off_line = std::abs((robot - body).x() * d.y() - (robot - body).y() * d.x());
  return Target{steps(cell) == 0 && off_line <= kOnLine ? behind : lattice_.centre(cell), false};
}

}  // namespace physltl::planning
