#include "camera.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace physltl::render {
namespace {

using Eigen::Matrix4f;
using Eigen::Vector3f;

constexpr float kMargin = 0.92f;  // the fitted scene fills this fraction of the frame

float radians(double degrees) { return static_cast<float>(degrees * std::numbers::pi / 180.0); }

Matrix4f look_at(const Vector3f& eye, const Vector3f& forward, const Vector3f& right, const Vector3f& up) {
  Matrix4f m = Matrix4f::Identity();
  m.block<1, 3>(0, 0) = right.transpose();
  m.block<1, 3>(1, 0) = up.transpose();
  m.block<1, 3>(2, 0) = -forward.transpose();
  m(0, 3) = -right.dot(eye);
  m(1, 3) = -up.dot(eye);
  m(2, 3) = forward.dot(eye);
  return m;
}

Matrix4f perspective(float fov_y, float aspect, float near, float far) {
  const float f = 1.0f / std::tan(fov_y / 2);
  Matrix4f m = Matrix4f::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far + near) / (near - far);
  m(2, 3) = 2 * far * near / (near - far);
  m(3, 2) = -1;
  return m;
}

Matrix4f orthographic(float left, float right, float bottom, float top, float near, float far) {
  Matrix4f m = Matrix4f::Identity();
  m(0, 0) = 2 / (right - left);
  m(1, 1) = 2 / (top - bottom);
  m(2, 2) = -2 / (far - near);
  m(0, 3) = -(right + left) / (right - left);
  m(1, 3) = -(top + bottom) / (top - bottom);
  m(2, 3) = -(far + near) / (far - near);
  return m;
}

CameraView top_view(const geometry::Rect& bounds, double top_height, int width, int height) {
  const float aspect = static_cast<float>(width) / height;
  const Eigen::Vector2f centre = (0.5 * (bounds.min + bounds.max)).cast<float>();
  const Eigen::Vector2f size = bounds.size().cast<float>();
  // Half of the visible height, so that the whole workspace fits with a margin whichever side is tighter.
  const float half_height = std::max(size.y(), size.x() / aspect) / (2 * kMargin);
  const float half_width = half_height * aspect;
  const float eye_height = static_cast<float>(top_height) + 10.0f;
  const Vector3f eye(centre.x(), centre.y(), eye_height);
  CameraView view;
  view.view_projection = orthographic(-half_width, half_width, -half_height, half_height, 1.0f, eye_height + 1.0f) *
                         look_at(eye, -Vector3f::UnitZ(), Vector3f::UnitX(), Vector3f::UnitY());
  view.metres_per_pixel = 2 * half_height / height;
  view.towards_camera = Vector3f::UnitZ();
  return view;
}

// Moves the projected workspace box to the middle of the picture and, with `fill`, scales it to fill the
// margin along the tighter side: an off-axis view of the same camera, like cropping its film.
void frame_workspace(CameraView& view, const geometry::Rect& bounds, double top_height, bool fill) {
  Eigen::Vector2f low = Eigen::Vector2f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector2f high = -low;
  for (double x : {bounds.min.x(), bounds.max.x()}) {
    for (double y : {bounds.min.y(), bounds.max.y()}) {
      for (double z : {0.0, top_height}) {
        const Eigen::Vector4f clip = view.view_projection * Eigen::Vector4f(static_cast<float>(x), static_cast<float>(y),
                                                                            static_cast<float>(z), 1.0f);
        const Eigen::Vector2f ndc = clip.head<2>() / clip.w();
        low = low.cwiseMin(ndc);
        high = high.cwiseMax(ndc);
      }
    }
  }
  const Eigen::Vector2f centre = 0.5f * (low + high);
  const float scale = fill ? 2 * kMargin / (high - low).maxCoeff() : 1.0f;
  Matrix4f crop = Matrix4f::Identity();  // ndc' = scale * (ndc - centre), depth unchanged
  crop(0, 0) = crop(1, 1) = scale;
  crop(0, 3) = -scale * centre.x();
  crop(1, 3) = -scale * centre.y();
  view.view_projection = crop * view.view_projection;
  view.metres_per_pixel /= scale;
}

