#include "physltl/planning/race.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace physltl::planning {
namespace {

// One planner's outcome: its search and, when it solved, the replay of its plan.
struct Attempt {
  PlanResult result;
  std::optional<Replay> replay;
  bool validated() const { return replay.has_value() && replay->validated(); }
};

Attempt plan_and_validate(const Problem& p, const PlannerOptions& options) {
  Attempt attempt{plan(p.world, p.task, p.knowledge, p.decomposition, options), std::nullopt};
  if (attempt.result.solved) {
    attempt.replay = replay(p.world, attempt.result.plan, p.formula, p.knowledge, validity_mode(options.guidance));
  }
  return attempt;
}

// Runs the attempts on their own threads; returns the index of the first that validated, or -1.
int run_threads(const Problem& problem, const PlannerOptions& options, std::vector<Attempt>& attempts) {
  const int threads = static_cast<int>(attempts.size());
  std::atomic<bool> race_over{false};
  std::mutex mutex;
  std::condition_variable finished;
  int running = threads;
  int winner = -1;
  {
    std::vector<std::jthread> workers;
    for (int t = 0; t < threads; ++t) {
      workers.emplace_back([&, t] {
        PlannerOptions own = options;
        own.seed = thread_seed(options.seed, t);
        own.stop = &race_over;
        Attempt attempt = plan_and_validate(problem, own);
        std::lock_guard lock(mutex);
        if (winner < 0 && attempt.validated()) {
          winner = t;
          race_over.store(true);
        }
        attempts[t] = std::move(attempt);
        --running;
        finished.notify_all();
      });
    }
    // The planners poll only the race's flag; an outside stop (Ctrl-C) is relayed to it from here, where
    // the calling thread waits anyway.
    std::unique_lock lock(mutex);
    while (running > 0) {
      finished.wait_for(lock, std::chrono::milliseconds(20));
      if (options.stop != nullptr && options.stop->load()) race_over.store(true);
    }
  }  // joins the workers
  return winner;
}

}  // namespace

std::uint64_t thread_seed(std::uint64_t run_seed, int thread) {
  if (thread == 0) return run_seed;
  // The thread-th output of SplitMix64 started at run_seed.
  std::uint64_t z = run_seed + static_cast<std::uint64_t>(thread) * 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

RaceResult race(const Problem& problem, const PlannerOptions& options, int threads) {
  std::vector<Attempt> attempts(static_cast<size_t>(std::max(threads, 1)));
  int winner = -1;
  if (attempts.size() == 1) {
    attempts[0] = plan_and_validate(problem, options);
    if (attempts[0].validated()) winner = 0;
  } else {
    winner = run_threads(problem, options, attempts);
  }

  RaceResult race;
  for (const auto& a : attempts) race.racers.push_back({a.result.stop_reason, a.result.stats});
  int chosen = winner;
  for (size_t t = 0; chosen < 0 && t < attempts.size(); ++t) {
    if (attempts[t].replay) chosen = static_cast<int>(t);  // a plan that failed replay: a bug to report
  }
  if (chosen < 0) chosen = 0;
  race.winner = winner;
  race.result = std::move(attempts[chosen].result);
  race.replay = std::move(attempts[chosen].replay);
  return race;
}

}  // namespace physltl::planning
