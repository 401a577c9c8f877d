#include "physltl/render/chart.h"

#include "text.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace physltl::render {
namespace {

using Colour = std::array<std::uint8_t, 3>;
constexpr Colour kInk{40, 40, 40};
constexpr Colour kGrid{225, 225, 225};
constexpr Colour kLimit{200, 60, 60};
// Planners in turn: blue, orange, green, purple, brown, pink, grey, olive (colour-blind safe enough).
constexpr std::array<Colour, 8> kSeries{{{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {148, 103, 189},
                                         {140, 86, 75}, {227, 119, 194}, {127, 127, 127}, {188, 189, 34}}};
constexpr float kFontPixels = 13.0f;

class Canvas {
 public:
  Canvas(int width, int height) : image_(width, height), font_(PHYSLTL_FONT_FILE, kFontPixels) {
    std::fill(image_.rgb.begin(), image_.rgb.end(), std::uint8_t{255});
  }

  void blend(int x, int y, const Colour& c, float alpha = 1.0f) {
    if (x < 0 || y < 0 || x >= image_.width || y >= image_.height) return;
    std::uint8_t* p = &image_.rgb[(static_cast<std::size_t>(y) * image_.width + x) * 3];
    for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::lround(p[k] + alpha * (c[k] - p[k])));
  }
  void rect(int x0, int y0, int x1, int y1, const Colour& c, float alpha = 1.0f) {
    for (int y = std::min(y0, y1); y <= std::max(y0, y1); ++y) {
      for (int x = std::min(x0, x1); x <= std::max(x0, x1); ++x) blend(x, y, c, alpha);
    }
  }
  void outline(int x0, int y0, int x1, int y1, const Colour& c) {
    rect(x0, y0, x1, y0, c), rect(x0, y1, x1, y1, c), rect(x0, y0, x0, y1, c), rect(x1, y0, x1, y1, c);
  }
  // A line two pixels wide, `dash` pixels on and off (0: solid).
  void line(double x0, double y0, double x1, double y1, const Colour& c, int dash = 0) {
    const int steps = static_cast<int>(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
    for (int i = 0; i <= steps; ++i) {
      if (dash > 0 && (i / dash) % 2 == 1) continue;
      const double t = static_cast<double>(i) / steps;
      const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0))), y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
      rect(x, y, x + 1, y + 1, c);
    }
  }
  void dot(double x, double y, int radius, const Colour& c, float alpha = 1.0f) {
    for (int dy = -radius; dy <= radius; ++dy) {
      for (int dx = -radius; dx <= radius; ++dx) {
        if (dx * dx + dy * dy <= radius * radius) blend(static_cast<int>(std::lround(x)) + dx, static_cast<int>(std::lround(y)) + dy, c, alpha);
      }
    }
  }
  float text_width(const std::string& s) const { return font_.width(s); }
  // `align`: 0 left, 0.5 centred, 1 right of x; y is the top of the line.
  void text(const std::string& s, double x, double y, const Colour& c, double align = 0.0) {
    const auto& coverage = font_.coverage();
    const int size = font_.atlas_size();
    for (const GlyphQuad& q : font_.layout(s, static_cast<float>(x - align * font_.width(s)), static_cast<float>(y))) {
      for (int py = static_cast<int>(std::floor(q.y0)); py < static_cast<int>(std::ceil(q.y1)); ++py) {
        for (int px = static_cast<int>(std::floor(q.x0)); px < static_cast<int>(std::ceil(q.x1)); ++px) {
          const float u = q.u0 + (px + 0.5f - q.x0) / (q.x1 - q.x0) * (q.u1 - q.u0);
          const float v = q.v0 + (py + 0.5f - q.y0) / (q.y1 - q.y0) * (q.v1 - q.v0);
          const int ax = std::clamp(static_cast<int>(u * size), 0, size - 1), ay = std::clamp(static_cast<int>(v * size), 0, size - 1);
          blend(px, py, c, coverage[static_cast<std::size_t>(ay) * size + ax] / 255.0f);
        }
      }
    }
  }
  float line_height() const { return font_.line_height(); }
  Image take() { return std::move(image_); }

 private:
  Image image_;
  FontAtlas font_;
};

