// Two parts. What never changes while one camera looks at one World is drawn once, supersampled 2x2 and
// averaged down, and kept with its depth: floor, grid, decomposition, regions, the fixed bodies' shadows, the
// search tree's segments and the fixed bodies; the solution path is painted over it as it grows. Every
// picture starts as a copy of it (colour and depth), then draws what moves:
//   mRegions, shadows of the moving bodies (flat on the floor, depth tested so that walls in front hide
//   them) -> movable boxes and the robot (depth tested) -> label and legend panels -> text.
// So the static scene is anti-aliased at no cost per frame (multisampling every frame cost 4x on llvmpipe,
// docs/rendering.md), and a frame costs what moves. Text is anti-aliased by its glyph coverage.

#include "physltl/render/renderer.h"

#include "camera.h"
#include "flat_geometry.h"
#include "framing.h"
#include "label_placement.h"
#include "legend_layout.h"
#include "gl_objects.h"
#include "meshes.h"
#include "palette.h"
#include "shape_kinds.h"
#include "shaders.h"
#include "text.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <memory>
#include <map>
#include <optional>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

namespace physltl::render {
namespace {

using Eigen::Matrix4f;
using Eigen::Vector3f;
using geometry::Pose2;

// Line widths in pixels at the camera target, converted to metres with the view's scale. Without
// multisampling a line thinner than a pixel breaks up, and perspective thins far lines by up to a third.
constexpr double kGridWidth = 1.5;
constexpr double kDecompositionWidth = 1.5;
constexpr double kEdgeWidth = 1.5;
constexpr double kGoalEdgeWidth = 4.0;
constexpr double kSegmentWidth = 1.5;
constexpr double kPathWidth = 3.0;
constexpr double kPathHaloWidth = 6.0;
constexpr float kPanelPadding = 3.0f;
constexpr float kLegendMargin = 2 * kPanelPadding;  // between the legend panel and the frame's corner
constexpr float kShadowStrength = 0.5f;  // alpha of black at the shadow's centre
constexpr int kSupersampling = 2;         // the static scene is drawn this many times larger each way

Vector3f towards_light() { return Vector3f(-0.35f, -0.5f, 0.8f).normalized(); }

Matrix4f body_transform(const Pose2& pose, float z, const Vector3f& scale) {
  Eigen::Affine3f t = Eigen::Translation3f(static_cast<float>(pose.position.x()),
                                           static_cast<float>(pose.position.y()), z) *
                      Eigen::AngleAxisf(static_cast<float>(pose.yaw), Vector3f::UnitZ()) * Eigen::Scaling(scale);
  return t.matrix();
}

// Appends `mesh` placed by `model` (x y z nx ny nz r g b a per vertex). Bodies are placed here on the CPU
// (a few thousand vertices) so that all of them take two draw calls, not one per body. `model` scales boxes along their own axes only and box normals lie on those axes, so rotating the normals
// is enough (no inverse transpose).
void add_mesh(std::vector<float>& out, const TriangleMesh& mesh, const Matrix4f& model, const Color& color) {
  const Eigen::Matrix3f rotation = model.topLeftCorner<3, 3>().colwise().normalized();
  for (std::size_t i = 0; i + 5 < mesh.size(); i += 6) {
    const Vector3f p = (model * Eigen::Vector4f(mesh[i], mesh[i + 1], mesh[i + 2], 1)).head<3>();
    const Vector3f n = rotation * Vector3f(mesh[i + 3], mesh[i + 4], mesh[i + 5]);
    out.insert(out.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), color.r, color.g, color.b, color.a});
  }
}

// Maps pixels (origin top left, y down) to clip space.
Matrix4f pixel_transform(int width, int height) {
  Matrix4f m = Matrix4f::Identity();
  m(0, 0) = 2.0f / width;
  m(0, 3) = -1;
  m(1, 1) = -2.0f / height;
  m(1, 3) = 1;
  return m;
}

// RGBA -> RGB for one row of `pixels`. GCC vectorises this byte loop into shuffles; word tricks were slower.
void strip_alpha(const std::uint8_t* rgba, std::uint8_t* rgb, int pixels) {
  for (int x = 0; x < pixels; ++x, rgba += 4, rgb += 3) {
    rgb[0] = rgba[0];
    rgb[1] = rgba[1];
    rgb[2] = rgba[2];
  }
}

void set_color(GLint location, const Color& c) { glUniform4f(location, c.r, c.g, c.b, c.a); }

// Rounded-rectangle shadows under the bodies, shifted away from the light by their height.
class ShadowGeometry {
 public:
  void add(const Pose2& pose, const Vec2& half_extents, double corner_radius, double height) {
    const Vec2 shift = offset(height);
    const double softness = blur(height);
    const Vec2 reach = half_extents + Vec2::Constant(corner_radius + 1.5 * softness);
    const Eigen::Rotation2Dd rotation(pose.yaw);
    const Vec2 corners[4] = {{-reach.x(), -reach.y()}, {reach.x(), -reach.y()}, {reach.x(), reach.y()},
                             {-reach.x(), reach.y()}};
    for (int i : {0, 1, 2, 0, 2, 3}) {
      const Vec2 world = pose.position + shift + rotation * corners[i];
      floats_.insert(floats_.end(),
                     {static_cast<float>(world.x()), static_cast<float>(world.y()), 0.0f,
                      static_cast<float>(corners[i].x()), static_cast<float>(corners[i].y()),
                      static_cast<float>(half_extents.x()), static_cast<float>(half_extents.y()),
                      static_cast<float>(corner_radius), static_cast<float>(softness), kShadowStrength});
    }
  }
  const std::vector<float>& floats() const { return floats_; }

