#include "text.h"

#include <stb_truetype.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace physltl::render {

struct FontAtlas::Glyphs {
  stbtt_bakedchar baked[kCount];
};

FontAtlas::FontAtlas(const std::string& font_file, float pixel_height)
    : coverage_(kAtlasSize * kAtlasSize), glyphs_(std::make_unique<Glyphs>()) {
  std::ifstream in(font_file, std::ios::binary);
  const std::vector<unsigned char> font((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  stbtt_fontinfo info;
  if (font.empty() || !stbtt_InitFont(&info, font.data(), 0) ||
      stbtt_BakeFontBitmap(font.data(), 0, pixel_height, coverage_.data(), kAtlasSize, kAtlasSize, kFirst, kCount,
                           glyphs_->baked) <= 0) {
    throw std::runtime_error("cannot read font " + font_file + " (Debian: apt-get install fonts-dejavu-core)");
  }
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
  const float scale = stbtt_ScaleForPixelHeight(&info, pixel_height);
  ascent_ = std::ceil(ascent * scale);
  line_height_ = std::ceil((ascent - descent + gap) * scale);
}

FontAtlas::~FontAtlas() = default;

int FontAtlas::glyph_index(unsigned char c) { return (c >= kFirst && c < kFirst + kCount ? c : '?') - kFirst; }

std::vector<GlyphQuad> FontAtlas::layout(const std::string& text, float x, float y) const {
  std::vector<GlyphQuad> quads;
  float pen_x = std::round(x);
  float baseline = std::round(y) + ascent_;
  for (unsigned char c : text) {
    stbtt_aligned_quad q;
    stbtt_GetBakedQuad(glyphs_->baked, kAtlasSize, kAtlasSize, glyph_index(c), &pen_x, &baseline, &q, 1);
    quads.push_back({q.x0, q.y0, q.x1, q.y1, q.s0, q.t0, q.s1, q.t1});
  }
  return quads;
}

float FontAtlas::width(const std::string& text) const {
  float w = 0;
  for (unsigned char c : text) w += glyphs_->baked[glyph_index(c)].xadvance;
  return w;
}

}  // namespace physltl::render
