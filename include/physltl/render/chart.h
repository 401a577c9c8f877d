#pragma once
// Charts for `bench`: box plots of planning time per planner on a log scale with each planner's success,
// and for a sweep the median time against the swept value, one line per planner. Drawn on the CPU with
// the renderer's font, so the same numbers give the same pixels.

#include "physltl/render/image.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace physltl::render {

struct TimeSeries {
  std::string name;
  std::vector<double> times_s;  // per run, unsolved runs at the time limit
  int solved = 0;
};

// One box per planner: quartiles, median, whiskers to the fastest and slowest run, every run as a dot; the
// time limit dashed; "solved k/n" under each name.
Image time_box_plot(const std::string& title, const std::vector<TimeSeries>& planners, double time_limit_s);

struct SweepLine {
  std::string name;
  std::vector<double> medians_s;  // one per swept value
  // One per swept value, or none: the peak memory of a run in a process of its own (0 where unknown).
  std::vector<double> peak_memory_mb;
};

// Median time (log scale) against the swept values (evenly spaced, labelled as given), one line per planner;
// below it, when some line has them, the peak memories (log scale).
Image sweep_chart(const std::string& title, const std::string& key, const std::vector<std::string>& values,
                  const std::vector<SweepLine>& planners);

struct CostCurves {
  std::string name;
  // Per run, its best cost over time: (seconds, cost) steps, the first at 0.
  std::vector<std::vector<std::pair<double, double>>> runs;
};

// The median over each planner's runs of the best cost found by each moment (a run counts with its last cost
// after it ended), one line per planner, on linear axes; `bound` dashed when given (no plan costs less).
Image cost_curves(const std::string& title, const std::vector<CostCurves>& planners, std::optional<double> bound);

// `top` above `bottom`, on white, as wide as the wider.
Image stacked(const Image& top, const Image& bottom);

}  // namespace physltl::render