  // Where the shadows of bodies no taller than `height` standing inside `bounds` may be drawn: shifted away
  // from the light, and blurred all round.
  static geometry::Rect reach(const geometry::Rect& bounds, double height) {
    const Vec2 shift = offset(height);
    const Vec2 blurred = Vec2::Constant(std::sqrt(2.0) * 1.5 * blur(height));
    return {bounds.min + shift.cwiseMin(0.0) - blurred, bounds.max + shift.cwiseMax(0.0) + blurred};
  }

 private:
  static Vec2 offset(double height) {
    const Vector3f light = towards_light();
    return Vec2(-light.x(), -light.y()) / light.z() * (0.5 * height);
  }
  static double blur(double height) { return 0.04 + 0.12 * height; }

  std::vector<float> floats_;
};

// The GL objects below are created as members, so the context must be current before any of them.
std::unique_ptr<OffscreenContext> made_current(std::unique_ptr<OffscreenContext> context) {
  context->make_current();
  return context;
}

}  // namespace

struct Renderer::Impl {
  scenario::World world;
  std::unique_ptr<OffscreenContext> context;
  int width, height;
  double top_height = 0;  // of the tallest body

  GlProgram lit{shaders::kLitVertex, shaders::kLitFragment};
  GlProgram flat{shaders::kFlatVertex, shaders::kFlatFragment};
  GlProgram shadow{shaders::kShadowVertex, shaders::kShadowFragment};
  GlProgram text{shaders::kTextVertex, shaders::kTextFragment};
  GlProgram layer_program{shaders::kLayerVertex, shaders::kLayerFragment};

  const TriangleMesh cube = unit_cube_mesh();
  mutable std::map<const geometry::Shape*, TriangleMesh> shape_meshes;  // of the World's cylinders and polygons
  const TriangleMesh sphere = unit_sphere_mesh(32, 16);
  GlMesh fixed_layer{3, 3, 4};  // the fixed bodies never move: built once
  GlMesh static_floor_layer{3, 4};
  GlMesh static_shadow_layer{3, 2, 4, 1};
  GlMesh mregion_layer{3, 4};
  // One buffer per layer, all filled before the first draw call of a frame: refilling a buffer that queued
  // draw calls still read would make the driver finish those first.
  GlMesh moving_layer{3, 3, 4};  // movable boxes and the robot
  GlMesh shadow_layer{3, 2, 4, 1};
  GlMesh segment_layer{3, 4};
  GlMesh path_layer{3, 4};
  GlMesh panel_layer{3, 4};
  GlMesh glyph_layer{2, 2};
  GlMesh resting_mregion_layer{3, 4};
  GlMesh resting_shadow_layer{3, 2, 4, 1};
  GlMesh resting_body_layer{3, 3, 4};
  GlMesh frame_quad{2};

  FontAtlas font;
  GLuint font_texture = 0;

  // The static scene for one view: its picture and depth, and what it was drawn for. The travelled path
  // is painted into it as it grows (frames of a plan extend it by a step or two each), so a frame does not
  // draw the whole path again; moving bodies pass over it.
  struct Background {
    View view;
    Matrix4f view_projection;
    std::vector<std::array<Vec2, 3>> decomposition;
    std::vector<SegmentOverlay> segments;
    std::vector<std::string> avoided_regions;
    std::vector<ObjectGoalOverlay> object_goals;  // their regions' outlines; whether they hold is drawn per picture
    std::unique_ptr<GlFramebuffer> framebuffer;
    std::vector<Vec2> path;  // the path painted so far
  };
  std::optional<Background> background;
  // Every picture is drawn here, not into the context's own buffer: copying the background into a
  // framebuffer of the very same formats is a plain memory copy for llvmpipe, and reading it back skips
  // OSMesa's copy into its client buffer.
  std::unique_ptr<GlFramebuffer> frame;
  std::vector<std::uint8_t> rgba;  // read_frame's buffer, kept to avoid allocating every frame

  // The camera of the last picture, kept while its view and its legend's rectangle stay the same (every
  // frame of a video): fitting it around the legend is not free.
  struct Framing {
    View view;
    PixelRect legend;
    std::vector<std::pair<int, int>> goals;  // object goals' (body, region): their labels
    CameraView camera;
    std::vector<std::optional<Eigen::Vector2f>> label_corners;  // per region, for every picture of the framing
  };
  std::optional<Framing> framing;
  PictureWords words;  // of the last picture

  // The movable bodies at rest, drawn once into a layer of their own (their mRegions, shadows and bodies,
  // in the order a frame draws them) that every frame lays over the background: a frame then draws only
  // the bodies that moved since and the robot, so a warehouse of thousands of resting boxes costs what
  // moves. The layer keeps its colours premultiplied by alpha and its depth (the background's and the
  // resting bodies'), so laying it over the background is drawing its contents there in the same order,
  // up to a unit of rounding in a channel. A body that moves, or whose mRegions change, is drawn by every
  // frame from then on (the layer drawn again without it).
  struct RestingLayer {
    View view;
    Matrix4f view_projection;
    std::vector<std::pair<int, int>> goals;  // object goals' (body, region): the bodies' colours
    std::vector<Pose2> poses;                // each movable body's pose as drawn
    std::vector<MRegionOverlay> mregions;    // the overlay's mRegions when it was drawn
    std::vector<bool> moving;                // bodies every frame draws instead
    std::unique_ptr<GlFramebuffer> framebuffer;
    PixelArea area;                          // where the layer has something: what a frame lays
  };
  std::optional<RestingLayer> resting;

  Impl(const scenario::World& w, std::unique_ptr<OffscreenContext> c)
      : world(w),
        context(made_current(std::move(c))),
        width(context->width()),
        height(context->height()),
        font(PHYSLTL_FONT_FILE, std::max(11.0f, std::round(height / 26.0f))) {
    upload_fixed_bodies();
    upload_font();
    const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    frame_quad.upload(corners, std::size(corners), GL_STATIC_DRAW);
  }

