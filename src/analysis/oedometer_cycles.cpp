#include "analysis/oedometer_cycles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/types.hpp"

namespace colza {

std::vector<RowRange> split_branches(const std::vector<double>& s, double reversal_tolerance) {
  const std::size_t n = s.size();
  if (n < 2) return {{0, n == 0 ? 0 : n - 1}};
  const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
  const double tol = reversal_tolerance * (*hi - *lo);
  std::vector<RowRange> out;
  std::size_t start = 0;
  int direction = 0;  // +1 travel increasing, -1 decreasing, 0 not yet known
  std::size_t top = 0, bottom = 0;  // rows of the running maximum and minimum since `start`
  for (std::size_t i = 1; i < n; ++i) {
    if (s[i] > s[top]) top = i;
    if (s[i] < s[bottom]) bottom = i;
    if (direction == 0) {
      if (s[top] - s[start] > tol) direction = +1;
      else if (s[start] - s[bottom] > tol) direction = -1;
      continue;
    }
    const std::size_t turn = direction > 0 ? top : bottom;
    const bool turned = direction > 0 ? s[turn] - s[i] > tol : s[i] - s[turn] > tol;
    if (!turned) continue;
    out.push_back({start, turn});
    start = turn;
    direction = -direction;
    top = bottom = turn;  // the running extremes of the new branch, over rows turn..i
    for (std::size_t k = turn + 1; k <= i; ++k) {
      if (s[k] > s[top]) top = k;
      if (s[k] < s[bottom]) bottom = k;
    }
  }
  out.push_back({start, n - 1});
  return out;
}

namespace {

// Slope of the least-squares line y(x) through the rows `rows`.
double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y,
                           const std::vector<std::size_t>& rows) {
  double mx = 0.0, my = 0.0;
  for (std::size_t r : rows) mx += x[r], my += y[r];
  mx /= static_cast<double>(rows.size());
  my /= static_cast<double>(rows.size());
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t r : rows) {
    sxy += (x[r] - mx) * (y[r] - my);
    sxx += (x[r] - mx) * (x[r] - mx);
  }
  return sxx > 0.0 ? sxy / sxx : kNotAvailable;
}

}  // namespace

LoadUnloadAnalysis analyse_load_unload(const std::vector<double>& travel, const std::vector<double>& force,
                                       const std::vector<double>& radial_force, const OedometerGeometry& g,
                                       const CycleAnalysisSettings& settings) {
  const std::size_t n = travel.size();
  if (force.size() != n || (!radial_force.empty() && radial_force.size() != n))
    throw std::invalid_argument("travel, force and radial force must have the same number of rows");
  if (n < 2) throw std::invalid_argument("a load-unload curve needs at least 2 rows");
  if (!(g.area > 0.0) || !(g.height > 0.0) || !(g.cylinder_diameter > 0.0))
    throw std::invalid_argument("the area, height and cylinder diameter must be positive");
  for (double s : settings.modulus_stresses)
    if (!(s > 0.0)) throw std::invalid_argument("modulus stresses must be positive");

  LoadUnloadAnalysis a;
  a.has_radial_force = !radial_force.empty();
  std::vector<double> sigma_v(n), eps(n), sigma_h(n, kNotAvailable);
  for (std::size_t i = 0; i < n; ++i) {
    sigma_v[i] = force[i] / g.area;
    eps[i] = travel[i] / g.height;
    if (a.has_radial_force) sigma_h[i] = radial_force[i] / (kPi * g.cylinder_diameter * (g.height - travel[i]));
  }
  const auto ratio = [&](double h, double v) { return a.has_radial_force && v > 0.0 ? h / v : kNotAvailable; };

  for (const RowRange& r : split_branches(travel, settings.reversal_tolerance)) {
    CurveBranch b;
    b.first_row = r.first;
    b.last_row = r.last;
    b.loading = travel[r.last] >= travel[r.first];
    b.stress_start = sigma_v[r.first];
    b.stress_end = sigma_v[r.last];
    b.strain_start = eps[r.first];
    b.strain_end = eps[r.last];
    double lo = sigma_v[r.first], hi = lo;
    for (std::size_t i = r.first; i <= r.last; ++i) {
      lo = std::min(lo, sigma_v[i]);
      hi = std::max(hi, sigma_v[i]);
      if (i > r.first) b.work += 0.5 * (sigma_v[i] + sigma_v[i - 1]) * (eps[i] - eps[i - 1]);
    }
    b.stress_extreme = b.loading ? hi : lo;
    b.lateral_ratio_end = ratio(sigma_h[r.last], sigma_v[r.last]);
    for (double target : settings.modulus_stresses) {
      if (target < lo || target > hi) continue;  // the branch does not pass through sigma*
      LocalModulus m;
      m.stress = target;
      std::vector<std::size_t> rows;
      for (std::size_t i = r.first; i <= r.last; ++i)
        if (std::abs(sigma_v[i] - target) <= settings.modulus_window * target) {
          if (rows.empty() || rows.back() + 1 != i) ++m.passages;  // a new run of rows in the window
          rows.push_back(i);
        }
      m.points = rows.size();
      if (!rows.empty()) {
        m.stress_low = m.stress_high = sigma_v[rows.front()];
        double sum_h = 0.0, sum_v = 0.0;
        for (std::size_t i : rows) {
          m.stress_low = std::min(m.stress_low, sigma_v[i]);
          m.stress_high = std::max(m.stress_high, sigma_v[i]);
          sum_h += sigma_h[i];
          sum_v += sigma_v[i];
        }
        m.lateral_ratio = ratio(sum_h, sum_v);
      }
      if (rows.size() >= 3) m.modulus = least_squares_slope(eps, sigma_v, rows);
      b.moduli.push_back(m);
    }
    a.branches.push_back(std::move(b));
  }
  for (std::size_t k = 0; k + 1 < a.branches.size(); ++k) {
    const CurveBranch& up = a.branches[k];
    const CurveBranch& down = a.branches[k + 1];
    if (!up.loading || down.loading) continue;
    LoadUnloadCycle c;
    c.loading_branch = k;
    c.unloading_branch = k + 1;
    c.loop_area = up.work + down.work;
    c.strain_at_turn = up.strain_end;
    c.permanent_strain = down.strain_end;
    c.rebound_strain = c.strain_at_turn - c.permanent_strain;
    a.cycles.push_back(c);
  }
  return a;
}

}  // namespace colza
