#include "label_placement.h"

#include <algorithm>
#include <limits>

namespace physltl::render {
namespace {

using Eigen::Vector2f;

constexpr float kGap = 2.0f;  // pixels between a label and its region, the frame's edge or the legend
constexpr float kOverAnotherRegion = 1000.0f;

float overlap(const PixelRect& a, const PixelRect& b) {
  const Vector2f low = a.min.cwiseMax(b.min), high = a.max.cwiseMin(b.max);
  return (high.array() > low.array()).all() ? (high - low).prod() : 0.0f;
}

// Next to the region, so that no leader line is needed: below it (the first choice: a box standing on it
// stays visible), above, right and left.
std::vector<Vector2f> places_around(const PixelRect& region, const Vector2f& size) {
  const Vector2f centre = 0.5f * (region.min + region.max);
  return {{centre.x() - size.x() / 2, region.max.y() + kGap},
          {centre.x() - size.x() / 2, region.min.y() - kGap - size.y()},
          {region.max.x() + kGap, centre.y() - size.y() / 2},
          {region.min.x() - kGap - size.x(), centre.y() - size.y() / 2}};
}

}  // namespace

std::vector<std::optional<Vector2f>> place_labels(const std::vector<LabelRequest>& labels, const std::vector<PixelRect>& bodies,
                                                  const PixelRect& legend, const Vector2f& frame) {
  std::vector<std::optional<Vector2f>> result;
  std::vector<PixelRect> placed;
  PixelRect kept_clear = legend;
  kept_clear.min -= Vector2f::Constant(kGap);
  kept_clear.max += Vector2f::Constant(kGap);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const LabelRequest& label = labels[i];
    std::optional<Vector2f> best;
    float best_cover = std::numeric_limits<float>::max();
    for (const Vector2f& place : places_around(label.region, label.size)) {
      const PixelRect rect{place, place + label.size};
      const bool inside = (rect.min.array() >= kGap).all() && (rect.max.array() <= frame.array() - kGap).all();
      if (!inside || (!legend.empty() && overlap(rect, kept_clear) > 0)) continue;
      if (std::any_of(placed.begin(), placed.end(), [&](const PixelRect& other) { return overlap(rect, other) > 0; })) continue;
      float cover = 0;
      for (const PixelRect& body : bodies) cover += overlap(rect, body);
      cover /= label.size.prod();
      // Over another region, a label reads as that region's: worse than any cover of bodies.
      for (std::size_t j = 0; j < labels.size(); ++j) {
        if (j != i && overlap(rect, labels[j].region) > 0) cover += kOverAnotherRegion;
      }
      if (cover < best_cover) best = place, best_cover = cover;
      if (cover <= kMaxBodyCover) break;  // the first place in order that covers little
    }
    if (best) placed.push_back({*best, *best + label.size});
    result.push_back(best);
  }
  return result;
}

}  // namespace physltl::render
