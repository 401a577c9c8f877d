#pragma once
// Room for the legend. The legend panel sits in the picture's top-left corner; the camera's image plane is
// scaled and shifted (like cropping the film, the view itself unchanged) so that no part of the world, and
// no region label, lies under it. See docs/rendering.md, "Where the legend goes".

#include "camera.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>

namespace physltl::render {

// A rectangle in pixels, origin top left, y down.
struct PixelRect {
  Eigen::Vector2f min = Eigen::Vector2f::Zero();
  Eigen::Vector2f max = Eigen::Vector2f::Zero();

  bool empty() const { return !(max.x() > min.x() && max.y() > min.y()); }
};

// Something drawn at a fixed size in pixels next to a world point, such as a region's label: `offset` is
// its rectangle relative to the pixel the anchor projects to.
struct AnchoredRect {
  Eigen::Vector3f anchor = Eigen::Vector3f::Zero();
  PixelRect offset;
};

// `view` with its image plane scaled by the largest factor up to 1, then shifted as little as possible, such
// that every `world` point lies inside the frame's margin, every label inside the frame, and the convex hull
// of all of them at least a few pixels away from `legend`. The view as it is when `legend` is empty or when
// no scale down to 1/20 leaves room (a legend wider and taller than the frame).
CameraView leave_room_for_legend(const CameraView& view, std::span<const Eigen::Vector3f> world,
                                 std::span<const AnchoredRect> labels, const PixelRect& legend);

}  // namespace physltl::render