  ~Impl() {
    context->make_current();
    glDeleteTextures(1, &font_texture);
  }

  void upload_fixed_bodies() {
    std::vector<float> vertices;
    for (const scenario::FixedBody& body : world.fixed_bodies) {
      top_height = std::max(top_height, body.height);
      if (body.mesh.empty()) {
        add_body(vertices, body.footprint.shape, body.footprint.pose, body.height, palette::kFixedBody);
      } else {
        add_mesh(vertices, obj_mesh(body.mesh, body.mesh_scale), body_transform(body.footprint.pose, 0, Vector3f::Ones()),
                 palette::kFixedBody);
      }
    }
    fixed_layer.upload(vertices.data(), vertices.size(), GL_STATIC_DRAW);
    for (const scenario::MovableBody& body : world.movable_bodies) top_height = std::max(top_height, body.height);
    top_height = std::max(top_height, 2 * world.robot.radius);
  }

  // A box is the unit cube scaled; cylinders and polygons are meshes of their own, made once a shape.
  void add_body(std::vector<float>& vertices, const geometry::Shape& shape, const Pose2& pose, double height,
                const Color& color) const {
    if (const auto size = kind_of(shape).as_cube(shape)) {
      add_mesh(vertices, cube, body_transform(pose, static_cast<float>(height) / 2, Vector3f(size->x(), size->y(), height)), color);
      return;
    }
    auto [mesh, made] = shape_meshes.try_emplace(&shape);
    if (made) mesh->second = kind_of(shape).mesh(shape, height);
    add_mesh(vertices, mesh->second, body_transform(pose, 0, Vector3f::Ones()), color);
  }

  // The movable bodies `moving` says (true: those drawn by every frame, with the robot; false: the resting
  // ones, without it).
  std::vector<float> movable_bodies(const scenario::EnvironmentState& state, const Overlay& overlay, bool moving) const {
    std::vector<float> vertices;
    for (std::size_t i = 0; i < world.movable_bodies.size(); ++i) {
      if (resting->moving[i] != moving) continue;
      const scenario::MovableBody& body = world.movable_bodies[i];
      add_body(vertices, body.footprint.shape, state.movable_poses[i], body.height, body_color(overlay, static_cast<int>(i)));
    }
    if (moving) add_robot(vertices, state);
    return vertices;
  }

  void add_robot(std::vector<float>& vertices, const scenario::EnvironmentState& state) const {
    const float r = static_cast<float>(world.robot.radius);
    add_mesh(vertices, sphere, body_transform({state.robot_position, 0.0}, r, Vector3f::Constant(r)),
             palette::kRobot);
    if (world.robot.drive == scenario::Drive::kDifferential) {
      // A dark bar over the top of the sphere from its centre past its front, so the heading shows from
      // above and from the side.
      const Vec2 heading(std::cos(state.robot_yaw), std::sin(state.robot_yaw));
      const geometry::Pose2 nose{state.robot_position + 0.6 * world.robot.radius * heading, state.robot_yaw};
      add_mesh(vertices, cube, body_transform(nose, 1.95f * r, Vector3f(1.3f * r, 0.35f * r, 0.2f * r)),
               palette::kRobotNose);
    }
  }