// A logarithmic axis (of times, or of memory) from the decade below the least value to the decade above
// the greatest.
struct LogAxis {
  double low_decade, high_decade;  // log10 of the ends
  double top, bottom;              // pixels
  double y(double value) const {
    const double l = std::log10(std::max(value, 1e-9));
    return bottom - (l - low_decade) / (high_decade - low_decade) * (bottom - top);
  }
};

LogAxis log_axis(double low, double high, double top, double bottom) {
  low = std::max(low, 1e-6);
  high = std::max(high, low * 1.0001);
  return {std::floor(std::log10(low)), std::ceil(std::log10(high)), top, bottom};
}

std::string decade_label(double decade, const char* unit) {
  char text[32];
  const double v = std::pow(10.0, decade);
  std::snprintf(text, sizeof text, v >= 1.0 ? "%.0f %s" : "%g %s", v, unit);
  return text;
}

void draw_log_axis(Canvas& canvas, const LogAxis& axis, int left, int right, const char* unit) {
  for (double d = axis.low_decade; d <= axis.high_decade + 1e-9; ++d) {
    const double y = axis.y(std::pow(10.0, d));
    canvas.rect(left, static_cast<int>(y), right, static_cast<int>(y), kGrid);
    canvas.text(decade_label(d, unit), left - 6, y - canvas.line_height() / 2, kInk, 1.0);
  }
  canvas.rect(left, static_cast<int>(axis.top), left, static_cast<int>(axis.bottom), kInk);
}

void draw_time_axis(Canvas& canvas, const LogAxis& axis, int left, int right) { draw_log_axis(canvas, axis, left, right, "s"); }

// One line per planner through its values (those above 0) at x_of(k), on `axis`.
template <typename XOf>
void draw_sweep_lines(Canvas& canvas, const LogAxis& axis, const std::vector<SweepLine>& planners,
                      std::vector<double> SweepLine::*values, const XOf& x_of) {
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const Colour& c = kSeries[i % kSeries.size()];
    const std::vector<double>& m = planners[i].*values;
    for (std::size_t k = 0; k < m.size(); ++k) {
      if (m[k] <= 0.0) continue;
      if (k > 0 && m[k - 1] > 0.0) canvas.line(x_of(k - 1), axis.y(m[k - 1]), x_of(k), axis.y(m[k]), c);
      canvas.dot(x_of(k), axis.y(m[k]), 4, c);
    }
  }
}

// A linear axis from `low` to `high` (pixels from `first` to `last`), with about five round ticks.
struct LinearAxis {
  double low, high, first, last;
  double at(double value) const { return first + (value - low) / (high - low) * (last - first); }
  std::vector<double> ticks() const {
    const double raw = (high - low) / 5.0, decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / decade < 2 ? 2 * decade : raw / decade < 5 ? 5 * decade : 10 * decade;
    std::vector<double> ticks;
    for (double t = std::ceil(low / step) * step; t <= high + 1e-9 * step; t += step) ticks.push_back(t);
    return ticks;
  }
};

// The value at time t of a run's steps: its last step at or before t.
double step_value(const std::vector<std::pair<double, double>>& steps, double t) {
  double value = steps.front().second;
  for (const auto& [time, cost] : steps) {
    if (time > t) break;
    value = cost;
  }
  return value;
}

