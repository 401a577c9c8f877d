#include "physltl/scenario/state_trace.h"

#include <algorithm>
#include <stdexcept>

namespace physltl::scenario {

StateTrace::StateTrace(const EnvironmentState& first)
    : front_(first), back_(first), robot_{robot_of(first)}, changes_begin_{0}, body_changes_(first.movable_poses.size()) {}

StateTrace::RobotSample StateTrace::robot_of(const EnvironmentState& state) {
  return {state.robot_position, state.robot_velocity, state.robot_yaw, state.robot_turn_rate};
}

void StateTrace::put_robot(const RobotSample& robot, EnvironmentState& state) {
  state.robot_position = robot.position;
  state.robot_velocity = robot.velocity;
  state.robot_yaw = robot.yaw;
  state.robot_turn_rate = robot.turn_rate;
}

void StateTrace::apply(const BodyChange& change, EnvironmentState& state) {
  const auto b = static_cast<std::size_t>(change.body);
  state.movable_poses[b] = change.pose;
  state.movable_velocities[b] = change.velocity;
}

void StateTrace::record_body(const EnvironmentState& state, int body) {
  const auto b = static_cast<std::size_t>(body);
  const geometry::Pose2& pose = state.movable_poses[b];
  const Vec2& velocity = state.movable_velocities[b];
  if (pose == back_.movable_poses[b] && velocity == back_.movable_velocities[b]) return;
  if (body_changes_[b].empty()) changed_bodies_.push_back(body);
  body_changes_[b].push_back(changes_.size());
  changes_.push_back({body, pose, velocity});
  apply(changes_.back(), back_);
}

// Appends `state`, recording the bodies `record_changes` compares (the first state of a trace is whole).
template <class RecordChanges>
void StateTrace::append(const EnvironmentState& state, const RecordChanges& record_changes) {
  if (empty()) {
    *this = StateTrace(state);
    return;
  }
  if (state.movable_poses.size() != front_.movable_poses.size()) {
    throw std::invalid_argument("StateTrace: a state with a different number of movable bodies");
  }
  const std::size_t first = changes_.size();
  record_changes();
  // The physics names its movers in the order it integrated them; a step's changes are kept in body order.
  std::sort(changes_.begin() + static_cast<std::ptrdiff_t>(first), changes_.end(),
            [](const BodyChange& a, const BodyChange& b) { return a.body < b.body; });
  for (std::size_t i = first; i < changes_.size(); ++i) body_changes_[static_cast<std::size_t>(changes_[i].body)].back() = i;
  changes_begin_.push_back(first);
  robot_.push_back(robot_of(state));
  put_robot(robot_.back(), back_);
}

void StateTrace::push_back(const EnvironmentState& state, std::span<const int> changed) {
  append(state, [&] {
    for (int body : changed) record_body(state, body);
  });
}

void StateTrace::push_back(const EnvironmentState& state) {
  append(state, [&] {
    for (std::size_t b = 0; b < state.movable_poses.size(); ++b) record_body(state, static_cast<int>(b));
  });
}

std::span<const StateTrace::BodyChange> StateTrace::changes(std::size_t i) const {
  if (i >= size()) throw std::out_of_range("StateTrace: no such step");
  const std::size_t end = i + 1 < changes_begin_.size() ? changes_begin_[i + 1] : changes_.size();
  return std::span(changes_).subspan(changes_begin_[i], end - changes_begin_[i]);
}

const StateTrace::BodyChange* StateTrace::last_change(std::size_t body, std::size_t i) const {
  const std::size_t end = i + 1 < changes_begin_.size() ? changes_begin_[i + 1] : changes_.size();
  const std::vector<std::size_t>& mine = body_changes_[body];
  const auto after = std::lower_bound(mine.begin(), mine.end(), end);  // its first change after step i
  return after == mine.begin() ? nullptr : &changes_[*(after - 1)];
}

EnvironmentState StateTrace::operator[](std::size_t i) const {
  if (i >= size()) throw std::out_of_range("StateTrace: no such step");
  if (i + 1 == size()) return back_;
  EnvironmentState state = front_;
  put_robot(robot_[i], state);
  for (int body : changed_bodies_) {
    if (const BodyChange* change = last_change(static_cast<std::size_t>(body), i)) apply(*change, state);
  }
  return state;
}

geometry::Pose2 StateTrace::body_pose(std::size_t body, std::size_t i) const {
  if (i >= size()) throw std::out_of_range("StateTrace: no such step");
  const BodyChange* change = last_change(body, i);
  return change != nullptr ? change->pose : front_.movable_poses[body];
}

StateTrace StateTrace::prefix(std::size_t n) const {
  if (n >= size()) return *this;
  StateTrace kept;
  if (n == 0) return kept;
  const std::size_t end = changes_begin_[n];  // the changes of steps before n
  kept.front_ = front_;
  kept.back_ = (*this)[n - 1];
  kept.robot_.assign(robot_.begin(), robot_.begin() + static_cast<std::ptrdiff_t>(n));
  kept.changes_.assign(changes_.begin(), changes_.begin() + static_cast<std::ptrdiff_t>(end));
  kept.changes_begin_.assign(changes_begin_.begin(), changes_begin_.begin() + static_cast<std::ptrdiff_t>(n));
  kept.body_changes_.resize(body_changes_.size());
  for (int body : changed_bodies_) {
    const std::vector<std::size_t>& mine = body_changes_[static_cast<std::size_t>(body)];
    std::vector<std::size_t>& theirs = kept.body_changes_[static_cast<std::size_t>(body)];
    theirs.assign(mine.begin(), std::lower_bound(mine.begin(), mine.end(), end));
    if (!theirs.empty()) kept.changed_bodies_.push_back(body);
  }
  return kept;
}

StateTrace::Iterator::Iterator(const StateTrace& trace, std::size_t at) : trace_(&trace), at_(at) {
  if (at_ < trace.size()) state_ = trace[at_];
}

StateTrace::Iterator& StateTrace::Iterator::operator++() {
  if (++at_ < trace_->size()) {
    for (const BodyChange& change : trace_->changes(at_)) apply(change, state_);
    put_robot(trace_->robot_[at_], state_);
  }
  return *this;
}

}  // namespace physltl::scenario
