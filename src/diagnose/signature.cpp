#include "diagnose/signature.hpp"

#include <cmath>
#include <stdexcept>

namespace colza::diagnose {

Signature signature_from_pairs(const std::vector<Eigen::VectorXd>& at_neutral,
                               const std::vector<Eigen::VectorXd>& at_probe, double step) {
  if (at_neutral.size() != at_probe.size() || at_neutral.empty())
    throw std::invalid_argument("signature_from_pairs: needs as many probe runs as neutral runs, at least one");
  if (step == 0.0) throw std::invalid_argument("signature_from_pairs: zero step");
  const std::size_t n = at_neutral.size();
  std::vector<Eigen::VectorXd> d(n);
  Signature s;
  s.seeds = static_cast<int>(n);
  s.mean = Eigen::VectorXd::Zero(at_neutral[0].size());
  for (std::size_t k = 0; k < n; ++k) {
    d[k] = (at_probe[k] - at_neutral[k]) / step;
    s.mean += d[k];
  }
  s.mean /= static_cast<double>(n);
  s.standard_error = Eigen::VectorXd::Zero(s.mean.size());
  if (n >= 2) {
    for (const auto& dk : d) s.standard_error += (dk - s.mean).array().square().matrix();
    s.standard_error = (s.standard_error / (static_cast<double>(n - 1) * static_cast<double>(n))).cwiseSqrt();
  }
  return s;
}

}  // namespace colza::diagnose
