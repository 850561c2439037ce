// Comparing two codes on a chaotic problem by ensembles: each code runs several independent
// realisations (the same sample with every coordinate moved by a tiny random amount, so that
// chaos makes each run another realisation), and the means are compared against their
// standard errors by Welch's t test (crosscheck/README.md, "Ensembles").
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace crosscheck {

// n values: mean, sample standard deviation sd (n - 1 in the denominator; 0 for n < 2) and
// standard error of the mean se = sd / sqrt(n).
struct SampleSummary {
  std::size_t n = 0;
  double mean = 0.0, sd = 0.0, se = 0.0;
};
SampleSummary summarise(const std::vector<double>& values);

// An estimated difference d of the two codes with its standard error se, the
// Welch-Satterthwaite degrees of freedom df, t = d / se and the two-sided p-value of t under
// Student's t with df degrees of freedom (the probability of |t| at least this large if the
// codes agree). With se = 0: t = 0 and p = 1 when d = 0, else t = NaN and p = 0. A mean of
// fewer than two runs cannot be judged: t and p are NaN.
struct MeanDifference {
  double difference = 0.0, se = 0.0, df = 0.0, t = 0.0, p = 1.0;
};
MeanDifference difference_of_means(const SampleSummary& colza, const SampleSummary& yade);

// A linear combination sum_k w_k mean_k of per-load means, for each code (with w the weights
// of a least-squares line's intercept or slope, line_weights in analysis/curve_comparison.hpp: the
// Mohr-Coulomb C or tan(Phi) of the mean strengths), and the difference of the codes'
// combinations, its standard error (se^2 = sum_k w_k^2 (se_colza,k^2 + se_yade,k^2), every
// run independent) and Welch-Satterthwaite degrees of freedom over the 2 K variance terms.
struct LinearComparison {
  double colza = 0.0, yade = 0.0, colza_se = 0.0, yade_se = 0.0;
  MeanDifference difference;
};
LinearComparison compare_linear(const std::vector<double>& weights, const std::vector<SampleSummary>& colza,
                                const std::vector<SampleSummary>& yade);

// The mean over the loads of the relative difference (mean_colza,k - mean_yade,k) /
// mean_yade,k: compare_linear with weights 1 / (K mean_yade,k) (YADE's means taken as fixed
// denominators), so its difference is the pooled relative difference.
LinearComparison compare_mean_relative(const std::vector<SampleSummary>& colza, const std::vector<SampleSummary>& yade);

// A packing file's text ("x y z r" per line; blank lines and lines whose first non-blank
// character is '#' are kept as they are, as colza's reader skips them) with every coordinate
// moved by an independent uniform random amount in [-amplitude, amplitude] (m); radii
// unchanged, numbers written with 17 significant digits. The same seed gives the same file on
// every machine (splitmix64, no standard-library distribution). Throws std::runtime_error
// naming the line if a line does not hold exactly four numbers.
std::string perturbed_packing(const std::string& text, std::uint64_t seed, double amplitude);

}  // namespace crosscheck
