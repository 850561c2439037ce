#include "calibration/response_surface.hpp"

#include <cmath>

namespace colza::calibration {

const char* to_string(SurfaceKind k) {
  switch (k) {
    case SurfaceKind::kPlane: return "plane";
    case SurfaceKind::kQuadratic: return "quadratic";
    case SurfaceKind::kAuto: return "auto";
  }
  return "?";
}

SurfaceKind surface_kind_from_string(const std::string& s) {
  if (s == "plane") return SurfaceKind::kPlane;
  if (s == "quadratic") return SurfaceKind::kQuadratic;
  if (s == "auto") return SurfaceKind::kAuto;
  throw std::invalid_argument("unknown surface kind \"" + s + "\" (plane | quadratic | auto)");
}

ParameterScaling ParameterScaling::from_bounds(const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) {
  ParameterScaling s;
  s.mid = 0.5 * (lower + upper);
  s.half = 0.5 * (upper - lower);
  for (Eigen::Index j = 0; j < s.half.size(); ++j)
    if (!(s.half[j] > 0.0)) s.half[j] = std::max(1.0, std::abs(s.mid[j]));  // degenerate range: unit scale
  return s;
}

std::size_t surface_terms(SurfaceKind kind, std::size_t n) {
  return kind == SurfaceKind::kPlane ? 1 + n : 1 + n + n * (n + 1) / 2;
}

Eigen::VectorXd ResponseSurface::basis(const Eigen::VectorXd& u) const {
  Eigen::VectorXd b(surface_terms(kind_, n_));
  b[0] = 1.0;
  for (std::size_t j = 0; j < n_; ++j) b[1 + j] = u[j];
  if (kind_ == SurfaceKind::kQuadratic) {
    std::size_t t = 1 + n_;
    for (std::size_t j = 0; j < n_; ++j)
      for (std::size_t k = j; k < n_; ++k) b[t++] = u[j] * u[k];
  }
  return b;
}

Eigen::MatrixXd ResponseSurface::basis_gradient(const Eigen::VectorXd& u) const {
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(surface_terms(kind_, n_), n_);
  for (std::size_t j = 0; j < n_; ++j) g(1 + j, j) = 1.0;
  if (kind_ == SurfaceKind::kQuadratic) {
    std::size_t t = 1 + n_;
    for (std::size_t j = 0; j < n_; ++j)
      for (std::size_t k = j; k < n_; ++k, ++t) {
        g(t, j) += u[k];
        g(t, k) += u[j];
      }
  }
  return g;
}

ResponseSurface ResponseSurface::fit(const Eigen::MatrixXd& points, const Eigen::VectorXd& y, SurfaceKind kind,
                                     const ParameterScaling& scaling) {
  const std::size_t N = static_cast<std::size_t>(points.rows()), n = static_cast<std::size_t>(points.cols());
  if (kind == SurfaceKind::kAuto) {
    // Quadratic only when it is determined with at least one residual degree of freedom.
    if (N > surface_terms(SurfaceKind::kQuadratic, n)) {
      try {
        return fit(points, y, SurfaceKind::kQuadratic, scaling);
      } catch (const SurfaceError&) {
      }
    }
    return fit(points, y, SurfaceKind::kPlane, scaling);
  }
  ResponseSurface s;
  s.kind_ = kind;
  s.scaling_ = scaling;
  s.n_ = n;
  const std::size_t p = surface_terms(kind, n);
  if (N < p)
    throw SurfaceError("a " + std::string(to_string(kind)) + " in " + std::to_string(n) + " parameter(s) needs at least " +
                       std::to_string(p) + " design points, got " + std::to_string(N));
  Eigen::MatrixXd A(N, p);
  for (std::size_t i = 0; i < N; ++i) A.row(i) = s.basis(scaling.to_unit(points.row(i).transpose())).transpose();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  qr.setThreshold(1e-10);
  if (static_cast<std::size_t>(qr.rank()) < p)
    throw SurfaceError("the design points do not determine a " + std::string(to_string(kind)) + " (rank " +
                       std::to_string(qr.rank()) + " < " + std::to_string(p) +
                       " terms): points are collinear or the design does not vary every parameter");
  s.coef_ = qr.solve(y);
  const Eigen::VectorXd r = y - A * s.coef_;
  const double ssr = r.squaredNorm();
  const double sst = (y.array() - y.mean()).square().sum();
  s.r2_ = sst > 0.0 ? 1.0 - ssr / sst : 1.0;
  s.points_ = N;
  s.dof_ = N - p;
  s.residual_std_ = s.dof_ > 0 ? std::sqrt(ssr / static_cast<double>(s.dof_)) : 0.0;
  return s;
}

double ResponseSurface::predict(const Eigen::VectorXd& x) const { return basis(scaling_.to_unit(x)).dot(coef_); }

Eigen::VectorXd ResponseSurface::gradient(const Eigen::VectorXd& x) const {
  const Eigen::VectorXd du = basis_gradient(scaling_.to_unit(x)).transpose() * coef_;
  return du.cwiseQuotient(scaling_.half);  // du/dx = 1 / half
}

std::vector<std::string> ResponseSurface::term_names(const std::vector<std::string>& names) const {
  std::vector<std::string> t{"1"};
  for (std::size_t j = 0; j < n_; ++j) t.push_back("u(" + names[j] + ")");
  if (kind_ == SurfaceKind::kQuadratic)
    for (std::size_t j = 0; j < n_; ++j)
      for (std::size_t k = j; k < n_; ++k) t.push_back("u(" + names[j] + ")*u(" + names[k] + ")");
  return t;
}

Eigen::VectorXd ResponseSurface::plane_in_si() const {
  if (kind_ != SurfaceKind::kPlane) return {};
  // y = b0 + sum b_j (x_j - mid_j) / half_j = (b0 - sum b_j mid_j / half_j) + sum (b_j / half_j) x_j
  Eigen::VectorXd a(1 + n_);
  a[0] = coef_[0];
  for (std::size_t j = 0; j < n_; ++j) {
    a[1 + j] = coef_[1 + j] / scaling_.half[j];
    a[0] -= a[1 + j] * scaling_.mid[j];
  }
  return a;
}

}  // namespace colza::calibration
