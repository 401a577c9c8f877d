#pragma once
// One expectation of one scenario, as `test` reports it and JUnit shows it.

#include <string>
#include <vector>

namespace physltl::app::scenario_test {

enum class Outcome { kPassed, kFailed, kSkipped, kUpdated };

struct CaseResult {
  std::string name;     // "check", "solves", "max_pushes", "plan.json", "preview.png", "frame_last.png"
  Outcome outcome = Outcome::kPassed;
  std::string message;  // why it failed or was skipped, what was updated; empty when it passed
  double time_s = 0.0;
};

struct ScenarioResult {
  std::string label;  // the entry as given
  std::vector<CaseResult> cases;
  double time_s = 0.0;
  bool interrupted = false;

  int count(Outcome outcome) const {
    int n = 0;
    for (const CaseResult& c : cases) n += c.outcome == outcome;
    return n;
  }
  bool passed() const { return count(Outcome::kFailed) == 0 && !interrupted; }
};

}  // namespace physltl::app::scenario_test
