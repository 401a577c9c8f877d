#include "push_plan_lead.h"

#include <algorithm>
#include <cmath>

namespace physltl::planners::knowledge {
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
// The robot walks to this far behind the body's side before it pushes.
constexpr double kBehindGap = 0.02;  // m

// The push primitive (steer). Walking, it heads for the point kPursuit metres ahead of its nearest point
// on the way, which keeps it on the line through the places' centres in a corridor a few centimetres
// wider than it, and turns corners by cutting them by a few centimetres, slowing to kCornerSpeed of its
// top speed at each; it slows to arrive behind the body in kArriveTime. Pushing, it heads along the push, closes its offset from the line through the
// body's centre within kCloseTime (it starts within kSquareBehind of it), and slows to reach the place in
// kArriveTime, no slower than kCreep of its top speed. It does not steer the body back onto the push's
// line: that would take the robot off its own, and in a corridor onto a wall; pushed through its centre,
// a body keeps the offset it had.
constexpr double kPursuit = 0.15;     // m
constexpr double kArriveTime = 0.4;   // s
constexpr double kCloseTime = 0.1;    // s
constexpr double kSquareBehind = 0.015;  // m
constexpr double kTouching = 0.005;      // m
constexpr double kCreep = 0.15;
constexpr double kCornerSpeed = 0.25;  // share of the top speed at a corner of the way
constexpr double kPushSpeed = 0.8;    // share of the top speed: a box shoved at full speed slides past its place
// A push's controls last this long, so that the plan's push count stays near the order's; walking
// controls are as short as the scenario allows, to turn its corners.
constexpr double kPushControlTime = 0.3;  // s
// Places of the way ahead the pursuit looks along.
constexpr int kWayAhead = 3;

geometry::Vec2 direction_of(int d) { return {kDx[d], kDy[d]}; }

// Where the robot stands to push lattice body k on `cell` in direction d, the lattice bodies on `held`:
// nearest the body's centre line of the places behind it that it fits in and no other body covers.
int stand_of(const lookahead::PushLattice& lattice, int k, int cell, int d, const std::vector<int>& held) {
  return lattice.first_stand(k, cell, d, [&](int c) {
    if (!lattice.robot_fits(c)) return false;
    bool free = true;
    for (std::size_t j = 0; j < held.size() && free; ++j) {
      if (static_cast<int>(j) != k) lattice.for_each_cover(static_cast<int>(j), held[j], [&](int covered) { free &= covered != c; });
    }
    return free;
  });
}

// Robot steps from every place to `goal` round the places the lattice bodies on `held` cover.
std::vector<int> walk_to(const lookahead::PushLattice& lattice, int goal, const std::vector<int>& held) {
  std::vector<int> steps(static_cast<std::size_t>(lattice.cells()), kNever);
  std::vector<bool> blocked(static_cast<std::size_t>(lattice.cells()), false);
  for (std::size_t k = 0; k < held.size(); ++k) {
    lattice.for_each_cover(static_cast<int>(k), held[k], [&](int c) { blocked[static_cast<std::size_t>(c)] = true; });
  }
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

// The point `ahead` metres along `way` (a polyline) from its point nearest `p`; its end when that is nearer.
geometry::Vec2 pursuit_point(const std::vector<geometry::Vec2>& way, const geometry::Vec2& p, double ahead) {
  std::size_t segment = 0;
  double along = 0.0, nearest = (p - way.front()).norm();
  for (std::size_t i = 0; i + 1 < way.size(); ++i) {
    const geometry::Vec2 v = way[i + 1] - way[i];
    const double length = v.norm();
    if (length < 1e-9) continue;
    const double t = std::clamp((p - way[i]).dot(v) / length, 0.0, length);
    const double distance = (way[i] + t * v / length - p).norm();
    if (distance < nearest) nearest = distance, segment = i, along = t;
  }
  for (std::size_t i = segment; i + 1 < way.size(); ++i) {
    const double length = (way[i + 1] - way[i]).norm();
    if (along + ahead <= length) return way[i] + (along + ahead) * (way[i + 1] - way[i]) / length;
    ahead -= length - along;
    along = 0.0;
  }
  return way.back();
}

}  // namespace

PushPlanLead::PushPlanLead(const lookahead::PushLattice& lattice, const std::vector<int>& start_cells,
                           const std::vector<lookahead::PushStep>& steps, const physltl::knowledge::AbstractKnowledge& knowledge)
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
    const int stand = stand_of(lattice, run.body, run.from, run.direction, run.before);
    run.walk = walk_to(lattice, stand, run.before);
    run.length = (lattice.body_centre(run.body, run.to) - lattice.body_centre(run.body, run.from)).norm();
    run.touching = lattice.half_along(run.body, run.direction) + robot_radius_;
    if (!lattice.unit_bodies() && stand >= 0) {
      // On the stand's line, touching the face of the place ahead of it: half the gap into that place.
      const geometry::Vec2 d = direction_of(run.direction);
      const geometry::Vec2 from_centre = lattice.centre(stand) - lattice.body_centre(run.body, run.from);
      run.touching = -from_centre.dot(d) - (lattice.step() + lookahead::kLatticeGap) / 2 + robot_radius_;
      run.beside = from_centre - from_centre.dot(d) * d;
    }
  }
  for (int j = static_cast<int>(runs_.size()) - 2; j >= 0; --j) {
    const Run& next = runs_[static_cast<std::size_t>(j) + 1];
    const Run& run = runs_[static_cast<std::size_t>(j)];
    const int robot_after = stand_of(lattice, run.body, run.to, run.direction, next.before);
    const int walk = robot_after < 0 ? kNever : next.walk[static_cast<std::size_t>(robot_after)];
    runs_[static_cast<std::size_t>(j)].after =
        next.after + next.length + (walk == kNever ? kNoWay : (walk + kGetReady) * lattice.step());
  }
  for (std::size_t k = 0; k < cells.size(); ++k) end_positions_.push_back(lattice.body_centre(static_cast<int>(k), cells[k]));
  if (!runs_.empty() && !runs_.back().ahead.empty()) {
    // A line ends the order short of its places: the gaps between its bodies closed.
    const Run& last = runs_.back();
    std::vector<int> line{last.body};
    line.insert(line.end(), last.ahead.begin(), last.ahead.end());
    const std::vector<double> shortfalls =
        lattice.line_shortfalls(line, last.before, last.direction).value_or(std::vector<double>(last.ahead.size()));
    for (std::size_t i = 0; i < last.ahead.size(); ++i) {
      end_positions_[static_cast<std::size_t>(last.ahead[i])] -= shortfalls[i] * direction_of(last.direction);
    }
  }
}