double quantile(std::vector<double> sorted, double q) {
  std::sort(sorted.begin(), sorted.end());
  const double rank = q * (static_cast<double>(sorted.size()) - 1);
  const auto lo = static_cast<std::size_t>(std::floor(rank)), hi = static_cast<std::size_t>(std::ceil(rank));
  return sorted[lo] + (rank - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

}  // namespace

Image time_box_plot(const std::string& title, const std::vector<TimeSeries>& planners, double time_limit_s) {
  constexpr int kColumn = 120, kLeft = 70, kTop = 40, kPlotHeight = 360;
  const int width = kLeft + kColumn * static_cast<int>(std::max<std::size_t>(planners.size(), 1)) + 20;
  Canvas canvas(width, kTop + kPlotHeight + 60);
  canvas.text(title, width / 2.0, 10, kInk, 0.5);
  double low = time_limit_s, high = time_limit_s;
  for (const auto& p : planners) {
    for (double t : p.times_s) low = std::min(low, t), high = std::max(high, t);
  }
  const LogAxis axis = log_axis(low, high, kTop, kTop + kPlotHeight);
  draw_time_axis(canvas, axis, kLeft, width - 20);
  canvas.line(kLeft, axis.y(time_limit_s), width - 20, axis.y(time_limit_s), kLimit, 6);
  canvas.text("time limit", width - 22, axis.y(time_limit_s) - canvas.line_height() - 1, kLimit, 1.0);
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const auto& p = planners[i];
    const Colour& c = kSeries[i % kSeries.size()];
    const double centre = kLeft + kColumn * (i + 0.5);
    if (!p.times_s.empty()) {
      const double q1 = axis.y(quantile(p.times_s, 0.25)), q3 = axis.y(quantile(p.times_s, 0.75));
      const double median = axis.y(quantile(p.times_s, 0.5));
      const auto [fastest, slowest] = std::minmax_element(p.times_s.begin(), p.times_s.end());
      canvas.line(centre, axis.y(*fastest), centre, axis.y(*slowest), kInk);
      canvas.rect(static_cast<int>(centre - 25), static_cast<int>(q3), static_cast<int>(centre + 25), static_cast<int>(q1), c, 0.35f);
      canvas.outline(static_cast<int>(centre - 25), static_cast<int>(q3), static_cast<int>(centre + 25), static_cast<int>(q1), c);
      canvas.rect(static_cast<int>(centre - 25), static_cast<int>(median) - 1, static_cast<int>(centre + 25), static_cast<int>(median) + 1, kInk);
      for (std::size_t k = 0; k < p.times_s.size(); ++k) {
        const double jitter = (static_cast<double>(k % 7) - 3.0) * 4.0;  // runs side by side, not on top
        canvas.dot(centre + 35 + jitter / 2, axis.y(p.times_s[k]), 2, c, 0.8f);
      }
    }
    canvas.text(p.name, centre, kTop + kPlotHeight + 8, kInk, 0.5);
    canvas.text("solved " + std::to_string(p.solved) + "/" + std::to_string(p.times_s.size()), centre,
                kTop + kPlotHeight + 8 + canvas.line_height(), c, 0.5);
  }
  return canvas.take();
}

Image cost_curves(const std::string& title, const std::vector<CostCurves>& planners, std::optional<double> bound) {
  constexpr int kWidth = 640, kLeft = 70, kRight = 160, kTop = 40, kPlotHeight = 260, kSamples = 200;
  double end = 0.0, low = bound.value_or(1e300), high = 0.0;
  for (const auto& p : planners) {
    for (const auto& run : p.runs) {
      for (const auto& [time, cost] : run) end = std::max(end, time), low = std::min(low, cost), high = std::max(high, cost);
    }
  }
  Canvas canvas(kWidth, kTop + kPlotHeight + 60);
  canvas.text(title, kWidth / 2.0, 10, kInk, 0.5);
  if (high <= 0.0) return canvas.take();
  if (high - low < 1e-9) low -= 0.5, high += 0.5;
  end = std::max(end, 1e-3);
  const LinearAxis x{0.0, end, kLeft, kWidth - kRight}, y{low - 0.05 * (high - low), high + 0.05 * (high - low), kTop + kPlotHeight, kTop};
  for (double t : y.ticks()) {
    canvas.rect(kLeft, static_cast<int>(y.at(t)), kWidth - kRight, static_cast<int>(y.at(t)), kGrid);
    canvas.text(fmt::format("{:g}", t), kLeft - 6, y.at(t) - canvas.line_height() / 2, kInk, 1.0);
  }
  for (double t : x.ticks()) canvas.text(fmt::format("{:g} s", t), x.at(t), kTop + kPlotHeight + 8, kInk, 0.5);
  canvas.text("seconds after the first plan", (kLeft + kWidth - kRight) / 2.0, kTop + kPlotHeight + 8 + canvas.line_height(), kInk, 0.5);
  canvas.rect(kLeft, kTop, kLeft, kTop + kPlotHeight, kInk);
  if (bound) {
    canvas.line(kLeft, y.at(*bound), kWidth - kRight, y.at(*bound), kLimit, 6);
    canvas.text("bound", kWidth - kRight + 4, y.at(*bound) - canvas.line_height() / 2, kLimit);
  }
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const Colour& c = kSeries[i % kSeries.size()];
    if (planners[i].runs.empty()) continue;
    double last_y = 0.0;
    for (int k = 0; k <= kSamples; ++k) {
      const double t = end * k / kSamples;
      std::vector<double> costs;
      for (const auto& run : planners[i].runs) costs.push_back(step_value(run, t));
      const double value = y.at(quantile(costs, 0.5));
      if (k > 0) canvas.line(x.at(end * (k - 1) / kSamples), last_y, x.at(t), value, c);
      last_y = value;
    }
    canvas.text(planners[i].name, kWidth - kRight + 4, last_y - canvas.line_height() / 2, c);
  }
  return canvas.take();
}

