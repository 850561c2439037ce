// Least-squares polynomial fits and the compression-curve characterisation of the paper
// (section 3.1): F(s) = c0 + c1 s + c2 s^2 over 150 N .. 29.3 kN, with s zeroed where the
// force first reaches 150 N.
#pragma once
#include <vector>

namespace colza {

struct PolynomialFit {
  std::vector<double> coefficients;  // c0, c1, ... (SI)
  double r2 = 0.0;                   // coefficient of determination
  std::size_t points = 0;
};

// Fits sum_k c_k x^k, k = 0..degree, by least squares (column-pivoting QR). Needs more
// points than coefficients; throws std::invalid_argument otherwise.
PolynomialFit fit_polynomial(const std::vector<double>& x, const std::vector<double>& y, int degree);

struct CompressionFit {
  bool valid = false;
  double zero_displacement = 0.0;  // piston travel where the force first reaches force_min (m)
  PolynomialFit fit;               // F(s) in N, s in m measured from zero_displacement
  bool reached_force_max = false;
};

// displacement/force: the recorded curve in time order.
CompressionFit fit_compression_curve(const std::vector<double>& displacement, const std::vector<double>& force,
                                     double force_min, double force_max);

}  // namespace colza
