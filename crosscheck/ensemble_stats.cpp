#include "ensemble_stats.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace crosscheck {

SampleSummary summarise(const std::vector<double>& values) {
  SampleSummary s;
  s.n = values.size();
  if (s.n == 0) return s;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n < 2) return s;
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(squares / static_cast<double>(s.n - 1));
  s.se = s.sd / std::sqrt(static_cast<double>(s.n));
  return s;
}

namespace {

// One variance term of a Welch-Satterthwaite sum: w^2 se^2 of a mean of n runs.
struct VarianceTerm {
  double variance;  // w^2 se^2
  std::size_t n;
};

// d with the variance terms of its independent parts: se, df = (sum v)^2 / sum v^2 / (n - 1)
// (Welch 1947, Satterthwaite 1946), t and the two-sided p-value.
MeanDifference difference_with(double difference, const std::vector<VarianceTerm>& terms) {
  double variance = 0.0, df_denominator = 0.0;
  bool testable = true;  // a mean of one run has no standard error to judge by
  for (const VarianceTerm& v : terms) {
    variance += v.variance;
    if (v.n > 1) df_denominator += v.variance * v.variance / static_cast<double>(v.n - 1);
    else testable = false;
  }
  MeanDifference d;
  d.difference = difference;
  d.se = std::sqrt(variance);
  if (!testable) {
    d.t = d.p = std::numeric_limits<double>::quiet_NaN();
    return d;
  }
  if (d.se == 0.0) {
    d.t = difference == 0.0 ? 0.0 : std::numeric_limits<double>::quiet_NaN();
    d.p = difference == 0.0 ? 1.0 : 0.0;
    return d;
  }
  d.df = df_denominator > 0.0 ? variance * variance / df_denominator : 0.0;
  d.t = difference / d.se;
  if (!(d.df > 0.0) || !std::isfinite(d.t)) {
    d.p = std::numeric_limits<double>::quiet_NaN();
    return d;
  }
  const boost::math::students_t student(d.df);
  d.p = 2.0 * boost::math::cdf(boost::math::complement(student, std::abs(d.t)));
  return d;
}

}  // namespace

MeanDifference difference_of_means(const SampleSummary& colza, const SampleSummary& yade) {
  return difference_with(colza.mean - yade.mean,
                         {{colza.se * colza.se, colza.n}, {yade.se * yade.se, yade.n}});
}

LinearComparison compare_linear(const std::vector<double>& weights, const std::vector<SampleSummary>& colza,
                                const std::vector<SampleSummary>& yade) {
  LinearComparison c;
  double var_colza = 0.0, var_yade = 0.0;
  std::vector<VarianceTerm> terms;
  for (std::size_t k = 0; k < weights.size(); ++k) {
    const double w2 = weights[k] * weights[k];
    c.colza += weights[k] * colza[k].mean;
    c.yade += weights[k] * yade[k].mean;
    var_colza += w2 * colza[k].se * colza[k].se;
    var_yade += w2 * yade[k].se * yade[k].se;
    terms.push_back({w2 * colza[k].se * colza[k].se, colza[k].n});
    terms.push_back({w2 * yade[k].se * yade[k].se, yade[k].n});
  }
  c.colza_se = std::sqrt(var_colza);
  c.yade_se = std::sqrt(var_yade);
  c.difference = difference_with(c.colza - c.yade, terms);
  return c;
}

LinearComparison compare_mean_relative(const std::vector<SampleSummary>& colza, const std::vector<SampleSummary>& yade) {
  std::vector<double> weights;
  for (const SampleSummary& y : yade) weights.push_back(1.0 / (static_cast<double>(yade.size()) * y.mean));
  return compare_linear(weights, colza, yade);
}

namespace {

// splitmix64 (Steele, Lea and Flood 2014): a fixed sequence of 64-bit numbers per seed.
std::uint64_t next_random(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Uniform in [-1, 1): the top 53 bits as a fraction of 2^53, doubled and shifted.
double symmetric_unit(std::uint64_t& state) { return 2.0 * std::ldexp(static_cast<double>(next_random(state) >> 11), -53) - 1.0; }

}  // namespace

std::string perturbed_packing(const std::string& text, std::uint64_t seed, double amplitude) {
  std::istringstream in(text);
  std::string out, line;
  std::uint64_t state = seed;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') {
      out += line + "\n";
      continue;
    }
    std::istringstream fields(line);
    double v[4];
    std::string rest;
    if (!(fields >> v[0] >> v[1] >> v[2] >> v[3]) || (fields >> rest))
      throw std::runtime_error("packing line " + std::to_string(number) + " does not hold exactly x y z r");
    char buffer[128];
    for (int d = 0; d < 3; ++d) v[d] += amplitude * symmetric_unit(state);
    std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g %.17g\n", v[0], v[1], v[2], v[3]);
    out += buffer;
  }
  return out;
}

}  // namespace crosscheck
