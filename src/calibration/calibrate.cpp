#include "calibration/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "calibration/calibration_common.hpp"
#include "calibration/surface_solver.hpp"
#include "calibration/uncertainty.hpp"
#include "core/concurrent.hpp"
#include "core/interrupt.hpp"

namespace colza::calibration {

Eigen::VectorXd Problem::lower() const {
  Eigen::VectorXd v(parameters.size());
  for (std::size_t j = 0; j < parameters.size(); ++j) v[j] = parameters[j].lower;
  return v;
}

Eigen::VectorXd Problem::upper() const {
  Eigen::VectorXd v(parameters.size());
  for (std::size_t j = 0; j < parameters.size(); ++j) v[j] = parameters[j].upper;
  return v;
}

namespace {

Eigen::MatrixXd stack(const std::vector<Run>& runs, const std::vector<std::size_t>& idx, bool outputs) {
  const auto& first = outputs ? runs[idx[0]].y : runs[idx[0]].x;
  Eigen::MatrixXd m(idx.size(), first.size());
  for (std::size_t r = 0; r < idx.size(); ++r) m.row(r) = (outputs ? runs[idx[r]].y : runs[idx[r]].x).transpose();
  return m;
}

std::vector<ResponseSurface> fit_surfaces(const Problem& p, const std::vector<Run>& runs,
                                          const std::vector<std::size_t>& idx, SurfaceKind kind) {
  const Eigen::MatrixXd X = stack(runs, idx, false), Y = stack(runs, idx, true);
  const ParameterScaling scaling = ParameterScaling::from_bounds(p.lower(), p.upper());
  std::vector<ResponseSurface> s;
  for (std::size_t i = 0; i < p.targets.size(); ++i) {
    try {
      s.push_back(ResponseSurface::fit(X, Y.col(static_cast<Eigen::Index>(i)), kind, scaling));
    } catch (const SurfaceError& e) {
      throw CalibrationError("design", std::string("cannot fit the response surface for ") + p.targets[i].name + ": " +
                                           e.what());
    }
  }
  return s;
}

// What a target's error is judged against: the measurement uncertainty u_i, combined, when
// the scatter s_i was measured, with what a realisation adds. A single run judged on its own:
// sqrt(u^2 + s^2). The mean of n realisations at a point solved on surfaces that carry a
// common offset c_0 of variance o (realisation 0 shares it: same packing): its miss
// (1/n) sum_k (c_k + e_k) - c_0 has variance s^2 / n + o (1 - 2 / n) (c_k of variance o,
// independent for k >= 1; e_k the rest, s^2 - o), so sqrt(u^2 + s^2 / n + o (1 - 2 / n)).
Eigen::VectorXd tolerances(const Problem& p, const Eigen::VectorXd& scatter, int averaged,
                           const Eigen::VectorXd& offset = {}) {
  Eigen::VectorXd t = target_sigmas(p);
  if (scatter.size() != t.size()) return t;
  const double n = static_cast<double>(averaged);
  Eigen::ArrayXd v = t.array().square() + scatter.array().square() / n;
  if (offset.size() == t.size() && averaged > 1) v += offset.array() * (1.0 - 2.0 / n);
  return v.sqrt().matrix();
}

// The narrowest span, relative to its design range, that the sequential mode's final planes
// were fitted across, over the parameters; and that parameter.
std::pair<double, std::size_t> narrowest_surface_span(const Problem& p, const CalibrationResult& r) {
  double narrowest = std::numeric_limits<double>::infinity();
  std::size_t which = 0;
  for (std::size_t j = 0; j < p.parameters.size(); ++j) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t k : r.surface_points) {
      lo = std::min(lo, r.runs[k].x[static_cast<Eigen::Index>(j)]);
      hi = std::max(hi, r.runs[k].x[static_cast<Eigen::Index>(j)]);
    }
    const double span = (hi - lo) / (p.parameters[j].upper - p.parameters[j].lower);
    if (span < narrowest) narrowest = span, which = j;
  }
  return {narrowest, which};
}

// Below this fraction of a parameter's design range, planes through runs that each settle
// their own sample may show the realisations' scatter rather than the model's response (a
// user's density calibration: runs 1 kg/m^3 apart on 1200 .. 1300 gave bulk densities 551,
// 564 and 578 kg/m^3, a slope of 84 for a response of 0.46).
constexpr double kNarrowSpan = 0.05;

