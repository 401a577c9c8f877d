#pragma once

#include "table_reader.h"
#include "physltl/scenario/world.h"

namespace physltl::scenario {

// The `expect { ... }` block of the scenario's own file (a scenario required as a module keeps its block
// for its own test). Reads what the table says; check_expectations() then holds it against the rest of the
// World (the regions it names).
Expectations read_expectations(TableReader& r);
void check_expectations(const World& world, std::vector<Diagnostic>& diagnostics);

}  // namespace physltl::scenario
