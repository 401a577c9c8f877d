#pragma once
// What the pictures' tests measure of a frame (legend_test.cpp, tests/app/pictures_at_scale_test.cpp): the
// legend's pixels over the world, and how much of the frame the world takes.

#include "physltl/render/image.h"

namespace physltl::render {

struct PictureMeasures {
  int legend_pixels = 0;    // pixels where the picture with the legend differs from the same framing without it
  int legend_over_world = 0;  // of them, pixels where the picture without it shows something of the world
  int world_width = 0, world_height = 0;  // the box of what differs from the background, in pixels
};

// `with_legend` and `room_only` drawn alike but for the legend (room_only: Overlay::legend_room only); the
// background is the colour of the frame's top-left corner in room_only.
PictureMeasures measure_picture(const Image& with_legend, const Image& room_only);

}  // namespace physltl::render