void finish_validation(const Problem& p, CalibrationResult& r, const Eigen::VectorXd& achieved,
                       const Eigen::VectorXd& tolerance) {
  r.achieved = achieved;
  r.error = achieved - target_values(p);
  r.tolerance = tolerance;
  r.within_uncertainty = normalised_misfit(p, achieved, tolerance) <= 1.0;
}

// Appends the replicates of x (realisation 0 gave y0) to r.runs, sets r.scatter and
// r.scatter_at and returns the mean of all R + 1 realisations.
Eigen::VectorXd record_scatter(const LoopOptions& opt, const Eigen::VectorXd& x, const Eigen::VectorXd& y0,
                               const std::vector<Eigen::VectorXd>& replicates, int iteration, CalibrationResult& r) {
  std::vector<Eigen::VectorXd> all{y0};
  Eigen::VectorXd mean = y0;
  for (std::size_t k = 0; k < replicates.size(); ++k) {
    r.runs.push_back({x, replicates[k], "replicate", iteration, static_cast<int>(k) + 1});
    if (opt.on_run) opt.on_run(r.runs.back());
    all.push_back(replicates[k]);
    mean += replicates[k];
  }
  r.scatter = realisation_scatter(all);
  r.scatter_at = x;
  return mean / static_cast<double>(all.size());
}

// Warnings on the surfaces the uncertainty comes from. Paper mode: the design's surfaces,
// judged by their residual and their R^2. Sequential mode: planes local to the solution,
// fitted to runs a fraction of the range apart, whose R^2 measures the realisation scatter
// against that small span rather than the fit, so only the missing residual is named.
void surface_warnings(const Problem& p, const std::vector<ResponseSurface>& s, bool sequential,
                      std::vector<std::string>& w) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].degrees_of_freedom() == 0)
      w.push_back("the surface for " + p.targets[i].name + " passes exactly through its " +
                  std::to_string(s[i].points()) + " points (no residual degree of freedom): its error is unknown and "
                  "not included in the parameter uncertainty; " +
                  (sequential ? "the search stopped on its start design: give more start points (sequential.start)"
                              : "add design points"));
    else if (!sequential && s[i].r2() < 0.9)
      w.push_back("the " + std::string(to_string(s[i].kind())) + " for " + p.targets[i].name + " fits poorly (R^2 = " +
                  fmt(s[i].r2()) + "): narrow the design range around the expected solution, or use --mode sequential");
  }
}

// Rounds to 10 significant digits: a point is stated the same way however it was computed
// (0.3, not 0.30000000000000004), so it maps to the same DEM run fingerprint.
Eigen::VectorXd round_point(Eigen::VectorXd x) {
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    if (x[j] == 0.0 || !std::isfinite(x[j])) continue;
    const double scale = std::pow(10.0, 9 - static_cast<int>(std::floor(std::log10(std::abs(x[j])))));
    x[j] = std::round(x[j] * scale) / scale;
  }
  return x;
}

void require_replicate_model(const Problem& p, const LoopOptions& opt) {
  if (p.replicates > 0 && !opt.replicate_model)
    throw CalibrationError("scatter.replicates", "this forward model has no other realisations (seeds) to measure the "
                                                 "scatter with: set replicates = 0");
}

// What a misfit counts in: the measurement uncertainty, or the tolerance with the scatter.
std::string misfit_unit(const CalibrationResult& r) {
  return r.scatter.size() ? " tolerances (measurement uncertainty and realisation scatter)" : " standard uncertainties";
}

// A scatter larger than the measurement uncertainty: one run cannot resolve the target.
void scatter_warnings(const Problem& p, CalibrationResult& r) {
  for (std::size_t i = 0; i < p.targets.size(); ++i)
    if (r.scatter[static_cast<Eigen::Index>(i)] > p.targets[i].uncertainty)
      r.warnings.push_back("the realisation scatter of " + p.targets[i].name + " (std " + fmt(r.scatter[i]) + " " +
                           p.targets[i].unit + " over " + std::to_string(p.replicates + 1) +
                           " seeds) exceeds its measurement uncertainty (" + fmt(p.targets[i].uncertainty) +
                           "): one run cannot resolve this target; the parameter uncertainty includes the part of the "
                           "scatter the design's surfaces do not show. A larger sample or runs averaged over seeds "
                           "would narrow it");
}

}  // namespace

