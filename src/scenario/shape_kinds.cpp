// The scenario's table of shape kinds (shape_kinds.h).

#include "shape_kinds.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

namespace physltl::scenario {
namespace {

using geometry::Vec2;
using json = nlohmann::ordered_json;

json point(const Vec2& p) { return {p.x(), p.y()}; }
double yaw_deg(const geometry::Footprint& f) { return f.pose.yaw * 180.0 / std::numbers::pi; }

// A box: four sides named in its own frame.
namespace box {

std::optional<Side> parse_side(const std::string& text) {
  static const std::map<std::string, Side> sides = {
      {"-x", Side::kMinusX}, {"+x", Side::kPlusX}, {"-y", Side::kMinusY}, {"+y", Side::kPlusY}};
  auto it = sides.find(text);
  return it == sides.end() ? std::nullopt : std::optional<Side>(it->second);
}

std::vector<int> read_push_from(TableReader& r, const geometry::Shape&) {
  std::vector<int> faces;
  for (const auto& text : r.strings("push_from")) {
    if (auto side = parse_side(text)) {
      faces.push_back(static_cast<int>(*side));
    } else {
      r.error("'push_from' sides are \"-x\", \"+x\", \"-y\" or \"+y\" (in the body's frame), got \"" + text + "\"");
    }
  }
  return faces;
}

constexpr ShapeKindScenario kRow{
    "box",
    [](const geometry::Shape&) { return 4; },
    [](const geometry::Shape&, int face) { return std::string(side_name(static_cast<Side>(face))); },
    [](const geometry::Shape& s) { return fmt::format("{:g} x {:g} m", 2 * s.half_extents().x(), 2 * s.half_extents().y()); },
    [](const geometry::Footprint& f) {
      return json{{"center", point(f.pose.position)}, {"size", point(2.0 * f.shape.half_extents())}, {"yaw_deg", yaw_deg(f)}};
    },
    [](const geometry::Shape& s, const std::function<void(const std::string&, double)>& range, const std::function<void()>&, double) {
      range("'size' x", 2 * s.half_extents().x());
      range("'size' y", 2 * s.half_extents().y());
    },
    [](const geometry::Shape&) { return true; },
    read_push_from,
};

}  // namespace box

// A cylinder: kCylinderSectors sectors, pushed from wherever the robot touches it.
namespace cylinder {

constexpr ShapeKindScenario kRow{
    "cylinder",
    [](const geometry::Shape&) { return kCylinderSectors; },
    [](const geometry::Shape&, int face) { return "sector " + std::to_string(face + 1); },
    [](const geometry::Shape& s) { return fmt::format("cylinder r = {:g} m", s.radius()); },
    [](const geometry::Footprint& f) {
      return json{{"shape", "cylinder"}, {"center", point(f.pose.position)}, {"radius", f.shape.radius()}};
    },
    [](const geometry::Shape& s, const std::function<void(const std::string&, double)>& range, const std::function<void()>&, double) {
      range("'radius'", s.radius());
    },
    [](const geometry::Shape&) { return true; },
    [](TableReader& r, const geometry::Shape&) {
      r.strings("push_from");
      r.error("'push_from' is for boxes and polygons: a cylinder is pushed from wherever the robot touches it, towards "
              "its axis");
      return std::vector<int>{};
    },
};

}  // namespace cylinder

// A polygon: face k from corner k to corner k + 1 of its outline.
namespace polygon {

json to_json(const geometry::Footprint& f) {
  json parts = json::array();
  for (const geometry::Polygon& part : f.shape.parts()) {
    json corners = json::array();
    for (const Vec2& v : part.vertices) corners.push_back(point(v));
    parts.push_back(std::move(corners));
  }
  json outline = json::array();
  for (const Vec2& v : f.shape.outline().vertices) outline.push_back(point(v));
  return {{"shape", "polygon"}, {"center", point(f.pose.position)}, {"yaw_deg", yaw_deg(f)}, {"points", outline}, {"convex_parts", parts}};
}

std::vector<int> read_push_from(TableReader& r, const geometry::Shape& shape) {
  std::vector<int> faces;
  const int count = static_cast<int>(shape.outline().vertices.size());
  for (int face : r.integers("push_from")) {
    if (face >= 1 && face <= count) {
      faces.push_back(face - 1);
    } else {
      r.error("'push_from' faces of a polygon are 1 to " + std::to_string(count) + " (face k runs from corner k to " +
              "the next), got " + std::to_string(face));
    }
  }
  return faces;
}

constexpr ShapeKindScenario kRow{
    "polygon",
    [](const geometry::Shape& s) { return static_cast<int>(s.outline().vertices.size()); },
    [](const geometry::Shape&, int face) { return "face " + std::to_string(face + 1); },
    [](const geometry::Shape& s) { return fmt::format("polygon of {} corners, {:.3g} m2", s.outline().vertices.size(), s.area()); },
    to_json,
    // Corners, convexity and area were checked as the polygon was read.
    [](const geometry::Shape& s, const std::function<void(const std::string&, double)>& range, const std::function<void()>& too_large,
       double longest) {
      if (s.bound_radius() > longest) too_large();
      if (!s.parts().empty()) range("the square root of its area", std::sqrt(s.area()));
    },
    [](const geometry::Shape& s) { return !s.parts().empty(); },
    read_push_from,
};

}  // namespace polygon

// geometry::Shape::Kind order.
constexpr std::array<const ShapeKindScenario*, 3> kKinds = {&box::kRow, &cylinder::kRow, &polygon::kRow};

}  // namespace

const ShapeKindScenario& kind_of(const geometry::Shape& shape) { return *kKinds[static_cast<std::size_t>(shape.kind())]; }

int face_count(const geometry::Shape& shape) { return kind_of(shape).face_count(shape); }

std::string face_name(const geometry::Shape& shape, int face) { return kind_of(shape).face_name(shape, face); }

const char* shape_name(const geometry::Shape& shape) { return kind_of(shape).name; }

std::string shape_size_text(const geometry::Shape& shape) { return kind_of(shape).size_text(shape); }

}  // namespace physltl::scenario
