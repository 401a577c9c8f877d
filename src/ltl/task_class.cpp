#include "physltl/ltl/task_class.h"

#include "physltl/ltl/co_safety.h"

#include <algorithm>

namespace physltl::ltl {
namespace {

// Whether a PNF formula uses no operator that needs a finite witness (F, U, M): every violation of it
// shows in a finite prefix.
bool is_syntactically_safe(const Formula& f) {
  switch (f.op()) {
    case Op::Finally:
    case Op::Until:
    case Op::StrongRelease:
      return false;
    case Op::Xor:
    case Op::Equiv:  // operands are needed in both polarities, so they must be free of temporal operators
      return std::ranges::all_of(f.children(), [](const Formula& c) {
        return is_syntactically_safe(c) && !find_co_safety_violation(c);
      });
    default:
      return std::ranges::all_of(f.children(), [](const Formula& c) { return is_syntactically_safe(c); });
  }
}

}  // namespace

const char* class_name(TaskClass task_class) {
  switch (task_class) {
    case TaskClass::kCoSafe: return "co-safe";
    case TaskClass::kSafety: return "safety";
    case TaskClass::kCoSafeAndSafety: return "co-safe and safety";
    case TaskClass::kGeneral: return "general";
  }
  return "?";
}

TaskClass classify(const Formula& pnf) {
  if (!find_co_safety_violation(pnf)) return TaskClass::kCoSafe;
  if (is_syntactically_safe(pnf)) return TaskClass::kSafety;
  if (pnf.op() == Op::And && std::ranges::all_of(pnf.children(), [](const Formula& c) {
        return !find_co_safety_violation(c) || is_syntactically_safe(c);
      })) {
    return TaskClass::kCoSafeAndSafety;
  }
  return TaskClass::kGeneral;
}

const char* semantics_of(TaskClass task_class) {
  if (task_class == TaskClass::kCoSafe) {
    return "a plan satisfies it once every continuation would (the first good prefix)";
  }
  return "a plan satisfies it when its run, with the robot (and every body) then stopping and staying where "
         "it is forever, satisfies it";
}

}  // namespace physltl::ltl