Eigen::MatrixXd line_fit_correlation(const std::vector<double>& x) {
  double sum = 0.0, sum_sq = 0.0;
  for (double v : x) sum += v, sum_sq += v * v;
  const double rho = -sum / std::sqrt(static_cast<double>(x.size()) * sum_sq);
  return (Eigen::Matrix2d() << 1.0, rho, rho, 1.0).finished();
}

double normalised_misfit(const Problem& p, const Eigen::VectorXd& y) { return normalised_misfit(p, y, target_sigmas(p)); }

double normalised_misfit(const Problem& p, const Eigen::VectorXd& y, const Eigen::VectorXd& tolerance) {
  double m = 0.0;
  for (std::size_t i = 0; i < p.targets.size(); ++i) m = std::max(m, std::abs(y[i] - p.targets[i].value) / tolerance[i]);
  return m;
}

double ranking_misfit(const Problem& p, const Eigen::VectorXd& y, const Eigen::VectorXd& tolerance) {
  if (p.ranking == RunRanking::kWorstTarget) return normalised_misfit(p, y, tolerance);
  Eigen::VectorXd r(static_cast<Eigen::Index>(p.targets.size()));
  for (std::size_t i = 0; i < p.targets.size(); ++i) {
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    r[k] = (y[k] - p.targets[i].value) / tolerance[k];
  }
  const double chi_square = p.target_correlation.size() == 0 ? r.squaredNorm()
                                                             : r.dot(p.target_correlation.ldlt().solve(r));
  return std::sqrt(chi_square / static_cast<double>(r.size()));
}

Eigen::VectorXd single_run_tolerance(const Problem& p, const Eigen::VectorXd& scatter) {
  return tolerances(p, scatter, 1);
}

void validate_problem(const Problem& p, bool sequential) {
  if (p.parameters.empty()) throw CalibrationError("parameters", "no parameters to calibrate");
  if (p.targets.empty()) throw CalibrationError("targets", "no targets to calibrate against");
  for (const auto& par : p.parameters)
    if (!(par.upper > par.lower))
      throw CalibrationError("parameters." + par.name, "the range [" + fmt(par.lower) + ", " + fmt(par.upper) +
                                                           "] is empty: the design must vary every parameter");
  for (const auto& t : p.targets) {
    if (!std::isfinite(t.value)) throw CalibrationError(t.name, "the measured target is not a finite number");
    if (!(t.uncertainty > 0.0)) throw CalibrationError(t.name, "the uncertainty must be > 0");
  }
  const Eigen::MatrixXd& R = p.target_correlation;
  if (R.size() != 0 && (R.rows() != static_cast<Eigen::Index>(p.targets.size()) || R.cols() != R.rows() ||
                        Eigen::LLT<Eigen::MatrixXd>(R).info() != Eigen::Success))
    throw CalibrationError("targets", "the targets' correlation matrix must be targets x targets and positive definite");
  if (p.targets.size() < p.parameters.size())
    throw CalibrationError("targets", "fewer targets (" + std::to_string(p.targets.size()) + ") than parameters (" +
                                          std::to_string(p.parameters.size()) + "): the parameters are not determined");
  const auto& pts = sequential ? p.sequential_start : p.design;
  const std::string points_key = sequential ? "sequential.start" : "design";
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Eigen::VectorXd& x = pts[k];
    if (x.size() != static_cast<Eigen::Index>(p.parameters.size()))
      throw CalibrationError(points_key, "a design point has " + std::to_string(x.size()) + " values for " +
                                             std::to_string(p.parameters.size()) + " parameters");
    // Outside the bounds, a start point could become the best run and invert the trust region.
    if ((x.array() < p.lower().array()).any() || (x.array() > p.upper().array()).any())
      throw CalibrationError(points_key, "point " + std::to_string(k + 1) + " lies outside the parameters' bounds");
    // A repeated point is the same run counted twice: a fit with a degree of freedom it has not.
    for (std::size_t l = 0; l < k; ++l)
      if (pts[l] == x)
        throw CalibrationError(points_key, "point " + std::to_string(k + 1) + " repeats point " + std::to_string(l + 1));
  }
  const std::size_t need = p.parameters.size() + 1;
  if (!sequential && p.design.size() < need)
    throw CalibrationError("design", "too few design points for a plane in " + std::to_string(p.parameters.size()) +
                                         " parameter(s): " + std::to_string(p.design.size()) + " given, at least " +
                                         std::to_string(need) + " needed");
  if (p.replicates < 0 || p.replicates == 1)
    throw CalibrationError("scatter.replicates", "must be 0 (off) or at least 2: one extra realisation gives a scatter "
                                                 "with a single degree of freedom");
  if (sequential && p.max_runs < static_cast<int>(need) + 1)
    throw CalibrationError("sequential.max_runs", "the budget must allow the " + std::to_string(need) +
                                                      " start points and at least one refinement run");
}

