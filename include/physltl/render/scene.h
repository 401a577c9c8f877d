#pragma once
// What a picture shows beyond the World and its state, as plain data filled in by the caller: the knowledge
// layer computes mRegions, the planner its tree and path, the app the legend. The renderer draws, nothing more.

#include "physltl/geometry/shapes.h"
#include "physltl/scenario/world.h"

#include <array>
#include <string>
#include <vector>

namespace physltl::render {

using geometry::Vec2;

struct Color {
  float r = 0, g = 0, b = 0, a = 1;  // 0..1, not premultiplied
  friend bool operator==(const Color&, const Color&) = default;
};

// A manipulation region of a movable body; active ones are those the robot may push from now.
struct MRegionOverlay {
  geometry::Polygon polygon;
  bool active = false;
  int body = -1;  // the movable body whose mRegion it is (World order); -1: drawn as if that body moved
};

struct SegmentOverlay {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  Color color;
  friend bool operator==(const SegmentOverlay&, const SegmentOverlay&) = default;
};

// A place the task wants a body in (an object proposition, BODY@REGION): the body is drawn in a colour of
// its own, the region outlined in that colour and labelled "body -> region"; the label turns green while
// the body's centre is in the region.
struct ObjectGoalOverlay {
  int body = 0;    // World::movable_bodies index
  int region = 0;  // World::regions index
  bool holds = false;
  friend bool operator==(const ObjectGoalOverlay&, const ObjectGoalOverlay&) = default;
};

struct Overlay {
  std::vector<MRegionOverlay> mregions;
  // Cells of the workspace decomposition, drawn as faint outlines beneath everything else.
  std::vector<std::array<Vec2, 3>> decomposition;
  // Search-tree edges, on the floor.
  std::vector<SegmentOverlay> segments;
  // The solution path (or the travelled part of it), on the floor above the tree; moving bodies pass over it.
  std::vector<Vec2> path;
  // Regions the task avoids (by name): drawn in a warning colour instead of the goals' yellow.
  std::vector<std::string> avoided_regions;
  std::vector<ObjectGoalOverlay> object_goals;
  // Lines of text in the top-left corner: formula, automaton state, time, ... The camera leaves room for
  // them: nothing of the world is drawn under the legend. A line wider than the picture is shortened in
  // its middle ("...").
  std::vector<std::string> legend;
  // For each row of the legend, every line it shows in the pictures of one sequence (the times, regions and
  // automaton states of a video): room is left for the widest of them, so every frame is framed alike.
  std::vector<std::vector<std::string>> legend_room;
};

// A rectangle of a picture in pixels, origin top left, y down.
struct PixelBox {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
struct PlacedLabel {
  std::string text;
  PixelBox box;  // its panel
};
// What a picture says in words: the legend's lines as drawn (cut to fit) and its panel, and each label
// line drawn with its panel; a region label left out for want of room is not among them.
struct PictureWords {
  std::vector<std::string> legend;
  PixelBox legend_box;
  std::vector<PlacedLabel> labels;
};

// kPerspective: the 3/4 view of World::render.camera; kTop: orthographic from above, fitted to the workspace.
using View = scenario::RenderView;

}  // namespace physltl::render
