// bench.png and sweep.png: the charts bench draws, against goldens, and what a reader needs from them.

#include "golden_image.h"
#include "physltl/render/chart.h"

#include <gtest/gtest.h>

namespace physltl::render {
namespace {

const std::vector<TimeSeries> kPlanners = {
    {"knowledge", {0.017, 0.02, 0.025, 0.019, 0.03}, 5},
    {"ompl-ltl", {0.6, 0.9, 1.4, 0.55, 10.0}, 4},  // one run unsolved, at the time limit
    {"ompl-rrt", {0.08, 0.11, 0.07, 0.09, 0.1}, 5},
};

TEST(ChartGolden, TimeBoxPlot) {
  EXPECT_TRUE(matches_golden(time_box_plot("ordered: time to the first validated plan", kPlanners, 10.0), "chart_box_plot"));
}

TEST(ChartGolden, SweepChart) {
  const Image image = sweep_chart("rooms_n: median time against rooms", "rooms", {"2", "4", "8", "16"},
                                  {{"knowledge", {0.026, 0.07, 0.23, 0.6}, {}}, {"baseline", {0.05, 0.2, 0.9, 3.1}, {}}});
  EXPECT_TRUE(matches_golden(image, "chart_sweep"));
}

// With peak memories, a second panel below; a value whose run found no plan (0) is left out of its line.
TEST(ChartGolden, SweepChartWithPeakMemory) {
  const Image image = sweep_chart("warehouse: median time against boxes", "boxes", {"200", "800", "3200"},
                                  {{"knowledge", {0.02, 0.08, 0.5}, {69.0, 77.6, 143.5}}, {"baseline", {0.05, 0.4, 4.0}, {70.0, 0.0, 160.0}}});
  EXPECT_TRUE(matches_golden(image, "chart_sweep_memory"));
}

// Improving planners' best cost over time, with the bound dashed below: a median of runs, each a step
// function that never rises.
TEST(ChartGolden, CostCurves) {
  const Image image = cost_curves("rooms: best cost (time) while improving, median of solved runs",
                                  {{"knowledge", {{{0, 36.5}, {0.02, 34.7}, {0.05, 32.5}}, {{0, 38.0}, {0.01, 35.5}}, {{0, 38.1}}}},
                                   {"baseline", {{{0, 61.8}, {0.03, 50.2}, {0.06, 47.0}}}}},
                                  24.53);
  EXPECT_TRUE(matches_golden(image, "chart_cost_curves"));
}

TEST(Chart, TwoChartsStackOneAboveTheOther) {
  const Image box = time_box_plot("t", kPlanners, 10.0);
  const Image curves = cost_curves("c", {{"knowledge", {{{0, 2.0}, {1.0, 1.0}}}}}, std::nullopt);
  const Image both = stacked(box, curves);
  EXPECT_EQ(both.width, std::max(box.width, curves.width));
  EXPECT_EQ(both.height, box.height + curves.height);
  EXPECT_TRUE(std::equal(box.rgb.begin(), box.rgb.begin() + box.width * 3, both.rgb.begin()));  // the first row
}

TEST(Chart, ABoxPlotWidensWithEachPlannerAndDrawsTheSameForTheSameNumbers) {
  const Image one = time_box_plot("t", {kPlanners[0]}, 10.0);
  const Image three = time_box_plot("t", kPlanners, 10.0);
  EXPECT_EQ(three.width - one.width, 2 * 120);
  EXPECT_EQ(time_box_plot("t", kPlanners, 10.0).rgb, three.rgb);
}

}  // namespace
}  // namespace physltl::render
