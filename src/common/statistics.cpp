#include "physltl/common/statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace physltl::common::statistics {

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

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit fit;
  const size_t n = std::min(x.size(), y.size());
  if (n == 0) return fit;
  const std::vector<double> xs(x.begin(), x.begin() + static_cast<long>(n)), ys(y.begin(), y.begin() + static_cast<long>(n));
  const double mx = mean(xs), my = mean(ys);
  double sxx = 0.0, sxy = 0.0;
  for (size_t i = 0; i < n; ++i) sxx += (xs[i] - mx) * (xs[i] - mx), sxy += (xs[i] - mx) * (ys[i] - my);
  fit.slope = sxx > 0.0 ? sxy / sxx : 0.0;
  fit.intercept = my - fit.slope * mx;
  for (size_t i = 0; i < n; ++i) {
    fit.largest_deviation = std::max(fit.largest_deviation, std::abs(ys[i] - (fit.intercept + fit.slope * xs[i])));
  }
  return fit;
}

}  // namespace physltl::common::statistics
