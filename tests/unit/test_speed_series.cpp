// How features move with speed (analysis/speed_series.hpp), on features with closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/speed_series.hpp"

using namespace colza;

// f(v) = 3 + 2 log10(v / 0.001) at three speeds spanning two decades: the least-squares slope
// per decade is exactly 2, and the change from the slowest to the fastest is (7 - 3) / 3.
TEST(SpeedSeries, AFeatureLinearInTheLogarithmOfSpeedHasItsSlopePerDecade) {
  const std::vector<double> speeds{0.1, 0.001, 0.01};  // any order
  std::vector<std::map<std::string, double>> features;
  for (double v : speeds) features.push_back({{"f", 3.0 + 2.0 * std::log10(v / 0.001)}, {"flat", 5.0}});
  const std::vector<SpeedTrend> t = speed_trends(speeds, features);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].feature, "f");
  EXPECT_NEAR(t[0].per_decade, 2.0, 1e-12);
  EXPECT_NEAR(t[0].relative_change, 4.0 / 3.0, 1e-12);
  EXPECT_EQ(t[0].values.size(), 3u);
  EXPECT_EQ(t[1].feature, "flat");
  EXPECT_EQ(t[1].per_decade, 0.0);
  EXPECT_EQ(t[1].relative_change, 0.0);
}

TEST(SpeedSeries, AFeatureMissingAtOneSpeedIsLeftOutAndAZeroBaseHasNoRelativeChange) {
  const std::vector<double> speeds{0.001, 0.01};
  const std::vector<std::map<std::string, double>> features{{{"a", 0.0}, {"b", 1.0}}, {{"a", 1.0}}};
  const std::vector<SpeedTrend> t = speed_trends(speeds, features);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].feature, "a");
  EXPECT_NEAR(t[0].per_decade, 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(t[0].relative_change));
}

TEST(SpeedSeries, FewerThanTwoOrRepeatedOrNonPositiveSpeedsAreRefused) {
  const std::map<std::string, double> f{{"a", 1.0}};
  EXPECT_THROW(speed_trends({0.01}, {f}), std::invalid_argument);
  EXPECT_THROW(speed_trends({0.01, 0.01}, {f, f}), std::invalid_argument);
  EXPECT_THROW(speed_trends({0.0, 0.01}, {f, f}), std::invalid_argument);
  EXPECT_THROW(speed_trends({0.01, 0.1}, {f}), std::invalid_argument);
}
