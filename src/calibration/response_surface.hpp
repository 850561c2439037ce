// Response surfaces for calibration (paper sections 3.2-3.3): one least-squares surface
// per target over the design points, y(x) = b0 + sum_j b_j u_j [+ sum_{j<=k} b_jk u_j u_k],
// with the parameters scaled to the design box, u_j = (x_j - mid_j) / half_j (dimensionless),
// so stiffnesses in N/m and friction coefficients share one well-conditioned system.
// The paper fits a plane ("planar regression surface") per target; a quadratic is used
// where the points determine it (full column rank and at least one residual degree of freedom).
#pragma once
#include <Eigen/Dense>
#include <stdexcept>
#include <string>
#include <vector>

namespace colza::calibration {

enum class SurfaceKind { kPlane, kQuadratic, kAuto };
const char* to_string(SurfaceKind k);
SurfaceKind surface_kind_from_string(const std::string& s);  // "plane" | "quadratic" | "auto"

// Thrown when the points cannot determine the requested surface (too few, or degenerate).
class SurfaceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ParameterScaling {
  Eigen::VectorXd mid, half;  // u = (x - mid) / half; half > 0
  Eigen::VectorXd to_unit(const Eigen::VectorXd& x) const { return (x - mid).cwiseQuotient(half); }
  Eigen::VectorXd from_unit(const Eigen::VectorXd& u) const { return mid + u.cwiseProduct(half); }
  static ParameterScaling from_bounds(const Eigen::VectorXd& lower, const Eigen::VectorXd& upper);
};

class ResponseSurface {
 public:
  // points: one row per design point (parameters in SI), y: the target at each point.
  // kAuto takes the quadratic when it is determined, else the plane. Throws SurfaceError.
  static ResponseSurface fit(const Eigen::MatrixXd& points, const Eigen::VectorXd& y, SurfaceKind kind,
                             const ParameterScaling& scaling);

  double predict(const Eigen::VectorXd& x) const;
  Eigen::VectorXd gradient(const Eigen::VectorXd& x) const;  // dy/dx in SI units of y per unit of x

  SurfaceKind kind() const { return kind_; }
  const Eigen::VectorXd& coefficients() const { return coef_; }  // in scaled variables u
  std::vector<std::string> term_names(const std::vector<std::string>& parameter_names) const;
  double r2() const { return r2_; }
  // Residual standard error sqrt(SSR / (N - p)) (units of y); 0 when N == p (no information).
  double residual_std() const { return residual_std_; }
  std::size_t points() const { return points_; }
  std::size_t degrees_of_freedom() const { return dof_; }
  // For a plane: y = a0 + sum a_j x_j in SI (a0 then a_1..a_n). Empty for a quadratic.
  Eigen::VectorXd plane_in_si() const;
  const ParameterScaling& scaling() const { return scaling_; }

 private:
  Eigen::VectorXd basis(const Eigen::VectorXd& u) const;
  Eigen::MatrixXd basis_gradient(const Eigen::VectorXd& u) const;  // d basis / d u, p x n
  SurfaceKind kind_ = SurfaceKind::kPlane;
  ParameterScaling scaling_;
  std::size_t n_ = 0;
  Eigen::VectorXd coef_;
  double r2_ = 0.0, residual_std_ = 0.0;
  std::size_t points_ = 0, dof_ = 0;
};

std::size_t surface_terms(SurfaceKind kind, std::size_t parameters);

}  // namespace colza::calibration