const std::vector<int>& PushPlanLead::walk_behind(int j, int body_cell) const {
  const Run& run = runs_[static_cast<std::size_t>(j)];
  if (body_cell == run.from) return run.walk;
  const std::lock_guard<std::mutex> lock(walks_mutex_);
  auto& walk = walks_[{j, body_cell}];
  if (walk.empty()) {
    std::vector<int> held = run.before;
    held[static_cast<std::size_t>(run.body)] = body_cell;
    walk = walk_to(lattice_, stand_of(lattice_, run.body, body_cell, run.direction, held), held);
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
    if ((position(state, static_cast<int>(k)) - lattice_.body_centre(static_cast<int>(k), places[k])).norm() > tolerance) return std::nullopt;
  }
  const Run& run = runs_[static_cast<std::size_t>(j)];
  const geometry::Vec2 d = direction_of(run.direction);
  // How far body k has come along the push from its place before it, and how far off the push's line.
  const auto offset_of = [&](int k) -> std::optional<Along> {
    const geometry::Vec2 offset = position(state, k) - lattice_.body_centre(k, places[static_cast<std::size_t>(k)]);
    const double a = offset.dot(d);
    const double lateral = std::abs(geometry::cross(offset, d));
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
  const geometry::Vec2 v = body + run.beside - robot;
  const double touching = run.touching;
  // A unit body's half width; a larger one is pushed from one place, as wide as a unit body.
  const double half_width = lattice_.unit_bodies() ? lattice_.half_along(run.body, lookahead::perpendicular(run.direction))
                                                   : (lattice_.step() - lookahead::kLatticeGap) / 2;
  const double depth = v.dot(d);
  const double lateral = std::abs(geometry::cross(v, d));
  return depth >= touching - kReadyDepth && depth <= touching + kReadyDepth && lateral <= kReadyLateral * half_width;
}

double PushPlanLead::robot_way(const geometry::Vec2& robot, const geometry::Vec2& body, int j) const {
  if (ready_to_push(robot, body, j)) return 0.0;
  const int cell = lattice_.robot_cell(robot);
  const int body_cell = lattice_.body_cell(runs_[static_cast<std::size_t>(j)].body, body);
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

PushPlanLead::Situation PushPlanLead::situation(const physics::PhysicsState& state, int push) const {
  const Run& run = runs_[static_cast<std::size_t>(push)];
  return {run, direction_of(run.direction), state.robot_position(), position(state, run.body) + run.beside, run.touching};
}

std::optional<PushPlanLead::Target> PushPlanLead::target(const physics::PhysicsState& state, int push) const {
  if (push < 0 || push >= pushes()) return std::nullopt;
  const auto [run, d, robot, body, touching] = situation(state, push);
  // Pushing: to where the robot stands behind the body on its place, which also steers the body back onto
  // the lattice's line.
  if (ready_to_push(robot, body - run.beside, push)) return Target{lattice_.body_centre(run.body, run.to) + run.beside - touching * d, true};
  const geometry::Vec2 behind = body - (touching + kBehindGap) * d;
  const Way way = way_ahead(robot, push, body - run.beside, kWalkAhead);
  if (way.places.empty()) return std::nullopt;
  const double off_line = std::abs(geometry::cross(robot - body, d));
  return Target{way.arriving && off_line <= kOnLine ? behind : lattice_.centre(way.places.back()), false};
}

PushPlanLead::Way PushPlanLead::way_ahead(const geometry::Vec2& robot, int j, const geometry::Vec2& body, int ahead) const {
  int cell = lattice_.robot_cell(robot);
  const int body_cell = lattice_.body_cell(runs_[static_cast<std::size_t>(j)].body, body);
  if (cell < 0 || body_cell < 0) return {};
  const std::vector<int>& walk = walk_behind(j, body_cell);
  const auto steps = [&](int c) { return c < 0 ? kNever : walk[static_cast<std::size_t>(c)]; };
  if (steps(cell) == kNever) {
    // The robot's nearest place is one a body holds, or off the walk: the neighbour nearest its push.
    int best = -1;
    for (int k = 0; k < kDirections; ++k) {
      const int n = lattice_.neighbour(cell, k);
      if (steps(n) != kNever && (best < 0 || steps(n) < steps(best))) best = n;
    }
    if (best < 0) return {};
    cell = best;
  }
  Way way{{cell}, false};
  for (int i = 0; i < ahead && steps(cell) > 0; ++i) {
    for (int k = 0; k < kDirections; ++k) {
      const int n = lattice_.neighbour(cell, k);
      if (lattice_.robot_passes(cell, k) && steps(n) == steps(cell) - 1) {
        cell = n;
        break;
      }
    }
    way.places.push_back(cell);
  }
  way.arriving = steps(cell) == 0;
  return way;
}

std::optional<PushPlanLead::Steer> PushPlanLead::steer(const physics::PhysicsState& state, int push, double max_speed) const {
  if (push < 0 || push >= pushes()) return std::nullopt;
  const auto [run, d, robot, body, touching] = situation(state, push);
  // The robot starts a push only square behind the body's centre: a push started off it leaves the robot
  // off the line for the whole push, which in a corridor a few centimetres wider than it ends on a wall.
  // Once touching, it keeps pushing and closes the offset as it goes.
  const double depth = (body - robot).dot(d);
  const bool square_behind = std::abs(geometry::cross(d, robot - body)) <= kSquareBehind;
  if (ready_to_push(robot, body - run.beside, push) && (square_behind || depth <= touching + kTouching)) {
    const double left = run.length - (body - run.beside - lattice_.body_centre(run.body, run.from)).dot(d);
    const double speed = std::clamp(left / kArriveTime, kCreep * max_speed, kPushSpeed * max_speed);
    // Along the push, closing the robot's offset from the line through the body's centre sideways.
    const geometry::Vec2 side(-d.y(), d.x());
    const geometry::Vec2 velocity = speed * d - (geometry::cross(d, robot - body) / kCloseTime) * side;
    return Steer{velocity.normalized(), std::min(max_speed, velocity.norm()), std::min(kPushControlTime, left / speed), true};
  }
  const Way ahead = way_ahead(robot, push, body - run.beside, kWayAhead);
  if (ahead.places.empty()) return std::nullopt;
  const bool arriving = ahead.arriving;
  // The way: the places' centres from the robot's place on, the last the point behind the body.
  std::vector<geometry::Vec2> way;
  for (int c : ahead.places) way.push_back(lattice_.centre(c));
  if (arriving) way.back() = body - (touching + kBehindGap) * d;
  const geometry::Vec2 aim = pursuit_point(way, robot, kPursuit);
  const double to_aim = (aim - robot).norm();
  if (to_aim < 1e-9) return Steer{d, 0.0, 0.0, false};
  // Slowing for the way's first corner (or its end, behind the body): a robot that turns at speed swings
  // wide, and a differential one turns on an arc of its speed over its turn rate.
  double to_corner = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i + 1 < way.size() && std::isinf(to_corner); ++i) {
    const geometry::Vec2 in = way[i] - way[i - 1], out = way[i + 1] - way[i];
    if (std::abs(geometry::cross(in, out)) > 1e-6 * in.norm() * out.norm()) to_corner = (way[i] - robot).norm();
  }
  if (arriving) to_corner = std::min(to_corner, (way.back() - robot).norm());
  const double speed = std::min(max_speed, std::max(arriving && aim == way.back() ? 0.0 : kCornerSpeed * max_speed, to_corner / kArriveTime));
  return Steer{(aim - robot) / to_aim, speed, 0.0, false};
}

}  // namespace physltl::planners::knowledge
