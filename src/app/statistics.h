#pragma once
// Summary statistics for benchmark figures. Pure functions of a sample; an empty sample gives 0.

#include <vector>

namespace physltl::app::statistics {

double mean(const std::vector<double>& sample);
double median(std::vector<double> sample);
// The q-quantile (q in [0, 1]) by linear interpolation between the closest ranks, as numpy's default
// and R's type 7: quantile(s, 0.5) == median(s), quantile(s, 1) == the maximum.
double quantile(std::vector<double> sample, double q);
double maximum(const std::vector<double>& sample);

}  // namespace physltl::app::statistics
