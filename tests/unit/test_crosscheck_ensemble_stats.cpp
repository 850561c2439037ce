// The cross-check's ensemble arithmetic (crosscheck/ensemble_stats.hpp), on cases worked by
// hand.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/curve_comparison.hpp"  // line_weights
#include "crosscheck/ensemble_runs.hpp"
#include "crosscheck/ensemble_stats.hpp"

namespace {

using crosscheck::compare_linear;
using crosscheck::compare_mean_relative;
using crosscheck::difference_of_means;
using colza::line_weights;
using crosscheck::perturbed_packing;
using crosscheck::SampleSummary;
using crosscheck::summarise;

// 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sum of squares about it 32, sd = sqrt(32 / 7),
// se = sd / sqrt(8) = sqrt(4 / 7).
TEST(CrosscheckEnsembleStats, SummarisesWithTheSampleStandardDeviation) {
  const SampleSummary s = summarise({2, 4, 4, 4, 5, 5, 7, 9});
  EXPECT_EQ(s.n, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_DOUBLE_EQ(s.sd, std::sqrt(32.0 / 7.0));
  EXPECT_DOUBLE_EQ(s.se, std::sqrt(4.0 / 7.0));
  const SampleSummary one = summarise({3.0});
  EXPECT_DOUBLE_EQ(one.mean, 3.0);
  EXPECT_EQ(one.sd, 0.0);
  EXPECT_EQ(one.se, 0.0);
}

// Means 10 and 7, standard errors 3 and 4 of 4 runs each: difference 3, se 5, t 0.6;
// Welch-Satterthwaite df = 25^2 / (9^2 / 3 + 16^2 / 3) = 1875 / 337; p = 2 P(T > 0.6) under
// Student's t with that df = 0.57211 (tests/unit/student_t_reference.py integrates the
// density, independently of Boost, and prints it). With a large df, p tends to the normal
// two-sided value 2 (1 - Phi(0.6)) = 0.548506.
TEST(CrosscheckEnsembleStats, WelchStatisticOfTwoMeans) {
  const SampleSummary colza{4, 10.0, 6.0, 3.0}, yade{4, 7.0, 8.0, 4.0};
  const auto d = difference_of_means(colza, yade);
  EXPECT_DOUBLE_EQ(d.difference, 3.0);
  EXPECT_DOUBLE_EQ(d.se, 5.0);
  EXPECT_DOUBLE_EQ(d.t, 0.6);
  EXPECT_NEAR(d.df, 1875.0 / 337.0, 1e-12);
  EXPECT_NEAR(d.p, 0.57211, 1e-5);
  const SampleSummary big_c{100000, 10.0, 0.0, 3.0}, big_y{100000, 7.0, 0.0, 4.0};
  EXPECT_NEAR(difference_of_means(big_c, big_y).p, 0.548506, 1e-5);
  // Without scatter, equal means pass (t = 0, p = 1) and different ones fail (p = 0).
  const SampleSummary a{2, 1.0, 0.0, 0.0}, b{2, 2.0, 0.0, 0.0};
  EXPECT_EQ(difference_of_means(a, a).t, 0.0);
  EXPECT_EQ(difference_of_means(a, a).p, 1.0);
  EXPECT_TRUE(std::isnan(difference_of_means(a, b).t));
  EXPECT_EQ(difference_of_means(a, b).p, 0.0);
  // One run on a side: nothing to judge by (the row fails).
  const SampleSummary one = summarise({5.0});
  EXPECT_TRUE(std::isnan(difference_of_means(one, summarise({1, 2, 3, 4})).p));
}

// t = 2 with 10 degrees of freedom: two-sided p = 0.073388 (student_t_reference.py, by the
// integral and by the closed form for an even df; tables of Student's t bracket it: the
// two-sided 0.05 critical value at df 10 is 2.228, the 0.10 one 1.812).
TEST(CrosscheckEnsembleStats, TwoSidedPValueOfStudentsT) {
  // Two groups of 11 runs with equal standard errors: df = (2 v)^2 / (2 v^2 / 10) = 20; to get
  // df = 10 use one group without scatter: df = v^2 / (v^2 / 10) = 10.
  const SampleSummary c{11, 2.0, 0.0, 1.0}, y{11, 0.0, 0.0, 0.0};
  const auto d = difference_of_means(c, y);
  EXPECT_DOUBLE_EQ(d.t, 2.0);
  EXPECT_DOUBLE_EQ(d.df, 10.0);
  EXPECT_NEAR(d.p, 0.07339, 1e-5);
}

// Two loads 1 and 3: slope weights (-1/2, 1/2). colza's means 4 and 8 (se 1 and 2), YADE's 4
// and 6 (se 2 and 2): slopes 2 and 1, se sqrt(1/4 + 1) and sqrt(1 + 1); the difference 1 has
// se sqrt(1/4 + 1 + 1 + 1) = sqrt(13) / 2.
TEST(CrosscheckEnsembleStats, PropagatesStandardErrorsThroughALinearCombination) {
  const auto w = line_weights({1.0, 3.0});
  const std::vector<SampleSummary> colza = {{8, 4.0, 0.0, 1.0}, {8, 8.0, 0.0, 2.0}};
  const std::vector<SampleSummary> yade = {{8, 4.0, 0.0, 2.0}, {8, 6.0, 0.0, 2.0}};
  const auto c = compare_linear(w.slope, colza, yade);
  EXPECT_DOUBLE_EQ(c.colza, 2.0);
  EXPECT_DOUBLE_EQ(c.yade, 1.0);
  EXPECT_DOUBLE_EQ(c.colza_se, std::sqrt(1.25));
  EXPECT_DOUBLE_EQ(c.yade_se, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(c.difference.difference, 1.0);
  EXPECT_DOUBLE_EQ(c.difference.se, std::sqrt(13.0) / 2.0);
  // Satterthwaite over the four terms w^2 se^2 = 1/4, 1, 1, 1 of means of 8 runs:
  // df = (13/4)^2 / ((1/16 + 1 + 1 + 1) / 7) = 7 (169/16) / (49/16) = 169/7.
  EXPECT_NEAR(c.difference.df, 169.0 / 7.0, 1e-12);
}

// Two loads: colza's means 11 and 20, YADE's 10 and 25 (se 1 and 2 each, 8 runs): relative
// differences +0.1 and -0.2, mean -0.05; weights 1/20 and 1/50, se = sqrt((1/20)^2 (1 + 1) +
// (1/50)^2 (4 + 4)).
TEST(CrosscheckEnsembleStats, MeanRelativeDifferenceOverTheLoads) {
  const std::vector<SampleSummary> colza = {{8, 11.0, 0.0, 1.0}, {8, 20.0, 0.0, 2.0}};
  const std::vector<SampleSummary> yade = {{8, 10.0, 0.0, 1.0}, {8, 25.0, 0.0, 2.0}};
  const auto r = compare_mean_relative(colza, yade);
  EXPECT_NEAR(r.difference.difference, -0.05, 1e-15);
  EXPECT_NEAR(r.difference.se, std::sqrt(2.0 / 400.0 + 8.0 / 2500.0), 1e-15);
}

// Comments kept, radii unchanged, every coordinate within the amplitude and most of them moved;
// the same seed gives the same text, another seed another.
TEST(CrosscheckEnsembleStats, PerturbsCoordinatesOnlyAndRepeatably) {
  const std::string packing = "# colza packing: x y z r (m), 2 spheres\n0.01 0.02 0.03 0.003\n0.04 0.05 0.06 0.0035\n";
  const double a = 1e-6;
  const std::string p = perturbed_packing(packing, 7, a);
  EXPECT_EQ(p, perturbed_packing(packing, 7, a));
  EXPECT_NE(p, perturbed_packing(packing, 8, a));
  std::istringstream in(p);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "# colza packing: x y z r (m), 2 spheres");
  const double original[2][4] = {{0.01, 0.02, 0.03, 0.003}, {0.04, 0.05, 0.06, 0.0035}};
  int moved = 0;
  for (int k = 0; k < 2; ++k) {
    double v[4];
    in >> v[0] >> v[1] >> v[2] >> v[3];
    for (int d = 0; d < 3; ++d) {
      EXPECT_LE(std::abs(v[d] - original[k][d]), a * (1 + 1e-9));
      moved += v[d] != original[k][d];
    }
    EXPECT_EQ(v[3], original[k][3]);
  }
  EXPECT_EQ(moved, 6);
  EXPECT_THROW(perturbed_packing("0.1 0.2 x\n", 1, a), std::runtime_error);
  EXPECT_THROW(perturbed_packing("0.1 0.2 0.3 0.004 5\n", 1, a), std::runtime_error);
  // Blank and indented comment lines pass through, as colza's reader skips them.
  EXPECT_EQ(perturbed_packing("  # note\n \t\r\n", 1, a), "  # note\n \t\r\n");
}

// An ensemble is judged on all its realisations or none: when a colza realisation fails,
// YADE's runs (the long ones: hours at full size) are not started, and the table says why (a
// walk-through saw YADE run its half of every pair after colza's had failed).
TEST(CrosscheckEnsembleRuns, YadeRunsOnlyWhenEveryColzaRealisationDid) {
  int yade_runs = 0;
  const auto yade = [&] { return ++yade_runs, true; };
  crosscheck::RealisationRuns runs;
  runs.colza = {{"colza-r1", [] { return true; }}, {"colza-r2", [] { return false; }}};
  runs.yade = {{"yade-r1", yade}, {"yade-r2", yade}};
  crosscheck::Report report;
  EXPECT_FALSE(crosscheck::run_realisations(runs, report, "ensemble", 1e-12));
  EXPECT_EQ(yade_runs, 0);
  ASSERT_EQ(report.rows().size(), 2u);
  EXPECT_EQ(report.rows()[0].difference, "colza-r2 failed (colza-r2.failed.log)");
  EXPECT_NE(report.rows()[1].difference.find("YADE's runs not started"), std::string::npos);

  runs.colza[1].run = [] { return true; };
  crosscheck::Report all_ran;
  EXPECT_TRUE(crosscheck::run_realisations(runs, all_ran, "ensemble", 1e-12));
  EXPECT_EQ(yade_runs, 2);
  EXPECT_TRUE(all_ran.rows().empty());
}

}  // namespace