Image stacked(const Image& top, const Image& bottom) {
  Image both(std::max(top.width, bottom.width), top.height + bottom.height);
  std::fill(both.rgb.begin(), both.rgb.end(), std::uint8_t{255});
  const auto copy = [&](const Image& part, int y0) {
    for (int y = 0; y < part.height; ++y) {
      std::copy_n(&part.rgb[static_cast<std::size_t>(y) * part.width * 3], static_cast<std::size_t>(part.width) * 3,
                  &both.rgb[(static_cast<std::size_t>(y0 + y) * both.width) * 3]);
    }
  };
  copy(top, 0);
  copy(bottom, top.height);
  return both;
}

Image sweep_chart(const std::string& title, const std::string& key, const std::vector<std::string>& values,
                  const std::vector<SweepLine>& planners) {
  constexpr int kWidth = 640, kLeft = 70, kRight = 160, kTop = 40, kPlotHeight = 340, kMemoryHeight = 200;
  double memory_low = 1e300, memory_high = 0;
  for (const auto& p : planners) {
    for (double m : p.peak_memory_mb) {
      if (m > 0.0) memory_low = std::min(memory_low, m), memory_high = std::max(memory_high, m);
    }
  }
  const bool memory = memory_high > 0.0;
  const int memory_top = kTop + kPlotHeight + 60 + 30;
  Canvas canvas(kWidth, memory ? memory_top + kMemoryHeight + 40 : kTop + kPlotHeight + 60);
  canvas.text(title, kWidth / 2.0, 10, kInk, 0.5);
  double low = 1e300, high = 0;
  for (const auto& p : planners) {
    for (double m : p.medians_s) low = std::min(low, m), high = std::max(high, m);
  }
  const LogAxis axis = log_axis(low > high ? 1e-3 : low, low > high ? 1.0 : high, kTop, kTop + kPlotHeight);
  draw_time_axis(canvas, axis, kLeft, kWidth - kRight);
  const auto x_of = [&](std::size_t k) {
    return values.size() < 2 ? (kLeft + kWidth - kRight) / 2.0
                             : kLeft + 30 + (kWidth - kRight - kLeft - 60) * static_cast<double>(k) / (values.size() - 1);
  };
  for (std::size_t k = 0; k < values.size(); ++k) canvas.text(values[k], x_of(k), kTop + kPlotHeight + 8, kInk, 0.5);
  canvas.text(key + " (median time of each value)", (kLeft + kWidth - kRight) / 2.0, kTop + kPlotHeight + 8 + canvas.line_height(), kInk, 0.5);
  draw_sweep_lines(canvas, axis, planners, &SweepLine::medians_s, x_of);
  if (memory) {
    canvas.text("peak memory of a run in a process of its own", kWidth / 2.0, memory_top - 24, kInk, 0.5);
    const LogAxis memory_axis = log_axis(memory_low, memory_high, memory_top, memory_top + kMemoryHeight);
    draw_log_axis(canvas, memory_axis, kLeft, kWidth - kRight, "MB");
    for (std::size_t k = 0; k < values.size(); ++k) canvas.text(values[k], x_of(k), memory_top + kMemoryHeight + 8, kInk, 0.5);
    draw_sweep_lines(canvas, memory_axis, planners, &SweepLine::peak_memory_mb, x_of);
  }
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const Colour& c = kSeries[i % kSeries.size()];
    const double legend_y = kTop + 10 + i * (canvas.line_height() + 4);
    canvas.rect(kWidth - kRight + 14, static_cast<int>(legend_y + 4), kWidth - kRight + 28, static_cast<int>(legend_y + 10), c);
    canvas.text(planners[i].name, kWidth - kRight + 34, legend_y, kInk);
  }
  return canvas.take();
}

}  // namespace physltl::render