std::vector<Eigen::VectorXd> evaluate_batch(const ForwardModel& model, const std::vector<Eigen::VectorXd>& points,
                                            int jobs) {
  std::vector<Eigen::VectorXd> out(points.size());
  run_concurrently(points.size(), jobs, [&](std::size_t k) { out[k] = model(points[k]); });
  return out;
}

CalibrationResult calibrate_paper(const Problem& p, const ForwardModel& model, const LoopOptions& opt) {
  validate_problem(p, false);
  require_replicate_model(p, opt);
  CalibrationResult r;
  r.mode = "paper";
  const std::vector<Eigen::VectorXd> ys = evaluate_batch(model, p.design, opt.jobs);
  std::vector<std::size_t> idx;
  for (std::size_t k = 0; k < p.design.size(); ++k) {
    r.runs.push_back({p.design[k], ys[k], "design", 0});
    idx.push_back(k);
    if (opt.on_run) opt.on_run(r.runs.back());
  }
  r.surfaces = fit_surfaces(p, r.runs, idx, p.surface);
  r.surface_points = idx;
  surface_warnings(p, r.surfaces, false, r.warnings);
  // A target out of reach even alone is a design range (or a measured value) to mend before
  // any further run. Targets reachable alone but not together may be the surfaces' failing
  // (a poor fit) as much as the model's: the validation run at the compromise tells.
  const Eigen::VectorXd compromise = solve_on_surfaces(r.surfaces, p, p.lower(), p.upper(), p.design);
  const ReachVerdict reach = judge_reach(r.surfaces, p, p.lower(), p.upper(), p.design, compromise);
  if (reach.kind == ReachVerdict::kNotAlone) throw CalibrationError(reach.key, reach.text);
  if (reach.kind == ReachVerdict::kNotTogether)
    r.warnings.push_back("judged on the design's surfaces, " + reach.text +
                         " (the solution below is that compromise, and its validation run shows what the model gives "
                         "there)");
  r.solution = round_point(compromise);
  // The validation run, and with replicates its other realisations (all in one batch).
  const BatchWithReplicates v =
      evaluate_with_replicates(model, opt.replicate_model, {r.solution}, r.solution, p.replicates, opt.jobs);
  r.runs.push_back({r.solution, v.points[0], "validation", 1});
  if (opt.on_run) opt.on_run(r.runs.back());
  Eigen::VectorXd achieved = v.points[0];
  const int averaged = 1 + p.replicates;
  if (p.replicates > 0) {  // the mean of the realisations is what is validated
    achieved = record_scatter(opt, r.solution, achieved, v.replicates, 1, r);
    scatter_warnings(p, r);
  }
  propagate_uncertainty(p, r.surfaces, r);
  determination_warnings(p, r);
  // The mean of the realisations at the solution misses the measurement by its own scatter
  // and by the design's offset the surfaces do not show (tolerances above; both empty, and
  // the tolerance u, without replicates).
  finish_validation(p, r, achieved, tolerances(p, r.scatter, averaged, unseen_scatter_variance(r.scatter, r.surfaces)));
  r.iterations = 1;
  if (!r.within_uncertainty)
    r.warnings.push_back("the validation " + std::string(averaged > 1 ? "(mean of " + std::to_string(averaged) +
                                                                           " realisations) "
                                                                     : "run ") +
                         "misses the measurement by " + fmt(normalised_misfit(p, r.achieved, r.tolerance)) +
                         misfit_unit(r) + ": the surface is not accurate enough near the solution; use "
                         "--mode sequential or add design points near the solution");
  return r;
}

