#pragma once

#include "lua_value.h"
#include "physltl/scenario/world.h"

#include <vector>

namespace physltl::scenario {

// Turns the constructor calls of a script into a World, reporting wrong types, unknown keys and
// missing or repeated elements. Values are not range-checked here: that is validate()'s job.
World read_world(const std::vector<Element>& elements, const std::string& path, std::vector<Diagnostic>& diagnostics);

}  // namespace physltl::scenario