CameraView perspective_view(const scenario::World& world, double azimuth_deg, double top_height, int width, int height) {
  const scenario::Camera& camera = world.render.camera;
  const float aspect = static_cast<float>(width) / height;
  const float elevation = radians(camera.elevation_deg), azimuth = radians(azimuth_deg);
  const Vector3f towards_camera(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                                std::sin(elevation));
  const Vector3f forward = -towards_camera;
  const Vector3f right = forward.cross(Vector3f::UnitZ()).normalized();
  const Vector3f up = right.cross(forward);
  const geometry::Rect& bounds = world.workspace.bounds;
  const geometry::Vec2 aim = camera.target.value_or(geometry::Vec2(0.5 * (bounds.min + bounds.max)));
  const Vector3f target(static_cast<float>(aim.x()), static_cast<float>(aim.y()), 0.0f);
  const float tan_y = std::tan(radians(camera.fov_deg) / 2), tan_x = tan_y * aspect;

  float distance = static_cast<float>(camera.distance);
  if (distance <= 0) {
    // The smallest distance at which every corner of the workspace box projects inside the margin: a point
    // p (relative to the target) lies at depth distance - p.towards_camera in front of the eye, and is in
    // view when |p.right| <= depth * tan_x * margin and |p.up| <= depth * tan_y * margin.
    const geometry::Rect& b = world.workspace.bounds;
    for (double x : {b.min.x(), b.max.x()}) {
      for (double y : {b.min.y(), b.max.y()}) {
        for (double z : {0.0, top_height}) {
          const Vector3f p = Vector3f(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)) - target;
          const float towards = p.dot(towards_camera);
          distance = std::max({distance, towards + std::abs(p.dot(right)) / (tan_x * kMargin),
                               towards + std::abs(p.dot(up)) / (tan_y * kMargin)});
        }
      }
    }
  }
  const Vector3f eye = target + distance * towards_camera;
  const float scene_radius = static_cast<float>(world.workspace.bounds.size().norm()) + static_cast<float>(top_height);
  const float near = std::max(0.05f, distance - 2 * scene_radius), far = distance + 2 * scene_radius;
  CameraView view;
  view.view_projection = perspective(radians(camera.fov_deg), aspect, near, far) * look_at(eye, forward, right, up);
  view.metres_per_pixel = 2 * distance * tan_y / height;
  view.towards_camera = towards_camera;
  // Perspective draws the near side larger than the far one, so a picture aimed at the workspace's centre
  // shows the workspace off centre. Unless the author chose the target (or the distance), shift (and
  // scale) the image plane so that the projected workspace is centred (and fills the frame's margin).
  if (!camera.target) frame_workspace(view, world.workspace.bounds, top_height, camera.distance <= 0);
  return view;
}

// The author's azimuth; else from the south (-90 degrees), unless the workspace is clearly taller than wide
// and the east (0) shows it larger: a tall world then runs across a wide frame instead of standing small
// in its middle.
double azimuth_deg(const scenario::World& world, double top_height, int width, int height) {
  if (world.render.camera.azimuth_deg) return *world.render.camera.azimuth_deg;
  constexpr double kSouth = -90.0, kEast = 0.0, kTall = 1.2;
  const geometry::Vec2 size = world.workspace.bounds.size();
  if (size.y() <= kTall * size.x()) return kSouth;
  const CameraView south = perspective_view(world, kSouth, top_height, width, height);
  const CameraView east = perspective_view(world, kEast, top_height, width, height);
  return east.metres_per_pixel < south.metres_per_pixel ? kEast : kSouth;
}

}  // namespace

Eigen::Vector2f CameraView::to_pixels(const Eigen::Vector3f& world_point) const {
  const Eigen::Vector4f clip = view_projection * world_point.homogeneous();
  const Eigen::Vector2f ndc = clip.head<2>() / clip.w();
  return {(ndc.x() + 1) / 2 * width, (1 - ndc.y()) / 2 * height};
}

CameraView make_camera_view(const scenario::World& world, double top_height, View view, int width, int height) {
  CameraView result = view == View::kTop ? top_view(world.workspace.bounds, top_height, width, height)
                                         : perspective_view(world, azimuth_deg(world, top_height, width, height), top_height, width, height);
  result.width = width;
  result.height = height;
  return result;
}

}  // namespace physltl::render
