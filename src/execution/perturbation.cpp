#include "physltl/execution/perturbation.h"

#include "physltl/planning/random.h"
#include "physltl/scenario/load.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace physltl::execution {
namespace {

constexpr int kMaxDraws = 1000;
// Mixed into the seed so that a world's draws never follow the planner's stream for the same seed.
constexpr std::uint64_t kPerturbationStream = 0x7065727475726221ull;

geometry::Vec2 in_disc(planning::Random& random, double radius) {
  // Uniform over the disc's area: the radius goes as the square root of a uniform number.
  const double r = radius * std::sqrt(random.uniform01());
  const double angle = random.uniform(-std::numbers::pi, std::numbers::pi);
  return {r * std::cos(angle), r * std::sin(angle)};
}

scenario::World draw(const scenario::World& model, const scenario::Uncertainty& u, planning::Random& random) {
  scenario::World world = model;
  for (auto& body : world.movable_bodies) {
    const scenario::BodyUncertainty& own = body.uncertainty;
    const double mass = own.mass.value_or(u.mass), friction = own.friction.value_or(u.friction);
    const double yaw_deg = own.yaw_deg.value_or(u.body_yaw_deg);
    body.mass *= random.uniform(1.0 - mass, 1.0 + mass);
    body.friction *= random.uniform(1.0 - friction, 1.0 + friction);
    body.footprint.pose.position += in_disc(random, own.pose.value_or(u.body_pose));
    body.footprint.pose.yaw += random.uniform(-yaw_deg, yaw_deg) * std::numbers::pi / 180.0;
  }
  world.robot.start += in_disc(random, u.start);
  return world;
}

}  // namespace

scenario::World perturbed_world(const scenario::World& model, const scenario::Uncertainty& uncertainty,
                                std::uint64_t seed, int index) {
  const bool own_ranges = std::any_of(model.movable_bodies.begin(), model.movable_bodies.end(), [](const auto& body) {
    const scenario::BodyUncertainty& u = body.uncertainty;
    return u.mass.value_or(0) > 0 || u.friction.value_or(0) > 0 || u.pose.value_or(0) > 0 || u.yaw_deg.value_or(0) > 0;
  });
  if (uncertainty.none() && !own_ranges) return model;
  planning::Random seeder(seed ^ kPerturbationStream);
  for (int i = 0; i < index; ++i) seeder.next();
  planning::Random random(seeder.next());
  std::string last_problem;
  for (int attempt = 0; attempt < kMaxDraws; ++attempt) {
    scenario::World world = draw(model, uncertainty, random);
    const auto problems = scenario::validate(world);
    if (problems.empty()) return world;
    last_problem = problems.front().message;
  }
  throw PerturbationError(fmt::format("no valid perturbed world in {} draws (the last: {}); the uncertainty is too "
                                      "wide for how close the bodies stand",
                                      kMaxDraws, last_problem));
}

}  // namespace physltl::execution
