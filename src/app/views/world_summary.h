#pragma once

#include "physltl/scenario/world.h"

#include <ostream>

namespace physltl::app {

// A few lines a person reads to see what a scenario contains.
void print_world_summary(std::ostream& out, const scenario::World& world);

}  // namespace physltl::app
