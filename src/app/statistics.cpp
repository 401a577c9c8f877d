#include "statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace physltl::app::statistics {

double mean(const std::vector<double>& sample) {
  if (sample.empty()) return 0.0;
  return std::accumulate(sample.begin(), sample.end(), 0.0) / static_cast<double>(sample.size());
}

double median(std::vector<double> sample) { return quantile(std::move(sample), 0.5); }

double quantile(std::vector<double> sample, double q) {
  if (sample.empty()) return 0.0;
  std::sort(sample.begin(), sample.end());
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(sample.size() - 1);
  const auto below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(below + 1, sample.size() - 1);
  return sample[below] + (position - static_cast<double>(below)) * (sample[above] - sample[below]);
}

double maximum(const std::vector<double>& sample) {
  return sample.empty() ? 0.0 : *std::max_element(sample.begin(), sample.end());
}

}  // namespace physltl::app::statistics
