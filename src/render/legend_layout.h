#pragma once
// The legend's lines as drawn (docs/rendering.md, "The legend"): never taller than a share of the frame,
// and every line as wide as the frame at most, cut where it keeps its meaning.

#include "text.h"

#include <string>
#include <vector>

namespace physltl::render {

// The most of the frame's height the legend's panel takes: the world keeps the rest. In a frame too small
// for that to hold three lines (under about 190 pixels tall), three lines still.
inline constexpr float kLegendHeightShare = 0.3f;
inline constexpr int kLeastLegendRows = 3;

// `line` within `room` pixels: as it is when it fits; else its beginning up to a whole word or sub-formula
// (cut before a space, never inside a name), "...", and the closing brackets the kept part opened, so that
// "task: F(a & F(b & F(c & F d)))" becomes "task: F(a & F(b & ...))" rather than losing its middle.
std::string fitted_line(const FontAtlas& font, const std::string& line, float room);

// At most `rows` of `lines`: all of them when they fit, else the first rows - 1 and more_lines(the rest).
std::vector<std::string> shown_lines(const std::vector<std::string>& lines, int rows);
// The last line of a legend that leaves `hidden` lines out: "... 9 more lines".
std::string more_lines(std::size_t hidden);

// The rows a legend may have in a frame `height` pixels tall with `padding` above and below its lines.
int legend_rows(const FontAtlas& font, int height, float padding);

}  // namespace physltl::render
