#pragma once
// Summary statistics for benchmark figures. Pure functions of a sample; an empty sample gives 0.

#include <vector>

namespace physltl::common::statistics {

double mean(const std::vector<double>& sample);
double median(std::vector<double> sample);
// The q-quantile (q in [0, 1]) by linear interpolation between the closest ranks, as numpy's default
// and R's type 7: quantile(s, 0.5) == median(s), quantile(s, 1) == the maximum.
double quantile(std::vector<double> sample, double q);
double maximum(const std::vector<double>& sample);

// The least-squares line y = intercept + slope * x through the points, and the largest distance of a
// point from it along y. Needs two distinct x; otherwise the slope is 0 and the line passes the mean.
struct LineFit {
  double intercept = 0.0;
  double slope = 0.0;
  double largest_deviation = 0.0;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace physltl::common::statistics
