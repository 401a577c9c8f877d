// The World's own helpers (world.h): names of sides and drives, and names to indices (a shape's faces and
// names are its kind's: shape_kinds.cpp).

#include "physltl/scenario/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

std::string_view render_view_name(RenderView view) { return view == RenderView::kTop ? "top" : "perspective"; }

std::optional<RenderView> render_view_named(std::string_view name) {
  for (RenderView view : kRenderViews) {
    if (name == render_view_name(view)) return view;
  }
  return std::nullopt;
}

std::string number_text(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", value);
  return buf;
}

std::optional<std::string> number_problem(double value, double lo, double hi, bool lo_allowed) {
  const auto text = number_text;
  // With as many digits as tell the value from the bound it passed ("1.0000001 > 1", not "1 > 1").
  const auto text_beside = [](double v, double bound) {
    char a[32], b[32];
    for (int digits = 6; digits < 17; ++digits) {
      std::snprintf(a, sizeof a, "%.*g", digits, v);
      std::snprintf(b, sizeof b, "%.*g", digits, bound);
      if (std::string_view(a) != b) return std::string(a);
    }
    std::snprintf(a, sizeof a, "%.17g", v);
    return std::string(a);
  };
  if (!std::isfinite(value)) return "must be finite";
  if (value < lo || (value == lo && !lo_allowed)) {
    return std::string("must be ") + (lo_allowed ? "at least " : "greater than ") + text(lo) + ", got " + text_beside(value, lo);
  }
  if (value > hi) return "is too large (" + text_beside(value, hi) + " > " + text(hi) + ")";
  return std::nullopt;
}

int movable_body_index(const World& world, std::string_view name) { return index_by_name(world.movable_bodies, name); }

int region_index(const World& world, std::string_view name) { return index_by_name(world.regions, name); }

namespace {

// `one` for the name of a single body or region, else the members of the group of that name (of the kind
// `members_of` picks), each looked up with `index`.
template <class MembersOf, class Index>
std::vector<int> named(const World& world, std::string_view name, int one, MembersOf members_of, Index index) {
  if (one >= 0) return {one};
  std::vector<int> indices;
  const int group = index_by_name(world.groups, name);
  if (group < 0) return indices;
  for (const std::string& member : members_of(world.groups[static_cast<std::size_t>(group)])) {
    const int i = index(world, member);
    if (i < 0) return {};
    indices.push_back(i);
  }
  return indices;
}

}  // namespace

std::vector<int> bodies_named(const World& world, std::string_view name) {
  return named(world, name, movable_body_index(world, name), [](const Group& g) { return g.bodies; }, movable_body_index);
}

std::vector<int> regions_named(const World& world, std::string_view name) {
  return named(world, name, region_index(world, name), [](const Group& g) { return g.regions; }, region_index);
}

}  // namespace physltl::scenario
