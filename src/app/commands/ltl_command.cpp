#include "cli/command.h"

#include "physltl/ltl/analysis.h"
#include "physltl/ltl/co_safety.h"
#include "physltl/ltl/hoa.h"
#include "physltl/ltl/translate.h"
#include "physltl/ltl/parser.h"

#include <iostream>
#include <memory>

namespace physltl::app {

namespace {

// The formula with a caret under the offending column, so the error is found at a glance.
std::string pointing_at(const std::string& formula, std::uint32_t column) {
  if (column == 0 || formula.find('\n') != std::string::npos) return "";
  return "\n  " + formula + "\n  " + std::string(column - 1, ' ') + "^";
}

}  // namespace

CommandRunner add_ltl_command(CLI::App& app) {
  struct Options {
    std::string formula;
    bool hoa = false;
    std::vector<std::string> invalid;
  };
  auto o = std::make_shared<Options>();
  app.add_option("formula", o->formula, "The task, e.g. 'F(p1 & F p2)' or 'F goal & G !hazard'")->required();
  app.add_flag("--hoa", o->hoa, "Print only the automaton, in HOA v1 (as Spot writes it)");
  app.add_option("--invalid", o->invalid, "Propositions the robot can never make true, e.g. p3,p5")
      ->delimiter(',');

  return [o]() -> int {
    ltl::Analysis analysis = [&] {
      try {
        return ltl::analyse(o->formula, o->invalid);
      } catch (const ltl::ParseError& e) {
        throw common::BadInput(std::string("bad formula: ") + e.what() + pointing_at(o->formula, e.column()));
      } catch (const ltl::AutomatonTooLarge& e) {
        throw common::BadInput(e.what());
      }
    }();
    if (o->hoa) {
      if (!analysis.dfa) {
        std::cerr << "physltl-studio: the task is infeasible: " << analysis.infeasibility() << "\n";
        return common::kExitNoPlan;
      }
      if (analysis.dfa->acceptance != ltl::Acceptance::kGoodPrefix) {
        throw common::BadInput(std::string("--hoa writes co-safe tasks only, whose automaton accepts good prefixes as Spot's "
                                   "does; this task is ") +
                       ltl::class_name(analysis.task_class) +
                       ", and its automaton accepts a finite run that stops and stays, which HOA has no "
                       "acceptance condition for (docs/ltl.md)");
      }
      ltl::write_hoa(std::cout, *analysis.dfa);
      return common::kExitOk;
    }
    ltl::write_summary(std::cout, analysis);
    return analysis.feasible() ? common::kExitOk : common::kExitNoPlan;
  };
}

}  // namespace physltl::app
