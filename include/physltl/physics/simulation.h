#pragma once
// The physics of a World, on ODE: the paper's PROPAGATOR. Planar motion: the robot drives on its wheels
// and the boxes slide on the floor (plane-2D joints), floor friction acts as Coulomb friction inside the
// solver, the robot's drive tracks a velocity set-point with a bounded force (docs/physics.md), and
// contacts are found in a fixed order, so the same state and control give bit-identical results. A box
// slower than 0.1 mm/s is at rest, and a step leaves out the boxes at rest that no moving body can reach:
// ODE holds, solves and tests for contact the bodies in motion, not the whole World.
// One Simulation per thread; it is the only code that mutates physical state.

#include "physltl/scenario/state.h"
#include "physltl/scenario/world.h"

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace physltl::physics {

using scenario::Vec2;

// What happens when the physics engine meets a world it cannot simulate (an error or a failed assertion of
// ODE's, which cannot be unwound): `handler` is called with the engine's message and must end the process
// (the program says so and exits with its own code); without one, the message is printed and the process
// aborts. Validation refuses the worlds known to cause it (bodies too light or too small).
using EngineFailureHandler = void (*)(const std::string& message);
void set_engine_failure_handler(EngineFailureHandler handler);

// Everything ODE integrates, for every dynamic body (robot first, then movables in World order).
// Restoring it is exact: a restored run continues bit for bit as the original one.
// The values are kept in blocks of a few bodies, the blocks in chunks, and states share the blocks and
// chunks whose bodies are the same: a state saved after a step copies only the blocks of the bodies the
// step moved and the chunks that hold them, so a search tree's nodes cost what their motions changed, not
// the whole World, a copy of a state costs a pointer per chunk, and restoring a state skips the chunks the
// simulation already holds.
class PhysicsState {
 public:
  // Per body: position x, y, z, yaw, linear velocity x, y, z, angular velocity x, y, z.
  static constexpr std::size_t kValuesPerBody = 10;
  static constexpr std::size_t kBodiesPerBlock = 8;
  static constexpr std::size_t kBlocksPerChunk = 16;
  struct Block {
    std::array<double, kValuesPerBody * kBodiesPerBlock> values{};
  };
  struct Chunk {
    std::array<std::shared_ptr<const Block>, kBlocksPerChunk> blocks;  // null past the last body
  };

  std::size_t bodies() const { return bodies_; }
  double value(std::size_t body, std::size_t k) const;
  // Changes one value of this state only (the blocks it shares with others stay as they are).
  void set_value(std::size_t body, std::size_t k, double v);
  Vec2 robot_position() const { return {value(0, 0), value(0, 1)}; }
  // Bit for bit: -0.0 is not 0.0 here.
  bool operator==(const PhysicsState& other) const;
  // Every value, body after body (OMPL's state vector), and back.
  void copy_values(std::span<double> out) const;
  static PhysicsState from_values(std::span<const double> values);
  // How many blocks this state holds in memory as one with `other`, and how many it has.
  std::size_t blocks_shared_with(const PhysicsState& other) const;
  std::size_t blocks() const { return (bodies_ + kBodiesPerBlock - 1) / kBodiesPerBlock; }

 private:
  friend class Simulation;
  // Block `b` of `values` (every value, body after body), the bodies past the end zero.
  static std::shared_ptr<const Block> block_of(std::span<const double> values, std::size_t b);
  // Chunk `c` of `blocks` (every block in order).
  static std::shared_ptr<const Chunk> chunk_of(std::span<const std::shared_ptr<const Block>> blocks, std::size_t c);
  const std::shared_ptr<const Block>& block(std::size_t b) const { return chunks_[b / kBlocksPerChunk]->blocks[b % kBlocksPerChunk]; }
  std::size_t bodies_ = 0;
  std::vector<std::shared_ptr<const Chunk>> chunks_;
};

// The robot touched a body in a step if the solver pressed on their contact and the step ends with them
// this close (docs/physics.md, "No body sinks into another").
inline constexpr double kTouchingGap = 1e-3;  // m

// A body as an overlap names it: the robot, or a body of the World's movable or fixed bodies.
struct BodyId {
  enum class Kind { kRobot, kMovable, kFixed };
  Kind kind = Kind::kRobot;
  int index = -1;  // into World::movable_bodies or World::fixed_bodies; -1 for the robot
  bool operator==(const BodyId&) const = default;
};
// Its name in `world`: "robot", or the body's own.
std::string body_name(const scenario::World& world, const BodyId& body);

// How deep two bodies overlap in the plane where a step ended (a prism's contacts through its top or
// bottom are not horizontal and do not count): the deepest pair of the bodies the step moved, with every
// body they may touch. Zero when none overlaps (docs/physics.md, "No body sinks into another").
struct Overlap {
  double depth = 0.0;  // m
  BodyId a, b;         // a: the robot or a movable body; b: a movable or fixed body
};

// What the robot's drive applied during a step: the planar force on the robot (N) and, for a
// differential drive, the torque about the vertical axis (N m).
struct DriveEffort {
  Vec2 force = Vec2::Zero();
  double torque = 0.0;
};

class Simulation {
 public:
  explicit Simulation(const scenario::World& world);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  PhysicsState save() const;
  void save(PhysicsState& out) const;  // reuses out's storage: the planner saves after every step
  void restore(const PhysicsState& state);

  // One step of the World's step_size with the drive tracking `setpoint`: (vx, vy) in m/s for a holonomic
  // robot, (forward speed m/s, turn rate rad/s) for a differential one. The set-point is not clamped:
  // one beyond the robot's limits is what the drive is asked, and replay reports it. `contacts` receives
  // the robot's contacts during the step.
  void step(const Vec2& setpoint, std::vector<scenario::RobotContact>& contacts);
  // What the drive applied during the last step (zero before the first).
  const DriveEffort& last_drive() const;
  // Whether ODE's exact solver (Dantzig's LCP) solved the last step. When it stops short ("LCP internal
  // error"), the step is taken again from where it began in 2, then 4 sub-steps; false when those failed
  // too, and the iterative solver took the step (docs/physics.md, "Steps the solver fails on").
  bool last_step_solved() const;
  // The deepest overlap where the last step ended.
  const Overlap& last_overlap() const;

  void read_environment(scenario::EnvironmentState& out) const;  // reuses out's storage
  // The movable bodies (World indices, ascending) the last step integrated or the last restore changed:
  // every other one kept its state bit for bit.
  std::span<const int> last_movers() const;
  // `out` held the environment before the last step or restore: brings the robot and last_movers() up to
  // date.
  void update_environment(scenario::EnvironmentState& out) const;
  scenario::EnvironmentState environment() const;
  double step_size() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace physltl::physics