  void upload_font() {
    glGenTextures(1, &font_texture);
    glBindTexture(GL_TEXTURE_2D, font_texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, font.atlas_size(), font.atlas_size(), 0, GL_RED, GL_UNSIGNED_BYTE,
                 font.coverage().data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }

  void draw_flat(const GlMesh& layer, const Matrix4f& transform) {
    flat.use();
    glUniformMatrix4fv(flat.uniform("transform"), 1, GL_FALSE, transform.data());
    layer.draw(GL_TRIANGLES);
  }

  FlatGeometry floor_paint(const Overlay& overlay, double metres_per_pixel) const {
    const geometry::Rect& bounds = world.workspace.bounds;
    FlatGeometry paint;
    paint.rectangle(bounds.min, bounds.max, palette::kFloor);
    for (double x = std::ceil(bounds.min.x()); x <= bounds.max.x(); x += 1.0) {
      paint.line({x, bounds.min.y()}, {x, bounds.max.y()}, kGridWidth * metres_per_pixel, palette::kGrid);
    }
    for (double y = std::ceil(bounds.min.y()); y <= bounds.max.y(); y += 1.0) {
      paint.line({bounds.min.x(), y}, {bounds.max.x(), y}, kGridWidth * metres_per_pixel, palette::kGrid);
    }
    for (const auto& cell : overlay.decomposition) {
      paint.outline(geometry::Polygon{{cell.begin(), cell.end()}}, kDecompositionWidth * metres_per_pixel,
                    palette::kDecomposition);
    }
    for (const scenario::Region& region : world.regions) {
      const bool avoided = std::find(overlay.avoided_regions.begin(), overlay.avoided_regions.end(), region.name) !=
                           overlay.avoided_regions.end();
      paint.polygon(region.polygon, avoided ? palette::kAvoidedRegion : palette::kRegion);
      paint.outline(region.polygon, kEdgeWidth * metres_per_pixel, avoided ? palette::kAvoidedRegionEdge : palette::kRegionEdge);
    }
    // A region where the task wants a body: outlined in that body's colour, inside its own edge.
    for (const ObjectGoalOverlay& goal : overlay.object_goals) {
      paint.outline(world.regions[static_cast<std::size_t>(goal.region)].polygon, kGoalEdgeWidth * metres_per_pixel,
                    body_color(overlay, goal.body));
    }
    return paint;
  }

  // The mRegions of the moving bodies (and those of no body), or of the resting ones.
  FlatGeometry mregion_paint(const Overlay& overlay, double metres_per_pixel, bool moving) const {
    FlatGeometry paint;
    for (const MRegionOverlay& m : overlay.mregions) {
      if ((m.body < 0 || resting->moving[static_cast<std::size_t>(m.body)]) != moving) continue;
      paint.polygon(m.polygon, m.active ? palette::kActiveMRegion : palette::kInactiveMRegion);
      paint.outline(m.polygon, kEdgeWidth * metres_per_pixel,
                    m.active ? palette::kActiveMRegionEdge : palette::kInactiveMRegionEdge);
    }
    return paint;
  }

  static void add_shadow(ShadowGeometry& shadows, const geometry::Shape& shape, const Pose2& pose, double height) {
    for (const ShadowShape& shadow : kind_of(shape).shadows(shape, pose)) shadows.add(shadow.pose, shadow.half_extents, shadow.corner_radius, height);
  }

  ShadowGeometry fixed_shadows() const {
    ShadowGeometry result;
    for (const scenario::FixedBody& body : world.fixed_bodies) add_shadow(result, body.footprint.shape, body.footprint.pose, body.height);
    return result;
  }

  ShadowGeometry movable_shadows(const scenario::EnvironmentState& state, bool moving) const {
    ShadowGeometry result;
    for (std::size_t i = 0; i < world.movable_bodies.size(); ++i) {
      if (resting->moving[i] != moving) continue;
      const scenario::MovableBody& body = world.movable_bodies[i];
      add_shadow(result, body.footprint.shape, state.movable_poses[i], body.height);
    }
    if (moving) result.add({state.robot_position, 0.0}, Vec2::Zero(), 0.8 * world.robot.radius, world.robot.radius);
    return result;
  }

  // What the camera must keep clear of the legend: the workspace's box from the floor to the tallest body,
  // with the floor grown by as far as the bodies' shadows reach beyond it.
  std::vector<Vector3f> world_points() const {
    const geometry::Rect& b = world.workspace.bounds;
    const geometry::Rect shadows = ShadowGeometry::reach(b, top_height);
    std::vector<Vector3f> points;
    for (const auto& [r, z] : {std::pair{shadows, 0.0}, std::pair{b, top_height}}) {
      for (double x : {r.min.x(), r.max.x()}) {
        for (double y : {r.min.y(), r.max.y()}) {
          points.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
        }
      }
    }
    return points;
  }

  // Text in a panel, one line of a region's label.
  struct Label {
    std::string text;
    AnchoredRect place;  // the panel's rectangle below the region, where the framing leaves room for it
    Color panel;
    std::size_t region = 0;
  };

  // Each region's label: its name, and below it the object goals on that region, "crate -> dock", green
  // while they hold; more than kListedGoals of them are one line, "5 bodies wanted here, 1 in" (the legend
  // lists them). Anchored centred below the region; where it is drawn is placed_labels' choice.
  static constexpr int kListedGoals = 2;
  std::vector<Label> labels(const Overlay& overlay) const {
    std::vector<Label> result;
    const float h = font.line_height();
    for (std::size_t r = 0; r < world.regions.size(); ++r) {
      const scenario::Region& region = world.regions[r];
      const Vec2 below(region.polygon.centroid().x(), region.polygon.bounds().min.y());
      const Vector3f anchor(static_cast<float>(below.x()), static_cast<float>(below.y()), 0);
      float row = 0;
      // `widest`: the longest text the line shows in any picture of a framing, so that its panel keeps the
      // place chosen for it.
      const auto add = [&](std::string text, const Color& panel, const std::string& widest = "") {
        const float w = std::max(font.width(text), font.width(widest)), top = kPanelPadding / 2 + row * (h + kPanelPadding);
        result.push_back({std::move(text), {anchor, {{-w / 2 - kPanelPadding, top}, {w / 2 + kPanelPadding, top + h + kPanelPadding}}}, panel, r});
        ++row;
      };
      add(region.name, palette::kPanel);
      std::vector<const ObjectGoalOverlay*> goals;
      for (const ObjectGoalOverlay& goal : overlay.object_goals) {
        if (goal.region == static_cast<int>(r)) goals.push_back(&goal);
      }
      if (goals.size() > kListedGoals) {
        const auto in = std::count_if(goals.begin(), goals.end(), [](const ObjectGoalOverlay* g) { return g->holds; });
        const std::string wanted = std::to_string(goals.size()) + " bodies wanted here, ";
        add(wanted + std::to_string(in) + " in", in > 0 ? palette::kGoalHolds : palette::kPanel, wanted + std::to_string(goals.size()) + " in");
        continue;
      }
      for (const ObjectGoalOverlay* goal : goals) {
        add(world.movable_bodies[static_cast<std::size_t>(goal->body)].name + " -> " + region.name,
            goal->holds ? palette::kGoalHolds : palette::kPanel);
      }
    }
    return result;
  }

  // A region's label as a whole: the box of its lines about their anchor.
  static std::vector<PixelRect> label_extents(const std::vector<Label>& lines, std::size_t regions) {
    std::vector<PixelRect> extents(regions, PixelRect{Eigen::Vector2f::Constant(std::numeric_limits<float>::max()),
                                                      Eigen::Vector2f::Constant(-std::numeric_limits<float>::max())});
    for (const Label& line : lines) {
      extents[line.region].min = extents[line.region].min.cwiseMin(line.place.offset.min);
      extents[line.region].max = extents[line.region].max.cwiseMax(line.place.offset.max);
    }
    return extents;
  }

  // The box of `points` in the picture.
  static PixelRect pixel_box(const CameraView& view, const std::vector<Vector3f>& points) {
    PixelRect box{Eigen::Vector2f::Constant(std::numeric_limits<float>::max()), Eigen::Vector2f::Constant(-std::numeric_limits<float>::max())};
    for (const Vector3f& p : points) {
      const Eigen::Vector2f q = view.to_pixels(p);
      box.min = box.min.cwiseMin(q);
      box.max = box.max.cwiseMax(q);
    }
    return box;
  }

  // Every body's outline in the picture, floor to top, the robot's too: what labels should not cover.
  std::vector<PixelRect> body_boxes(const CameraView& view, const scenario::EnvironmentState& state) const {
    std::vector<PixelRect> boxes;
    const auto add = [&](const geometry::Shape& shape, const Pose2& pose, double height) {
      std::vector<Vector3f> corners;
      const geometry::Rect b = geometry::bounds(shape, pose);
      for (double z : {0.0, height}) {
        for (const Vec2& c : {b.min, b.max, Vec2(b.min.x(), b.max.y()), Vec2(b.max.x(), b.min.y())}) {
          corners.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(z));
        }
      }
      boxes.push_back(pixel_box(view, corners));
    };
    for (const scenario::FixedBody& body : world.fixed_bodies) add(body.footprint.shape, body.footprint.pose, body.height);
    for (std::size_t i = 0; i < world.movable_bodies.size(); ++i) {
      add(world.movable_bodies[i].footprint.shape, state.movable_poses[i], world.movable_bodies[i].height);
    }
    add(geometry::Shape::circle(world.robot.radius), {state.robot_position, 0.0}, 2 * world.robot.radius);
    return boxes;
  }

