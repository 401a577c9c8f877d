// The World's own helpers (world.h): names of sides and drives, and names to indices (a shape's faces and
// names are its kind's: shape_kinds.cpp).

#include "physltl/scenario/world.h"

#include <algorithm>

namespace physltl::scenario {
namespace {

template <class Named>
int index_by_name(const std::vector<Named>& list, std::string_view name) {
  const auto it = std::find_if(list.begin(), list.end(), [&](const Named& n) { return n.name == name; });
  return it == list.end() ? -1 : static_cast<int>(it - list.begin());
}

}  // namespace

const char* side_name(Side side) {
  switch (side) {
    case Side::kMinusX: return "-x";
    case Side::kPlusX: return "+x";
    case Side::kMinusY: return "-y";
    case Side::kPlusY: return "+y";
  }
  return "?";
}

const char* drive_name(Drive drive) {
  switch (drive) {
    case Drive::kHolonomic: return "holonomic";
    case Drive::kDifferential: return "differential";
  }
  return "?";
}

int movable_body_index(const World& world, std::string_view name) { return index_by_name(world.movable_bodies, name); }

int region_index(const World& world, std::string_view name) { return index_by_name(world.regions, name); }

}  // namespace physltl::scenario
