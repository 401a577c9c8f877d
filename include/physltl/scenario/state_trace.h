#pragma once
// The states of a run, one per physics step, kept as what changed: the robot at every step, a movable body
// only at the steps where its pose or velocity changed. A warehouse of thousands of resting boxes then
// costs what its moving bodies cost, not its size times the number of steps.

#include "physltl/scenario/state.h"

#include <cstddef>
#include <iterator>
#include <span>
#include <vector>

namespace physltl::scenario {

class StateTrace {
 public:
  // A body's new state at one step.
  struct BodyChange {
    int body = 0;  // into World::movable_bodies
    geometry::Pose2 pose;
    Vec2 velocity = Vec2::Zero();
  };

  StateTrace() = default;
  explicit StateTrace(const EnvironmentState& first);

  // Appends `state`. The first form compares only the bodies in `changed` with the previous state: the
  // caller knows the others did not change (the physics' movers of the step).
  void push_back(const EnvironmentState& state, std::span<const int> changed);
  void push_back(const EnvironmentState& state);

  std::size_t size() const { return robot_.size(); }
  bool empty() const { return robot_.empty(); }
  const EnvironmentState& front() const { return front_; }
  const EnvironmentState& back() const { return back_; }
  // State `i` rebuilt: the first state with each body's last change up to step i (costs one state's copy).
  EnvironmentState operator[](std::size_t i) const;
  Vec2 robot_position(std::size_t i) const { return robot_[i].position; }
  Vec2 robot_velocity(std::size_t i) const { return robot_[i].velocity; }
  double robot_yaw(std::size_t i) const { return robot_[i].yaw; }
  // Movable body `body`'s pose at step i, without rebuilding the state.
  geometry::Pose2 body_pose(std::size_t body, std::size_t i) const;
  // The bodies whose state at step i differs from step i - 1 (none at step 0), in body order.
  std::span<const BodyChange> changes(std::size_t i) const;
  // The first `n` states.
  StateTrace prefix(std::size_t n) const;

  // The states in order, each rebuilt from the one before by its changes.
  class Iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = EnvironmentState;
    using difference_type = std::ptrdiff_t;
    using pointer = const EnvironmentState*;
    using reference = const EnvironmentState&;
    Iterator(const StateTrace& trace, std::size_t at);
    const EnvironmentState& operator*() const { return state_; }
    const EnvironmentState* operator->() const { return &state_; }
    Iterator& operator++();
    bool operator==(const Iterator& other) const { return at_ == other.at_; }

   private:
    const StateTrace* trace_;
    std::size_t at_;
    EnvironmentState state_;
  };
  Iterator begin() const { return {*this, 0}; }
  Iterator end() const { return {*this, size()}; }

 private:
  struct RobotSample {
    Vec2 position = Vec2::Zero();
    Vec2 velocity = Vec2::Zero();
    double yaw = 0.0;
    double turn_rate = 0.0;
  };
  static RobotSample robot_of(const EnvironmentState& state);
  static void put_robot(const RobotSample& robot, EnvironmentState& state);
  void record_body(const EnvironmentState& state, int body);
  template <class RecordChanges>
  void append(const EnvironmentState& state, const RecordChanges& record_changes);
  static void apply(const BodyChange& change, EnvironmentState& state);
  const BodyChange* last_change(std::size_t body, std::size_t i) const;  // up to step i; none: as at the start

  EnvironmentState front_, back_;
  std::vector<RobotSample> robot_;
  std::vector<BodyChange> changes_;          // every step's changes, in step order
  std::vector<std::size_t> changes_begin_;   // per step, where its changes begin in changes_
  // Per body, the indices into changes_ of its changes (empty for a body that never moved), and the
  // bodies that have some, so that rebuilding a state looks only at those.
  std::vector<std::vector<std::size_t>> body_changes_;
  std::vector<int> changed_bodies_;
};

}  // namespace physltl::scenario