  // Each region label's top-left corner in `view` (label_placement.h), or none where it is left out.
  std::vector<std::optional<Eigen::Vector2f>> placed_labels(const CameraView& view, const Overlay& overlay, const PixelRect& legend,
                                                            const scenario::EnvironmentState& state) const {
    const std::vector<PixelRect> extents = label_extents(labels(overlay), world.regions.size());
    std::vector<LabelRequest> requests;
    for (std::size_t r = 0; r < world.regions.size(); ++r) {
      std::vector<Vector3f> corners;
      for (const Vec2& v : world.regions[r].polygon.vertices) corners.emplace_back(static_cast<float>(v.x()), static_cast<float>(v.y()), 0.0f);
      requests.push_back({pixel_box(view, corners), extents[r].max - extents[r].min});
    }
    return place_labels(requests, body_boxes(view, state), legend, Eigen::Vector2f(static_cast<float>(width), static_cast<float>(height)));
  }

  // The colour of movable body `body`: its own when the task wants it somewhere, else the boxes' blue.
  static Color body_color(const Overlay& overlay, int body) {
    std::vector<int> named;
    for (const ObjectGoalOverlay& goal : overlay.object_goals) {
      if (std::find(named.begin(), named.end(), goal.body) == named.end()) named.push_back(goal.body);
    }
    const auto it = std::find(named.begin(), named.end(), body);
    if (it == named.end()) return palette::kMovableBody;
    return palette::kNamedBodies[static_cast<std::size_t>(it - named.begin()) % std::size(palette::kNamedBodies)];
  }

  // The legend's lines as drawn (legend_layout.h): at most a share of the frame's height, each line cut to
  // the frame's width where it keeps its meaning.
  std::string fitted(const std::string& line) const {
    return fitted_line(font, line, static_cast<float>(width) - 2 * kLegendMargin - 2 * kPanelPadding);
  }
  int legend_row_limit() const { return legend_rows(font, height, kLegendMargin + kPanelPadding); }
  std::vector<std::string> legend_lines(const std::vector<std::string>& lines) const {
    std::vector<std::string> shown = shown_lines(lines, legend_row_limit());
    for (std::string& line : shown) line = fitted(line);
    return shown;
  }

  // The panel for `lines`, or for the widest of each row of `room` (the lines a sequence of pictures will
  // show), within the legend's share of the frame.
  PixelRect legend_rect(const std::vector<std::string>& lines, const std::vector<std::vector<std::string>>& room) const {
    if (lines.empty() && room.empty()) return {};
    const auto rows = static_cast<std::size_t>(legend_row_limit());
    float widest = 0;
    for (const std::string& line : legend_lines(lines)) widest = std::max(widest, font.width(line));
    for (std::size_t r = 0; r < std::min(room.size(), rows); ++r) {
      for (const std::string& line : room[r]) widest = std::max(widest, font.width(fitted(line)));
    }
    if (room.size() > rows) widest = std::max(widest, font.width(more_lines(room.size() - (rows - 1))));
    const auto shown_rows = std::min(std::max(lines.size(), room.size()), rows);
    const float h = font.line_height() * static_cast<float>(shown_rows);
    return {{kLegendMargin, kLegendMargin}, {kLegendMargin + widest + 2 * kPanelPadding, kLegendMargin + h + 2 * kPanelPadding}};
  }

  const CameraView& camera(View view_kind, const Overlay& overlay, const scenario::EnvironmentState& state) {
    const PixelRect legend = legend_rect(overlay.legend, overlay.legend_room);
    // An object goal's label is as wide whether it holds or not: the framing depends on which goals there are.
    std::vector<std::pair<int, int>> goals;
    for (const ObjectGoalOverlay& goal : overlay.object_goals) goals.emplace_back(goal.body, goal.region);
    if (!framing || framing->view != view_kind || framing->legend.min != legend.min || framing->legend.max != legend.max ||
        framing->goals != goals) {
      const CameraView view = make_camera_view(world, top_height, view_kind, width, height);
      std::vector<AnchoredRect> places;
      for (const Label& label : labels(overlay)) places.push_back(label.place);
      framing = Framing{view_kind, legend, goals, leave_room_for_legend(view, world_points(), places, legend), {}};
      framing->label_corners = placed_labels(framing->camera, overlay, legend, state);
    }
    return framing->camera;
  }

