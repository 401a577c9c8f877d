#pragma once
// Text for labels and the legend: printable ASCII baked from a TrueType font into one coverage bitmap
// (stb_truetype, anti-aliased, deterministic), laid out as textured quads in pixel coordinates.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace physltl::render {

struct GlyphQuad {
  float x0, y0, x1, y1;  // pixels, origin top left, y down
  float u0, v0, u1, v1;  // in the atlas
};

class FontAtlas {
 public:
  // Throws std::runtime_error naming the file when the font cannot be read.
  FontAtlas(const std::string& font_file, float pixel_height);
  ~FontAtlas();
  FontAtlas(const FontAtlas&) = delete;
  FontAtlas& operator=(const FontAtlas&) = delete;

  int atlas_size() const { return kAtlasSize; }
  const std::vector<std::uint8_t>& coverage() const { return coverage_; }  // atlas_size^2 bytes
  float line_height() const { return line_height_; }
  float ascent() const { return ascent_; }

  float width(const std::string& text) const;
  // Quads for `text` with its top-left corner at (x, y); characters outside printable ASCII show as '?'.
  std::vector<GlyphQuad> layout(const std::string& text, float x, float y) const;

 private:
  static constexpr int kAtlasSize = 512;
  static constexpr int kFirst = 32, kCount = 95;
  static int glyph_index(unsigned char c);
  std::vector<std::uint8_t> coverage_;
  struct Glyphs;  // stb_truetype's baked metrics (an anonymous struct there, so not forward-declarable)
  std::unique_ptr<Glyphs> glyphs_;
  float line_height_ = 0;
  float ascent_ = 0;
};

}  // namespace physltl::render
