// How long the knowledge layer takes on the paper's scenario A (scenarios/rooms.lua). INFERENCE and the
// validity rules run after every propagation step of the planner; feasibility runs once per `check`.

#include "physltl/knowledge/feasibility.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/knowledge/validity.h"
#include "physltl/scenario/load.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace physltl;

const scenario::World& rooms() {
  static const scenario::World world = scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/rooms.lua");
  return world;
}

void InferInPlace(benchmark::State& s) {
  const auto k = knowledge::formulate(rooms());
  const auto state = scenario::EnvironmentState::initial(rooms());
  knowledge::Kappa kappa = knowledge::infer(k, state);
  for (auto _ : s) {
    knowledge::infer(k, state, kappa);
    benchmark::DoNotOptimize(kappa);
  }
}
BENCHMARK(InferInPlace)->Unit(benchmark::kMicrosecond);

void InferFresh(benchmark::State& s) {
  const auto k = knowledge::formulate(rooms());
  const auto state = scenario::EnvironmentState::initial(rooms());
  for (auto _ : s) benchmark::DoNotOptimize(knowledge::infer(k, state));
}
BENCHMARK(InferFresh)->Unit(benchmark::kMicrosecond);

void CheckValidityWithOneContact(benchmark::State& s) {
  const auto k = knowledge::formulate(rooms());
  auto state = scenario::EnvironmentState::initial(rooms());
  const knowledge::Kappa kappa = knowledge::infer(k, state);
  state.robot_position = {-3.0, 0.95};  // under B1, in its -y mRegion
  const scenario::RobotContact contact{scenario::RobotContact::Body::kMovable, 0, {-3.0, 1.2}};
  for (auto _ : s) benchmark::DoNotOptimize(knowledge::check_validity(k, kappa, state, {&contact, 1}));
}
BENCHMARK(CheckValidityWithOneContact)->Unit(benchmark::kMicrosecond);

void Feasibility(benchmark::State& s) {
  const auto k = knowledge::formulate(rooms());
  for (auto _ : s) benchmark::DoNotOptimize(knowledge::evaluate_feasibility(k));
}
BENCHMARK(Feasibility)->Unit(benchmark::kMillisecond);

}  // namespace
