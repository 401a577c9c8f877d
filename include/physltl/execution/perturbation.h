#pragma once
// Worlds as reality might be: the model with each movable body's mass, floor friction and pose and the
// robot's start drawn from the ranges of an Uncertainty (docs/robustness.md).

#include "physltl/scenario/world.h"

#include <cstdint>
#include <stdexcept>

namespace physltl::execution {

// Drawn uniformly and independently: mass x U[1-m, 1+m] and friction x U[1-f, 1+f] per movable body, its
// position uniform in a disc of radius body_pose, its heading plus U[-yaw, yaw] (a body's own ranges,
// MovableBody::uncertainty, replacing the world's for it); the robot's start uniform in a disc of radius
// start. A draw that is not a valid world (scenario::validate: a body outside the
// workspace or overlapping another, the robot starting inside one) is drawn again. World `index` of
// `seed` comes from a generator of its own, seeded apart from the planner's, so the same seed and index
// give the same world whatever else is drawn. Zero uncertainty gives the model itself.
// Throws PerturbationError when 1000 draws in a row are invalid.
scenario::World perturbed_world(const scenario::World& model, const scenario::Uncertainty& uncertainty,
                                std::uint64_t seed, int index);

struct PerturbationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace physltl::execution
