#include "physltl/common/statistics.h"

#include <gtest/gtest.h>

namespace physltl::common::statistics {
namespace {

TEST(Statistics, MedianOfOddAndEvenSamplesRegardlessOfOrder) {
  EXPECT_DOUBLE_EQ(median({3, 1, 2}), 2.0);
  EXPECT_DOUBLE_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ(median({7}), 7.0);
}

TEST(Statistics, MeanAndMaximum) {
  EXPECT_DOUBLE_EQ(mean({1, 2, 6}), 3.0);
  EXPECT_DOUBLE_EQ(maximum({1, 9, 6}), 9.0);
}

TEST(Statistics, QuantileInterpolatesBetweenClosestRanks) {
  // Ten values 1..10: rank position 0.9 * 9 = 8.1, between 9 and 10 (numpy: 9.1).
  const std::vector<double> sample = {10, 9, 8, 7, 6, 5, 4, 3, 2, 1};
  EXPECT_DOUBLE_EQ(quantile(sample, 0.9), 9.1);
  EXPECT_DOUBLE_EQ(quantile(sample, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(sample, 1.0), 10.0);
  EXPECT_DOUBLE_EQ(quantile(sample, 0.5), median(sample));
}

TEST(Statistics, EmptySamplesGiveZero) {
  EXPECT_EQ(median({}), 0.0);
  EXPECT_EQ(mean({}), 0.0);
  EXPECT_EQ(quantile({}, 0.9), 0.0);
  EXPECT_EQ(maximum({}), 0.0);
}

TEST(Statistics, FitLineRecoversALineAndReportsTheLargestDeviation) {
  const LineFit exact = fit_line({2, 4, 8, 16}, {1, 2, 4, 8});
  EXPECT_NEAR(exact.slope, 0.5, 1e-12);
  EXPECT_NEAR(exact.intercept, 0.0, 1e-12);
  EXPECT_NEAR(exact.largest_deviation, 0.0, 1e-12);
  // y = 1 + 2x with the third point 0.3 high: the line moves a little towards it.
  const LineFit bent = fit_line({0, 1, 2, 3}, {1, 3, 5.3, 7});
  EXPECT_NEAR(bent.slope, 2.03, 1e-12);
  EXPECT_NEAR(bent.intercept, 1.03, 1e-12);
  EXPECT_NEAR(bent.largest_deviation, 0.21, 1e-12);
}

TEST(Statistics, FitLineThroughOneXIsFlat) {
  const LineFit fit = fit_line({3, 3}, {1, 2});
  EXPECT_EQ(fit.slope, 0.0);
  EXPECT_DOUBLE_EQ(fit.intercept, 1.5);
}

}  // namespace
}  // namespace physltl::common::statistics