  // Glyph quads (x y u v per vertex) of one line with its top-left corner at (x, y) in pixels.
  void add_text(const std::string& line, float x, float y, std::vector<float>& glyphs) const {
    for (const GlyphQuad& q : font.layout(line, x, y)) {
      for (int corner : {0, 1, 2, 0, 2, 3}) {
        const bool right = corner == 1 || corner == 2, bottom = corner >= 2;
        glyphs.insert(glyphs.end(), {right ? q.x1 : q.x0, bottom ? q.y1 : q.y0, right ? q.u1 : q.u0,
                                     bottom ? q.v1 : q.v0});
      }
    }
  }

  // Region labels and the legend: light panels into panel_layer, glyph quads into glyph_layer.
  void upload_text(const Overlay& overlay) {
    FlatGeometry panels;
    std::vector<float> glyphs;
    words.labels.clear();
    const std::vector<Label> lines = labels(overlay);
    const std::vector<PixelRect> extents = label_extents(lines, world.regions.size());
    for (const Label& label : lines) {
      const std::optional<Eigen::Vector2f>& corner = framing->label_corners[label.region];
      if (!corner) continue;
      const Eigen::Vector2f min = *corner + label.place.offset.min - extents[label.region].min;
      const Eigen::Vector2f max = *corner + label.place.offset.max - extents[label.region].min;
      panels.rectangle(min.cast<double>(), max.cast<double>(), label.panel);
      add_text(label.text, 0.5f * (min.x() + max.x() - font.width(label.text)), min.y() + kPanelPadding / 2, glyphs);
      words.labels.push_back({label.text, {min.x(), min.y(), max.x(), max.y()}});
    }
    words.legend.clear();
    if (!overlay.legend.empty()) {
      const PixelRect legend = legend_rect(overlay.legend, {});
      panels.rectangle(legend.min.cast<double>(), legend.max.cast<double>(), palette::kPanel);
      words.legend = legend_lines(overlay.legend);
      words.legend_box = {legend.min.x(), legend.min.y(), legend.max.x(), legend.max.y()};
      for (std::size_t i = 0; i < words.legend.size(); ++i) {
        add_text(words.legend[i], kLegendMargin + kPanelPadding,
                 kLegendMargin + kPanelPadding + font.line_height() * static_cast<float>(i), glyphs);
      }
    }
    upload(panel_layer, panels);
    glyph_layer.upload(glyphs.data(), glyphs.size());
  }

  static void upload(GlMesh& layer, const FlatGeometry& geometry) {
    layer.upload(geometry.floats().data(), geometry.floats().size());
  }

  void upload_layers(const scenario::EnvironmentState& state, const Overlay& overlay, const CameraView& view) {
    upload(mregion_layer, mregion_paint(overlay, view.metres_per_pixel, true));
    const std::vector<float> bodies = movable_bodies(state, overlay, true);
    moving_layer.upload(bodies.data(), bodies.size());
    const ShadowGeometry shadow_geometry = movable_shadows(state, true);
    shadow_layer.upload(shadow_geometry.floats().data(), shadow_geometry.floats().size());
    upload_text(overlay);
  }

  // Keeps the resting layer true to `state` and `overlay`: drawn again, without them, when bodies it
  // holds moved or their mRegions changed, and from scratch for another view or other object goals.
  void keep_resting_layer(View view_kind, const CameraView& view, const Overlay& overlay,
                          const scenario::EnvironmentState& state) {
    std::vector<std::pair<int, int>> goals;
    for (const ObjectGoalOverlay& goal : overlay.object_goals) goals.emplace_back(goal.body, goal.region);
    bool redraw = !resting || resting->view != view_kind || resting->view_projection != view.view_projection ||
                  resting->goals != goals || resting->mregions.size() != overlay.mregions.size();
    if (redraw) {
      std::unique_ptr<GlFramebuffer> framebuffer = resting ? std::move(resting->framebuffer) : nullptr;
      resting = RestingLayer{view_kind, view.view_projection, goals, {}, {}, std::vector<bool>(world.movable_bodies.size()),
                             std::move(framebuffer), PixelArea{}};
    } else {
      // A resting body the physics woke moves by rounding errors: what moves less than a hundredth of a
      // pixel is drawn where the layer has it.
      const double still = 0.01 * view.metres_per_pixel;
      for (std::size_t i = 0; i < world.movable_bodies.size(); ++i) {
        const Pose2& was = resting->poses[i], &now = state.movable_poses[i];
        const double reach = world.movable_bodies[i].footprint.shape.bound_radius();
        if (resting->moving[i] || ((was.position - now.position).norm() <= still && std::abs(was.yaw - now.yaw) * reach <= still)) continue;
        resting->moving[i] = redraw = true;
      }
      for (std::size_t k = 0; k < overlay.mregions.size(); ++k) {
        const MRegionOverlay &was = resting->mregions[k], &now = overlay.mregions[k];
        if (now.body < 0 || resting->moving[static_cast<std::size_t>(now.body)] || same_to_the_eye(was, now, still)) continue;
        resting->moving[static_cast<std::size_t>(now.body)] = redraw = true;
      }
    }
    if (!redraw) return;
    try {
      draw_resting_layer(view, overlay, state);
    } catch (...) {
      resting.reset();  // drawn for nothing it could record: drawn from scratch next time
      throw;
    }
    resting->poses = state.movable_poses;
    resting->mregions = overlay.mregions;
  }

  static bool same_to_the_eye(const MRegionOverlay& a, const MRegionOverlay& b, double still) {
    const auto& u = a.polygon.vertices;
    const auto& v = b.polygon.vertices;
    if (a.active != b.active || a.body != b.body || u.size() != v.size()) return false;
    for (std::size_t i = 0; i < u.size(); ++i) {
      if ((u[i] - v[i]).norm() > still) return false;
    }
    return true;
  }

