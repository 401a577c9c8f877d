#pragma once
// Where the picture is taken from: the 3/4 perspective of the scenario's camera settings, or a top view.

#include "physltl/geometry/shapes.h"
#include "physltl/render/scene.h"
#include "physltl/scenario/world.h"

#include <Eigen/Core>

namespace physltl::render {

struct CameraView {
  Eigen::Matrix4f view_projection;  // world -> clip space
  float metres_per_pixel = 0;       // at the camera target, to size lines given in pixels
  Eigen::Vector3f towards_camera;   // unit vector, for lighting
  int width = 0;
  int height = 0;

  // Pixel coordinates (origin top left, y down) of a world point.
  Eigen::Vector2f to_pixels(const Eigen::Vector3f& world_point) const;
};

// `top_height` is the height of the tallest body, so the perspective fit keeps whole walls in view.
CameraView make_camera_view(const scenario::World& world, double top_height, View view, int width, int height);

}  // namespace physltl::render
