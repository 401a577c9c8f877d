// The World's own helpers (world.h): names of sides, faces, shapes and drives, and names to indices.

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

int face_count(const geometry::Shape& shape) {
  switch (shape.kind()) {
    case geometry::Shape::Kind::kBox: return 4;
    case geometry::Shape::Kind::kCircle: return kCylinderSectors;
    case geometry::Shape::Kind::kPolygon: break;
  }
  return static_cast<int>(shape.outline().vertices.size());
}

std::string face_name(const geometry::Shape& shape, int face) {
  switch (shape.kind()) {
    case geometry::Shape::Kind::kBox: return side_name(static_cast<Side>(face));
    case geometry::Shape::Kind::kCircle: return "sector " + std::to_string(face + 1);
    case geometry::Shape::Kind::kPolygon: break;
  }
  return "face " + std::to_string(face + 1);
}

const char* shape_name(const geometry::Shape& shape) {
  switch (shape.kind()) {
    case geometry::Shape::Kind::kBox: return "box";
    case geometry::Shape::Kind::kCircle: return "cylinder";
    case geometry::Shape::Kind::kPolygon: break;
  }
  return "polygon";
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