namespace {

// Planes (one per target) through the runs of `pool` nearest run `best` (scaled distance):
// the n + 2 nearest, a plane's n + 1 terms with one residual degree of freedom (all of them
// when fewer), more if those do not determine a plane. `used` receives the runs fitted.
std::vector<ResponseSurface> local_planes(const Problem& p, const std::vector<Run>& runs,
                                          const std::vector<std::size_t>& pool, std::size_t best,
                                          const ParameterScaling& sc, std::vector<std::size_t>& used) {
  const std::size_t neighbours = p.parameters.size() + 2;
  std::vector<std::size_t> order = pool;
  const Eigen::VectorXd ub = sc.to_unit(runs[best].x);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return (sc.to_unit(runs[a].x) - ub).norm() < (sc.to_unit(runs[b].x) - ub).norm();
  });
  for (std::size_t k = std::min(order.size(), neighbours); k <= order.size(); ++k) {
    used.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(k));
    try {
      return fit_surfaces(p, runs, used, SurfaceKind::kPlane);
    } catch (const CalibrationError&) {
    }
  }
  throw CalibrationError("sequential.start", "the start points do not determine a plane: they must not be collinear");
}

// Without a measured scatter, a sequential search's last planes are judged by their residual:
// runs that spread about a plane (residual std, at least one degree of freedom) by more than
// its target's measurement uncertainty cannot resolve that target one run at a time, and the
// plane's slope, the parameter uncertainty and the reach verdict drawn from it show mostly the
// spread. (A user's density calibration on the 117-sphere sample: runs at rho_p 1237-1275
// kg/m^3 gave bulk densities 555-572 kg/m^3, a residual of 12.6 for an uncertainty of 5, a
// slope of 0.002 for a response of 0.44; it was told the target was out of reach and to
// raise sequential.max_runs.) Appends the warning and returns true when some target is so.
bool residual_warning(const Problem& p, const std::vector<ResponseSurface>& s, bool can_replicate,
                      std::vector<std::string>& w) {
  std::string spread;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i].degrees_of_freedom() == 0 || !(s[i].residual_std() > p.targets[i].uncertainty)) continue;
    spread += (spread.empty() ? "" : "; ") + p.targets[i].name + " " + fmt(s[i].residual_std()) + " " +
              p.targets[i].unit + " against " + fmt(p.targets[i].uncertainty) + " (" + std::to_string(s[i].points()) +
              " runs, " + std::to_string(s[i].degrees_of_freedom()) + " degree(s) of freedom)";
  }
  if (spread.empty()) return false;
  w.push_back("the runs spread about the last local planes by more than the measurement's uncertainty (residual std " +
              spread + "): one run cannot resolve such a target, so the planes' slopes, and the parameter "
              "uncertainty and reach drawn from them, mostly show the runs' spread, not the response. " +
              (can_replicate ? std::string("Where each run settles its own sample that spread is the realisation "
                                           "scatter: measure it with [scatter] replicates (the tolerance then "
                                           "includes it), or use a larger sample")
                             : std::string("Every run loads the same packing, so the spread is the response's own "
                                           "roughness at the runs' spacing: give start points further apart "
                                           "(sequential.start), or use a larger sample")));
  return true;
}

}  // namespace

