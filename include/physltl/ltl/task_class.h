#pragma once
// Which kind of task a formula is, and so how a finite plan satisfies it.
//
// A plan is a finite run. A syntactically co-safe task is satisfied by a good prefix: the run satisfies
// it when every continuation would. Any other task is read as "the robot stops and stays": the run,
// followed by its last letter forever, satisfies it in standard LTL (docs/ltl.md).

#include "physltl/ltl/formula.h"

namespace physltl::ltl {

enum class TaskClass {
  kCoSafe,           // after pushing negations inward: only X, F, U, M over literals
  kSafety,           // only X, G, R, W over literals
  kCoSafeAndSafety,  // a conjunction of co-safe and safety parts, as OMPL's product takes it
  kGeneral,          // anything else, e.g. F G a or G(a -> F b)
};

// "co-safe", "safety", "co-safe and safety", "general".
const char* class_name(TaskClass task_class);

// The class of a formula in positive normal form.
TaskClass classify(const Formula& pnf);

// How a finite plan satisfies a task of this class, in one sentence for people.
const char* semantics_of(TaskClass task_class);

}  // namespace physltl::ltl