  void draw_resting_layer(const CameraView& view, const Overlay& overlay, const scenario::EnvironmentState& state) {
    upload(resting_mregion_layer, mregion_paint(overlay, view.metres_per_pixel, false));
    const ShadowGeometry shadows = movable_shadows(state, false);
    resting_shadow_layer.upload(shadows.floats().data(), shadows.floats().size(), GL_STATIC_DRAW);
    const std::vector<float> bodies = movable_bodies(state, overlay, false);
    resting_body_layer.upload(bodies.data(), bodies.size(), GL_STATIC_DRAW);
    if (!resting->framebuffer) resting->framebuffer = std::make_unique<GlFramebuffer>(width, height);
    resting->area = resting_area(view, overlay, state);
    const GlFramebuffer& layer = *resting->framebuffer;
    copy_framebuffer(background->framebuffer->id(), width, height, layer.id(), width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, layer.id());
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    // Colour blended as usual but kept premultiplied, alpha accumulated: the layer is "over" its contents.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    draw_movable_things(resting_mregion_layer, resting_shadow_layer, resting_body_layer, view);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }

  // Flat things on the floor, depth tested against the walls and bodies already drawn but never written;
  // then the bodies.
  void draw_movable_things(const GlMesh& mregions, const GlMesh& shadows, const GlMesh& bodies, const CameraView& view) {
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    draw_flat(mregions, view.view_projection);
    draw_shadows(shadows, view);
    glDepthMask(GL_TRUE);
    draw_lit(bodies, view);
    glDisable(GL_DEPTH_TEST);
  }

  // The pixels the resting bodies, their shadows and mRegions may cover (a few pixels more for edges
  // and rounding): a frame lays only that part of the layer, so a world of few bodies pays for few pixels.
  PixelArea resting_area(const CameraView& view, const Overlay& overlay, const scenario::EnvironmentState& state) const {
    Eigen::AlignedBox2f box;
    const auto add = [&](const Vec2& p, double z) {
      box.extend(view.to_pixels(Vector3f(static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(z))));
    };
    for (std::size_t i = 0; i < world.movable_bodies.size(); ++i) {
      if (resting->moving[i]) continue;
      const scenario::MovableBody& body = world.movable_bodies[i];
      const geometry::Rect footprint = geometry::bounds(body.footprint.shape, state.movable_poses[i]);
      const geometry::Rect shadow = ShadowGeometry::reach(footprint, body.height);
      for (const auto& [r, z] : {std::pair{shadow, 0.0}, std::pair{footprint, body.height}}) {
        for (double x : {r.min.x(), r.max.x()}) {
          for (double y : {r.min.y(), r.max.y()}) add({x, y}, z);
        }
      }
    }
    for (const MRegionOverlay& m : overlay.mregions) {
      if (m.body < 0 || resting->moving[static_cast<std::size_t>(m.body)]) continue;
      for (const Vec2& v : m.polygon.vertices) add(v, 0.0);
    }
    if (box.isEmpty()) return {};
    constexpr float kMargin = 4.0f;  // px: edges drawn half their width outside, rounding
    const auto clamp = [](float v, int most) { return std::clamp(static_cast<int>(std::floor(v)), 0, most); };
    // Pixel rows go downwards, OpenGL's upwards.
    return {clamp(box.min().x() - kMargin, width), clamp(static_cast<float>(height) - box.max().y() - kMargin, height),
            clamp(box.max().x() + kMargin + 1, width), clamp(static_cast<float>(height) - box.min().y() + kMargin + 1, height)};
  }

  // The resting layer over the frame, with its depth, where it has something.
  void lay_resting_layer() {
    const PixelArea& area = resting->area;
    if (area.empty()) return;
    const GlFramebuffer& layer = *resting->framebuffer;
    copy_framebuffer_area(layer.id(), frame->id(), area, GL_DEPTH_BUFFER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, frame->id());
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_SCISSOR_TEST);
    glScissor(area.x0, area.y0, area.x1 - area.x0, area.y1 - area.y0);
    layer_program.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, layer.color_texture());
    glUniform1i(layer_program.uniform("layer"), 0);
    frame_quad.draw(GL_TRIANGLE_STRIP);
    glDisable(GL_SCISSOR_TEST);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }

  void draw_shadows(const GlMesh& layer, const CameraView& view) {
    shadow.use();
    glUniformMatrix4fv(shadow.uniform("transform"), 1, GL_FALSE, view.view_projection.data());
    layer.draw(GL_TRIANGLES);
  }

  void draw_lit(const GlMesh& layer, const CameraView& view) {
    lit.use();
    glUniformMatrix4fv(lit.uniform("view_projection"), 1, GL_FALSE, view.view_projection.data());
    const Vector3f light = towards_light();
    glUniform3f(lit.uniform("towards_light"), light.x(), light.y(), light.z());
    layer.draw(GL_TRIANGLES);
  }

  void clear(GLuint framebuffer, int w, int h) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, w, h);
    const Color& bg = palette::kBackground;
    glClearColor(bg.r, bg.g, bg.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }

  // The static scene for `view`, drawn at twice the size in each direction and averaged down; its depth
  // is the fixed bodies' at the picture's own size, so that moving things are hidden exactly where the
  // copied picture shows a wall.
  const GlFramebuffer& static_scene(View view_kind, const CameraView& view, const Overlay& overlay) {
    if (!background || background->view != view_kind || background->view_projection != view.view_projection ||
        background->decomposition != overlay.decomposition ||
        background->segments != overlay.segments || background->avoided_regions != overlay.avoided_regions ||
        !same_goal_places(background->object_goals, overlay.object_goals) ||
        !extends(overlay.path, background->path)) {
      draw_static_scene(view_kind, view, overlay);
    }
    paint_path(overlay.path, view);
    return *background->framebuffer;
  }

  static bool same_goal_places(const std::vector<ObjectGoalOverlay>& a, const std::vector<ObjectGoalOverlay>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const ObjectGoalOverlay& x, const ObjectGoalOverlay& y) { return x.body == y.body && x.region == y.region; });
  }

  static bool extends(const std::vector<Vec2>& path, const std::vector<Vec2>& prefix) {
    return path.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), path.begin());
  }

  // The part of `path` beyond what the background shows: its halo from the last painted point on, then its
  // line from as far back as that halo reaches, so the new halo hides no part of the line already there.
  void paint_path(const std::vector<Vec2>& path, const CameraView& view) {
    std::vector<Vec2>& painted = background->path;
    if (path.size() == painted.size()) return;
    const double halo = kPathHaloWidth * view.metres_per_pixel;
    const std::size_t joint = painted.empty() ? 0 : painted.size() - 1;
    std::size_t covered = joint;
    while (covered > 0 && (path[covered - 1] - path[joint]).norm() < halo) --covered;
    const auto from = [&](std::size_t first) {
      return std::vector<Vec2>(path.begin() + static_cast<std::ptrdiff_t>(first), path.end());
    };
    FlatGeometry paint;
    paint.polyline(from(joint), halo, palette::kPathHalo);
    paint.polyline(from(covered), kPathWidth * view.metres_per_pixel, palette::kPath);
    upload(path_layer, paint);
    glBindFramebuffer(GL_FRAMEBUFFER, background->framebuffer->id());
    glViewport(0, 0, width, height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    draw_flat(path_layer, view.view_projection);
    painted.insert(painted.end(), path.begin() + static_cast<std::ptrdiff_t>(painted.size()), path.end());
  }

  void draw_static_scene(View view_kind, const CameraView& view, const Overlay& overlay) {
    upload(static_floor_layer, floor_paint(overlay, view.metres_per_pixel));
    FlatGeometry segments;
    for (const SegmentOverlay& s : overlay.segments) segments.line(s.from, s.to, kSegmentWidth * view.metres_per_pixel, s.color);
    upload(segment_layer, segments);
    const ShadowGeometry shadows = fixed_shadows();
    static_shadow_layer.upload(shadows.floats().data(), shadows.floats().size(), GL_STATIC_DRAW);

    const GlFramebuffer supersampled(kSupersampling * width, kSupersampling * height);
    clear(supersampled.id(), supersampled.width(), supersampled.height());
    glDisable(GL_DEPTH_TEST);
    draw_flat(static_floor_layer, view.view_projection);
    draw_shadows(static_shadow_layer, view);
    draw_flat(segment_layer, view.view_projection);
    glEnable(GL_DEPTH_TEST);
    draw_lit(fixed_layer, view);

    auto framebuffer = std::make_unique<GlFramebuffer>(width, height);
    clear(framebuffer->id(), width, height);
    draw_lit(fixed_layer, view);  // the depth; its colour is replaced next
    copy_framebuffer(supersampled.id(), supersampled.width(), supersampled.height(), framebuffer->id(), width, height,
                     GL_COLOR_BUFFER_BIT, GL_LINEAR);
    background = Background{view_kind, view.view_projection, overlay.decomposition, overlay.segments, overlay.avoided_regions, overlay.object_goals,
                            std::move(framebuffer), {}};
  }

  Image draw(const scenario::EnvironmentState& state, const Overlay& overlay, View view_kind) {
    if (state.movable_poses.size() != world.movable_bodies.size()) {
      throw std::invalid_argument("render: the state has " + std::to_string(state.movable_poses.size()) +
                                  " movable poses, the world " + std::to_string(world.movable_bodies.size()) +
                                  " movable bodies");
    }
    context->make_current();
    const CameraView& view = camera(view_kind, overlay, state);
    const GlFramebuffer& scene = static_scene(view_kind, view, overlay);
    keep_resting_layer(view_kind, view, overlay, state);
    upload_layers(state, overlay, view);

    if (!frame) frame = std::make_unique<GlFramebuffer>(width, height);
    copy_framebuffer(scene.id(), width, height, frame->id(), width, height, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT,
                     GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, frame->id());
    glViewport(0, 0, width, height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    lay_resting_layer();
    draw_movable_things(mregion_layer, shadow_layer, moving_layer, view);

    const Matrix4f pixels = pixel_transform(width, height);
    draw_flat(panel_layer, pixels);
    text.use();
    glUniformMatrix4fv(text.uniform("transform"), 1, GL_FALSE, pixels.data());
    set_color(text.uniform("color"), palette::kText);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, font_texture);
    glUniform1i(text.uniform("atlas"), 0);
    glyph_layer.draw(GL_TRIANGLES);

    return read_frame();
  }

  // The frame's colour, rows from top to bottom. Read as RGBA, which llvmpipe hands over as it stores it;
  // asking OpenGL for RGB made it convert pixel by pixel at several times the cost.
  Image read_frame() {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, frame->id());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    rgba.resize(static_cast<std::size_t>(width) * height * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    Image image(width, height);
    for (int y = 0; y < height; ++y) {  // OpenGL's rows go upwards
      const std::uint8_t* in = rgba.data() + static_cast<std::size_t>(height - 1 - y) * width * 4;
      strip_alpha(in, image.rgb.data() + static_cast<std::size_t>(y) * width * 3, width);
    }
    return image;
  }
};

Renderer::Renderer(const scenario::World& world, std::unique_ptr<OffscreenContext> context)
    : impl_(std::make_unique<Impl>(world, std::move(context))) {}

Renderer::Renderer(const scenario::World& world, int width, int height)
    : Renderer(world, make_osmesa_context(width, height)) {}

Renderer::~Renderer() = default;

Image Renderer::draw(const scenario::EnvironmentState& state, const Overlay& overlay, View view) {
  return impl_->draw(state, overlay, view);
}

const PictureWords& Renderer::words() const { return impl_->words; }

}  // namespace physltl::render