CalibrationResult calibrate_sequential(const Problem& p, const ForwardModel& model, const LoopOptions& opt) {
  validate_problem(p, true);
  require_replicate_model(p, opt);
  CalibrationResult r;
  r.mode = "sequential";
  const std::size_t n = p.parameters.size();
  const Eigen::VectorXd lo = p.lower(), hi = p.upper();
  const ParameterScaling sc = ParameterScaling::from_bounds(lo, hi);
  std::vector<Eigen::VectorXd> start = p.sequential_start;
  if (start.empty()) {
    // Centre of the range and one step of a quarter range along each parameter.
    start.push_back(sc.mid);
    for (std::size_t j = 0; j < n; ++j) {
      Eigen::VectorXd x = sc.mid;
      x[j] += 0.5 * sc.half[j];
      start.push_back(x);
    }
    for (auto& x : start) x = round_point(x);
  }
  // The start design, and with replicates the other realisations of its first point (one batch).
  const BatchWithReplicates b =
      evaluate_with_replicates(model, opt.replicate_model, start, start[0], p.replicates, opt.jobs);
  const std::vector<Eigen::VectorXd>& ys = b.points;
  std::vector<std::size_t> pool;  // runs that take part in the search (not the replicates)
  for (std::size_t k = 0; k < start.size(); ++k) {
    r.runs.push_back({start[k], ys[k], "design", 0});
    pool.push_back(k);
    if (opt.on_run) opt.on_run(r.runs.back());
  }
  // Know the noise before chasing it: with the scatter s measured at the first start point
  // (assumed to hold across the range), a single run is a hit within sqrt(u^2 + s^2).
  // Refining further buys nothing: any one realisation, the design's included, is off by ~s.
  if (p.replicates > 0) {
    record_scatter(opt, start[0], ys[0], b.replicates, 0, r);
    scatter_warnings(p, r);
  }
  const Eigen::VectorXd tolerance = single_run_tolerance(p, r.scatter);
  auto misfit = [&](std::size_t k) { return ranking_misfit(p, r.runs[k].y, tolerance); };
  std::size_t best = pool[0];
  for (std::size_t k : pool)
    if (misfit(k) < misfit(best)) best = k;
  double radius = 0.5;  // trust-region half width in scaled units (1 = half the range)
  int iteration = 0;  // refinement runs made; a retry on a repeated point is not one
  bool stalled = false;
  while (misfit(best) > 1.0 && static_cast<int>(pool.size()) < p.max_runs) {
    std::vector<std::size_t> idx;
    const std::vector<ResponseSurface> s = local_planes(p, r.runs, pool, best, sc, idx);
    const Eigen::VectorXd tlo = lo.cwiseMax(r.runs[best].x - radius * sc.half);
    const Eigen::VectorXd thi = hi.cwiseMin(r.runs[best].x + radius * sc.half);
    Eigen::VectorXd x = round_point(solve_on_surfaces(s, p, tlo, thi, {r.runs[best].x}));
    // A point already evaluated brings nothing new: shrink and retry (or give up).
    bool duplicate = false;
    for (const auto& run : r.runs) duplicate = duplicate || (sc.to_unit(run.x) - sc.to_unit(x)).norm() < 1e-9;
    r.surfaces = s;
    r.surface_points = idx;
    if (duplicate) {
      radius *= 0.5;
      if (radius < 1e-4) {
        r.warnings.push_back("the refinement stalled (the surrogate's solution repeats an evaluated point)");
        stalled = true;
        break;
      }
      continue;
    }
    throw_if_interrupted();  // Ctrl-C between runs, for models that never step (core/interrupt.hpp)
    ++iteration;
    r.runs.push_back({x, model(x), "refinement", iteration});
    if (opt.on_run) opt.on_run(r.runs.back());
    const std::size_t k = r.runs.size() - 1;
    pool.push_back(k);
    if (misfit(k) < misfit(best)) {
      best = k;
      radius = std::min(2.0 * radius, 2.0);
    } else {
      radius *= 0.5;
    }
  }
  r.iterations = iteration;
  r.solution = r.runs[best].x;
  // The uncertainty comes from the loop's last planes, fitted around the best run before the
  // last refinement. When they have no residual degree of freedom (the n + 1 start runs,
  // after a first refinement that hit) or the search stopped on the start design, planes
  // through the runs nearest the solution, its own included, replace them: with n + 2 runs
  // they have a residual, whose error then enters the uncertainty. (Refitting every time on the nearest runs was tried:
  // at convergence they cluster, their slopes are the runs' scatter, and the full-size
  // compression identity test's mu_pp came out +/- 0.35 instead of +/- 0.04.)
  bool no_residual = r.surfaces.empty();
  for (const ResponseSurface& surface : r.surfaces) no_residual = no_residual || surface.degrees_of_freedom() == 0;
  if (no_residual) r.surfaces = local_planes(p, r.runs, pool, best, sc, r.surface_points);
  surface_warnings(p, r.surfaces, true, r.warnings);
  // Only a model whose realisations scatter (one with other seeds to run) can have [scatter]
  // replicates; without them, the runs' own spread about the planes is all there is to see.
  const bool can_replicate = static_cast<bool>(opt.replicate_model);
  const bool lost_in_residual = p.replicates == 0 && residual_warning(p, r.surfaces, can_replicate, r.warnings);
  r.runs[best].role = r.runs[best].role == "design" ? "design+validation" : "validation";
  propagate_uncertainty(p, r.surfaces, r);
  determination_warnings(p, r);
  const auto [span, narrow] = narrowest_surface_span(p, r);
  if (span < kNarrowSpan && p.replicates == 0 && can_replicate) {
    const Parameter& q = p.parameters[narrow];
    r.warnings.push_back("the uncertainty comes from planes through runs " + fmt(100.0 * span) + " % of " + q.name +
                         "'s design range apart: where runs at nearby points scatter (each DEM run settles its own "
                         "sample), those planes' slopes measure the scatter rather than the response, and the +/- "
                         "can be far too small; measure the scatter with [scatter] replicates");
  }
  finish_validation(p, r, r.runs[best].y, tolerance);
  // The search stops at the first run within the tolerance and keeps the best of several, so
  // without a measured scatter that run's success is partly luck. One more realisation at
  // the solution (seed + 1), which took no part in choosing it, confirms it or not.
  bool confirmation_missed = false;
  if (r.within_uncertainty && p.replicates == 0 && opt.replicate_model) {
    throw_if_interrupted();
    r.confirmation = opt.replicate_model(r.solution, 1);
    r.runs.push_back({r.solution, r.confirmation, "confirmation", iteration, 1});
    if (opt.on_run) opt.on_run(r.runs.back());
    r.confirmation_misfit = normalised_misfit(p, r.confirmation, tolerance);
    if (r.confirmation_misfit > 1.0) {
      r.within_uncertainty = false;
      confirmation_missed = true;
      const double differ = ((r.confirmation - r.achieved).array().abs() / tolerance.array()).maxCoeff();
      r.warnings.push_back("the solution's run was within the tolerance, but another realisation there (seed + 1) "
                           "misses the measurement by " + fmt(r.confirmation_misfit) + misfit_unit(r) +
                           "; the two realisations differ by up to " + fmt(differ) +
                           misfit_unit(r) + ", so the stop may have been a lucky draw: measure the realisation "
                           "scatter ([scatter] replicates) and judge the solution against it");
    }
  }
  if (!r.within_uncertainty && !confirmation_missed) {
    // Is the target reachable at all inside the bounds (judged on the last local surfaces)?
    // Not on planes whose residual exceeds the uncertainty: their slopes are the runs' spread.
    ReachVerdict reach;
    if (!lost_in_residual)
      reach = judge_reach(r.surfaces, p, lo, hi, {r.solution}, solve_on_surfaces(r.surfaces, p, lo, hi, {r.solution}));
    const bool out_of_reach = reach.kind != ReachVerdict::kReached;
    if (out_of_reach) r.warnings.push_back("judged on the last local planes: " + reach.text);
    // A search that had narrowed to a few per cent of the range and still missed is chasing
    // the runs' scatter: more runs would not help.
    const bool narrowed = radius < kNarrowSpan && can_replicate;
    std::string advice = "raise sequential.max_runs";
    if (stalled)
      advice = "the search stalled before its budget was spent (above), so more runs will not help";
    else if (lost_in_residual)
      advice = "the runs spread about the last planes by more than the measurement's uncertainty (see above), so "
               "more runs will not help";
    else if (out_of_reach)
      advice = "the planes put the measurement out of reach inside the bounds (above), so more runs will not help";
    else if (narrowed)
      advice = "the search had narrowed to " + fmt(100.0 * radius) +
               " % of half the range, where the runs miss by more than the tolerance; if runs at nearby points "
               "scatter, more runs will not help: measure the scatter ([scatter] replicates) or check the "
               "measurement's uncertainty";
    r.warnings.push_back("stopped after " + std::to_string(pool.size()) + " runs (sequential.max_runs = " +
                         std::to_string(p.max_runs) + ") with the best run " +
                         fmt(normalised_misfit(p, r.achieved, tolerance)) + misfit_unit(r) + " from the measurement: " +
                         advice);
  }
  return r;
}

}  // namespace colza::calibration
