#pragma once
// What each kind of shape is to a scenario, one row per kind (geometry/shape_kinds.h has the geometry's):
// its name and faces as scenario files write them, how its size is checked and told, how it is written to
// JSON, how its push_from is read. A new kind of body is one more row here.

#include "physltl/scenario/world.h"
#include "table_reader.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace physltl::scenario {

struct ShapeKindScenario {
  const char* name;  // "box", "cylinder", "polygon"
  int (*face_count)(const geometry::Shape& shape);
  std::string (*face_name)(const geometry::Shape& shape, int face);
  // "0.5 x 0.5 m", for check's summary.
  std::string (*size_text)(const geometry::Shape& shape);
  // Its footprint in check --json: a box as it always was ({center, size, yaw_deg}), other kinds with
  // "shape" and what they are made of.
  nlohmann::ordered_json (*to_json)(const geometry::Footprint& footprint);
  // Validation of its size: `range(what, value)` for each length to hold between 0 and the longest a
  // scenario may give, `too_large()` when it has no such length but reaches too far.
  void (*check_size)(const geometry::Shape& shape, const std::function<void(const std::string&, double)>& range,
                     const std::function<void()>& too_large, double longest);
  // Whether it has an outline to place (a polygon whose corners could not be read has none).
  bool (*placeable)(const geometry::Shape& shape);
  // A movable body's push_from: the faces it names, as this kind numbers them (errors through `r`).
  std::vector<int> (*read_push_from)(TableReader& r, const geometry::Shape& shape);
};

const ShapeKindScenario& kind_of(const geometry::Shape& shape);

}  // namespace physltl::scenario
