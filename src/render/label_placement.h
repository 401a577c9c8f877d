#pragma once
// Where region labels go (docs/rendering.md, "Labels"): each region's label (its name and the object
// goals on it, stacked) in the first of a few places around the region, in pixels of the final framing,
// where it overlaps no label placed before it, stays clear of the legend and inside the frame, lies over no
// other region and covers little of the bodies (else the free place that does so least); a label with no
// free place is left out.

#include "framing.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace physltl::render {

// The most of a label's area that may lie over the bodies' outlines while a place without overlap is
// left; when every free place covers more, the least covered is taken.
inline constexpr float kMaxBodyCover = 0.25f;

struct LabelRequest {
  PixelRect region;       // the region's box in the picture
  Eigen::Vector2f size;   // the label's width and height
};

// Each label's top-left corner, or none where it is left out. Labels are placed in the order given.
std::vector<std::optional<Eigen::Vector2f>> place_labels(const std::vector<LabelRequest>& labels, const std::vector<PixelRect>& bodies,
                                                         const PixelRect& legend, const Eigen::Vector2f& frame);

}  // namespace physltl::render
