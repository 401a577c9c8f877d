// Translation times for the paper's scalable task patterns (issue 3 asks: sequencing and disjunction of
// 10 regions well under 10 ms, coverage of 10 regions, 1024 states, under 100 ms).

#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using physltl::ltl::Formula;

Formula sequencing(int n) {
  std::string f = "F p" + std::to_string(n);
  for (int i = n - 1; i >= 1; --i) f = "F(p" + std::to_string(i) + " & " + f + ")";
  return physltl::ltl::parse(f);
}

Formula joined(int n, const char* op) {
  std::string f;
  for (int i = 1; i <= n; ++i) f += (i > 1 ? op : "") + std::string("F p") + std::to_string(i);
  return physltl::ltl::parse(f);
}

void run(benchmark::State& state, const Formula& f) {
  std::size_t states = 0;
  for (auto _ : state) {
    auto dfa = physltl::ltl::translate(f);
    states = dfa.size();
    benchmark::DoNotOptimize(dfa);
  }
  state.counters["states"] = static_cast<double>(states);
}

void Sequencing(benchmark::State& state) { run(state, sequencing(static_cast<int>(state.range(0)))); }
void Disjunction(benchmark::State& state) { run(state, joined(static_cast<int>(state.range(0)), " | ")); }
void Coverage(benchmark::State& state) { run(state, joined(static_cast<int>(state.range(0)), " & ")); }

BENCHMARK(Sequencing)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(Disjunction)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(Coverage)->Arg(5)->Arg(10)->Unit(benchmark::kMillisecond);

}  // namespace
