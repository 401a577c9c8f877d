#include "framing.h"

#include "physltl/geometry/convex_hull.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

namespace physltl::render {
namespace {

using Eigen::Vector2f;
using geometry::Vec2;

constexpr float kWorldMargin = 0.04f;  // of the frame's width and height on each side, as the default framing
constexpr float kLabelMargin = 2.0f;   // pixels between a label and the frame's edge
constexpr float kLegendGap = 4.0f;     // pixels between the legend and the nearest thing of the world
constexpr float kSmallestScale = 0.05f;
constexpr int kBisections = 24;

// The half-plane {t : normal . t <= bound}.
struct HalfPlane {
  Vec2 normal;
  double bound;
};

// The part of a convex polygon on the half-plane's side (one step of Sutherland and Hodgman's clipping).
std::vector<Vec2> clip(const std::vector<Vec2>& polygon, const HalfPlane& h) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    const double da = h.normal.dot(a) - h.bound, db = h.normal.dot(b) - h.bound;
    if (da <= 0) out.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

Vec2 closest_point_on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  if (length2 == 0) return a;
  return a + d * std::clamp((p - a).dot(d) / length2, 0.0, 1.0);
}

// The point of a convex polygon nearest to the origin.
Vec2 closest_to_origin(const std::vector<Vec2>& polygon) {
  if (polygon.size() >= 3 && geometry::Polygon{polygon}.contains(Vec2::Zero())) return Vec2::Zero();
  Vec2 best = polygon.front();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 p = closest_point_on_segment(polygon[i], polygon[(i + 1) % polygon.size()], Vec2::Zero());
    if (p.squaredNorm() < best.squaredNorm()) best = p;
  }
  return best;
}

class LegendFit {
 public:
  LegendFit(const CameraView& view, std::span<const Eigen::Vector3f> world, std::span<const AnchoredRect> labels,
            const PixelRect& legend)
      : size_(static_cast<float>(view.width), static_cast<float>(view.height)), centre_(0.5f * size_), legend_(legend) {
    for (const Eigen::Vector3f& p : world) world_.push_back(view.to_pixels(p));
    for (const AnchoredRect& label : labels) labels_.push_back({view.to_pixels(label.anchor), label.offset});
  }

  // The shift (pixels) nearest to none that places everything at `scale` about the frame's centre, if any.
  std::optional<Vec2> shift_at(float scale) const {
    std::vector<Vec2> points;
    Eigen::AlignedBox2f world_box, label_box;
    for (const Vector2f& p : world_) {
      const Vector2f q = centre_ + scale * (p - centre_);
      world_box.extend(q);
      points.push_back(q.cast<double>());
    }
    for (const Label& label : labels_) {
      const Vector2f q = centre_ + scale * (label.anchor - centre_);
      for (const Vector2f& corner : {label.offset.min, label.offset.max, Vector2f(label.offset.min.x(), label.offset.max.y()),
                                     Vector2f(label.offset.max.x(), label.offset.min.y())}) {
        label_box.extend(q + corner);
        points.push_back((q + corner).cast<double>());
      }
    }
    // Shifts that keep the world inside the margin and the labels inside the frame: a rectangle.
    Vector2f low = -Vector2f::Constant(std::numeric_limits<float>::max()), high = -low;
    const Vector2f margin = kWorldMargin * size_;
    if (!world_box.isEmpty()) {
      low = low.cwiseMax(margin - world_box.min());
      high = high.cwiseMin(size_ - margin - world_box.max());
    }
    if (!label_box.isEmpty()) {
      low = low.cwiseMax(Vector2f::Constant(kLabelMargin) - label_box.min());
      high = high.cwiseMin(size_ - Vector2f::Constant(kLabelMargin) - label_box.max());
    }
    if ((high.array() < low.array()).any()) return std::nullopt;
    const std::vector<Vec2> shifts = {low.cast<double>(), {high.x(), low.y()}, high.cast<double>(), {low.x(), high.y()}};

    std::optional<Vec2> best;
    for (const HalfPlane& h : separations(geometry::convex_hull(points))) {
      const std::vector<Vec2> allowed = clip(shifts, h);
      if (allowed.empty()) continue;
      const Vec2 shift = closest_to_origin(allowed);
      if (!best || shift.squaredNorm() < best->squaredNorm()) best = shift;
    }
    return best;
  }

 private:
  struct Label {
    Vector2f anchor;
    PixelRect offset;
  };

  // The shifts that separate `hull` from the legend along one axis each. Two convex shapes are apart iff
  // some edge normal of one of them separates them (the separating axis theorem): the hull's outward
  // normals, and the legend's four sides.
  std::vector<HalfPlane> separations(const geometry::Polygon& hull) const {
    std::vector<Vec2> normals = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    const std::vector<Vec2>& v = hull.vertices;
    for (std::size_t i = 0; v.size() >= 2 && i < v.size(); ++i) {
      const Vec2 edge = v[(i + 1) % v.size()] - v[i];
      if (edge.norm() > 0) normals.push_back(Vec2(edge.y(), -edge.x()).normalized());  // outward: hull is ccw
    }
    const Vec2 legend[4] = {legend_.min.cast<double>(), legend_.max.cast<double>(),
                            {legend_.min.x(), legend_.max.y()}, {legend_.max.x(), legend_.min.y()}};
    std::vector<HalfPlane> result;
    for (const Vec2& n : normals) {
      double hull_far = -std::numeric_limits<double>::max(), legend_near = std::numeric_limits<double>::max();
      for (const Vec2& p : v) hull_far = std::max(hull_far, n.dot(p));
      for (const Vec2& l : legend) legend_near = std::min(legend_near, n.dot(l));
      result.push_back({n, legend_near - kLegendGap - hull_far});  // hull_far + n.shift <= legend_near - gap
    }
    return result;
  }

  Vector2f size_, centre_;
  PixelRect legend_;
  std::vector<Vector2f> world_;
  std::vector<Label> labels_;
};

CameraView scaled_and_shifted(CameraView view, float scale, const Vec2& shift) {
  // ndc' = scale * ndc + (2 shift_x / width, -2 shift_y / height): pixel y runs down, ndc y up.
  Eigen::Matrix4f crop = Eigen::Matrix4f::Identity();
  crop(0, 0) = crop(1, 1) = scale;
  crop(0, 3) = static_cast<float>(2 * shift.x() / view.width);
  crop(1, 3) = static_cast<float>(-2 * shift.y() / view.height);
  view.view_projection = crop * view.view_projection;
  view.metres_per_pixel /= scale;
  return view;
}

}  // namespace

CameraView leave_room_for_legend(const CameraView& view, std::span<const Eigen::Vector3f> world,
                                 std::span<const AnchoredRect> labels, const PixelRect& legend) {
  if (legend.empty()) return view;
  const LegendFit fit(view, world, labels, legend);
  if (const std::optional<Vec2> shift = fit.shift_at(1.0f)) return scaled_and_shifted(view, 1.0f, *shift);
  // A smaller scale leaves more room (the world shrinks about its own middle, labels keep their size), so the
  // largest scale that fits is found by bisection; what is returned is a placement found to fit.
  float fits = kSmallestScale, too_large = 1.0f;
  std::optional<Vec2> shift = fit.shift_at(fits);
  if (!shift) return view;
  for (int i = 0; i < kBisections; ++i) {
    const float middle = 0.5f * (fits + too_large);
    if (const std::optional<Vec2> s = fit.shift_at(middle)) {
      fits = middle;
      shift = s;
    } else {
      too_large = middle;
    }
  }
  return scaled_and_shifted(view, fits, *shift);
}

}  // namespace physltl::render
