#include "diagnose/diagnosis.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <set>

#include "calibration/response_surface.hpp"
#include "calibration/sensitivity.hpp"
#include "core/concurrent.hpp"
#include "diagnose/held_out.hpp"
#include "diagnose/model_comparison.hpp"
#include "diagnose/verdict.hpp"
#include "io/format_number.hpp"

namespace colza::diagnose {

using calibration::CalibrationError;
using calibration::Parameter;

namespace {

std::string fmt(double v) { return format_significant(v, 4); }

Eigen::VectorXd measured_values(const DiagnosisProblem& p) {
  Eigen::VectorXd m(static_cast<Eigen::Index>(p.features.size()));
  for (std::size_t i = 0; i < p.features.size(); ++i) m[static_cast<Eigen::Index>(i)] = p.features[i].measured;
  return m;
}

Eigen::VectorXd lab_samples(const DiagnosisProblem& p) {
  Eigen::VectorXd n(static_cast<Eigen::Index>(p.features.size()));
  for (std::size_t i = 0; i < p.features.size(); ++i) n[static_cast<Eigen::Index>(i)] = p.features[i].samples;
  return n;
}

Eigen::VectorXd measured_sd(const DiagnosisProblem& p) {
  Eigen::VectorXd u(static_cast<Eigen::Index>(p.features.size()));
  for (std::size_t i = 0; i < p.features.size(); ++i) u[static_cast<Eigen::Index>(i)] = p.features[i].uncertainty;
  return u;
}

// A forward model that counts its runs and evaluates a batch of (point, realisation) side by side.
class CountingModel {
 public:
  CountingModel(const DiagnosisForward& model, int jobs) : model_(model), jobs_(jobs) {}
  Eigen::VectorXd operator()(const ModelPoint& x, int realisation) {
    ++runs_;
    return model_(x, realisation);
  }
  std::vector<Eigen::VectorXd> batch(const std::vector<std::pair<ModelPoint, int>>& jobs) {
    std::vector<Eigen::VectorXd> out(jobs.size());
    run_concurrently(jobs.size(), jobs_, [&](std::size_t k) { out[k] = (*this)(jobs[k].first, jobs[k].second); });
    return out;
  }
  int runs() const { return runs_.load(); }
  int jobs() const { return jobs_; }

 private:
  const DiagnosisForward& model_;
  int jobs_;
  std::atomic<int> runs_{0};
};

// Realisations 1..n of one point.
std::vector<Eigen::VectorXd> realisations(CountingModel& model, const ModelPoint& x, int n) {
  std::vector<std::pair<ModelPoint, int>> jobs;
  for (int k = 1; k <= n; ++k) jobs.emplace_back(x, k);
  return model.batch(jobs);
}

// The calibration problem over `parameters`, the features as targets with the noise `sd`
// (measurement and realisation scatter) as their uncertainty, so that the solver weighs
// features by what a run can resolve. Runs are ranked by their root-mean-square misfit, the
// chi-square the fit is then judged by: ranked by the worst feature, a baseline that cannot
// fit one feature would be left where that feature's error is least, not where the data as a
// whole put it, and the refit's linearisation would have to carry the rest.
calibration::Problem calibration_problem(const DiagnosisProblem& p, const std::vector<Parameter>& parameters,
                                         const Eigen::VectorXd& sd, std::vector<Eigen::VectorXd> start) {
  calibration::Problem c;
  c.parameters = parameters;
  for (std::size_t i = 0; i < p.features.size(); ++i)
    c.targets.push_back({p.features[i].name, p.features[i].unit, p.features[i].measured, sd[static_cast<Eigen::Index>(i)]});
  c.target_correlation = p.measured_correlation;
  c.surface = calibration::SurfaceKind::kPlane;
  c.ranking = calibration::RunRanking::kRootMeanSquare;
  c.max_runs = std::max(p.settings.calibration_runs, static_cast<int>(parameters.size()) + 2);
  c.sequential_start = std::move(start);
  return c;
}

// The realisations at a fit and the noise they give; the adequacy is judged once the
// sensitivities are known (judge_refit).
Fit realise_fit(const DiagnosisProblem& p, CountingModel& model, const std::string& name, const ModelPoint& point) {
  Fit f;
  f.model = name;
  const std::vector<Eigen::VectorXd> ys = realisations(model, point, p.settings.replicates);
  f.mean_features = mean_of(ys);
  f.realisation_features = ys;
  f.noise = make_noise_model(measured_sd(p), p.measured_correlation, ys, lab_samples(p));
  return f;
}

// The residual after the linearised refit (a Gauss-Newton step from the fit, in whitened
// units, shift clamped to the parameters' bounds): m - ybar - A d, d = argmin |L^-1 (m - ybar
// - A d)|; the calibration's search stops at a run within the noise, not at the least-squares
// optimum, and what is left in the span of A is not a discrepancy of the model. Judged as a
// chi-square on F - (columns of A) degrees of freedom.
void judge_refit(const DiagnosisProblem& p, Fit& f, const Eigen::MatrixXd& A, const Eigen::VectorXd& lower,
                 const Eigen::VectorXd& upper, const NoiseModel& noise) {
  const Eigen::VectorXd r = measured_values(p) - f.mean_features;
  Eigen::VectorXd d = noise.whiten(A).completeOrthogonalDecomposition().solve(noise.whiten(r));
  f.held_at_bound.assign(static_cast<std::size_t>(d.size()), false);
  for (Eigen::Index j = 0; j < d.size(); ++j) {
    const double wanted = f.parameters[j] + d[j];
    f.held_at_bound[static_cast<std::size_t>(j)] = wanted < lower[j] || wanted > upper[j];
    d[j] = std::clamp(wanted, lower[j], upper[j]) - f.parameters[j];
  }
  f.refit_shift = d;
  f.adequacy = test_adequacy(noise, r - A * d, static_cast<int>(A.cols()), p.settings.significance);
}

// d y / d x of the least-squares plane y = c + J x through every run of the model's own seed
// (realisation 0): the calibration's design spans the ranges and its refinements crowd the
// solution, so this is a slope over the whole range (its own local planes, fitted on the
// crowded points, are too short to resolve a slope under the DEM's chaos). Empty when the
// runs do not determine a plane (fewer than np + 2, or no spread along a parameter).
Eigen::MatrixXd plane_slopes(const std::vector<calibration::Run>& runs, const std::vector<Parameter>& parameters) {
  std::vector<const calibration::Run*> own;
  for (const auto& r : runs)
    if (r.replicate == 0) own.push_back(&r);
  const Eigen::Index np = static_cast<Eigen::Index>(parameters.size());
  if (static_cast<Eigen::Index>(own.size()) < np + 2) return {};
  Eigen::MatrixXd X(static_cast<Eigen::Index>(own.size()), np);
  Eigen::VectorXd lower(np), upper(np);
  for (Eigen::Index j = 0; j < np; ++j)
    lower[j] = parameters[static_cast<std::size_t>(j)].lower, upper[j] = parameters[static_cast<std::size_t>(j)].upper;
  for (std::size_t k = 0; k < own.size(); ++k) X.row(static_cast<Eigen::Index>(k)) = own[k]->x.transpose();
  const calibration::ParameterScaling scaling = calibration::ParameterScaling::from_bounds(lower, upper);
  std::vector<calibration::ResponseSurface> planes;
  try {
    for (Eigen::Index i = 0; i < own[0]->y.size(); ++i) {
      Eigen::VectorXd y(X.rows());
      for (std::size_t k = 0; k < own.size(); ++k) y[static_cast<Eigen::Index>(k)] = own[k]->y[i];
      planes.push_back(calibration::ResponseSurface::fit(X, y, calibration::SurfaceKind::kPlane, scaling));
    }
  } catch (const calibration::SurfaceError&) {
    return {};
  }
  return calibration::surfaces_jacobian(planes, scaling.mid);
}

// The parameters' standard deviations under the noise, to first order about the fit:
// sqrt(diag((A^T Sigma^-1 A)^-1)), A the features' sensitivities (Gauss-Newton). The
// calibration's own are drawn from planes through its last, crowded runs, whose slopes show
// the runs' scatter as much as the response; these carry the noise the residuals are judged by.
Eigen::VectorXd sigma_under_noise(const NoiseModel& noise, const Eigen::MatrixXd& A) {
  const Eigen::MatrixXd W = noise.whiten(A);
  const Eigen::MatrixXd information = W.transpose() * W;
  return information.completeOrthogonalDecomposition().pseudoInverse().diagonal().cwiseMax(0.0).cwiseSqrt();
}

// Step 1: the baseline calibrated and judged.
Fit fit_baseline(const DiagnosisProblem& p, CountingModel& model) {
  const std::size_t np = p.parameters.size();
  Eigen::VectorXd centre(static_cast<Eigen::Index>(np));
  for (std::size_t j = 0; j < np; ++j)
    centre[static_cast<Eigen::Index>(j)] = 0.5 * (p.parameters[j].lower + p.parameters[j].upper);
  // The features' noise before the fit, from realisations at the centre: the solver's weights.
  const std::vector<Eigen::VectorXd> at_centre = realisations(model, ModelPoint{centre}, std::max(2, std::min(4, p.settings.replicates)));
  const NoiseModel prior = make_noise_model(measured_sd(p), p.measured_correlation, at_centre, lab_samples(p));
  calibration::LoopOptions opt;
  opt.jobs = model.jobs();
  const calibration::CalibrationResult r = calibration::calibrate_sequential(
      calibration_problem(p, p.parameters, prior.sd, {}),
      [&](const Eigen::VectorXd& x) { return model(ModelPoint{x}, 0); }, opt);
  Fit f = realise_fit(p, model, "baseline", ModelPoint{r.solution});
  f.parameters = r.solution;
  f.calibration_runs = static_cast<int>(r.forward_runs());
  f.design_sensitivity = plane_slopes(r.runs, p.parameters);
  return f;
}

// The baseline's sensitivities: the plane through the calibration's runs where they
// determine one (a slope over the whole range, at one seed), else by
// common random numbers at the fit: realisations 1..n of a step along each parameter against
// the same realisations at the fit. A step of a tenth of a range moves a DEM feature by less
// than its chaotic scatter between packings, so the planes are the better estimate.
Eigen::MatrixXd measure_sensitivities(const DiagnosisProblem& p, CountingModel& model, const Fit& base) {
  const Eigen::MatrixXd& D = base.design_sensitivity;
  if (D.rows() == static_cast<Eigen::Index>(p.features.size()) &&
      D.cols() == static_cast<Eigen::Index>(p.parameters.size()) && D.allFinite())
    return D;
  const int n = std::min(p.settings.signature_seeds, static_cast<int>(base.realisation_features.size()));
  const std::vector<Eigen::VectorXd> at_fit(base.realisation_features.begin(), base.realisation_features.begin() + n);
  std::vector<std::pair<ModelPoint, int>> jobs;
  std::vector<double> steps;
  for (std::size_t j = 0; j < p.parameters.size(); ++j) {
    const Parameter& par = p.parameters[j];
    double h = p.settings.sensitivity_step * (par.upper - par.lower);
    if (base.parameters[static_cast<Eigen::Index>(j)] + h > par.upper) h = -h;
    steps.push_back(h);
    Eigen::VectorXd xs = base.parameters;
    xs[static_cast<Eigen::Index>(j)] += h;
    for (int s = 1; s <= n; ++s) jobs.emplace_back(ModelPoint{xs}, s);
  }
  const std::vector<Eigen::VectorXd> ys = model.batch(jobs);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(p.features.size()), static_cast<Eigen::Index>(p.parameters.size()));
  for (std::size_t j = 0; j < p.parameters.size(); ++j) {
    const auto first = ys.begin() + static_cast<std::ptrdiff_t>(j * static_cast<std::size_t>(n));
    J.col(static_cast<Eigen::Index>(j)) = signature_from_pairs(at_fit, {first, first + n}, steps[j]).mean;
  }
  return J;
}

// The score tests of the signatures in `d` against the refit's residual: what the baseline's
// parameters cannot absorb inside their ranges. A parameter the refit holds at a bound can
// absorb no more in the direction the data ask for, so only the others' sensitivities are
// projected out.
ScoreTests score_against_refit(const DiagnosisProblem& p, const DiagnosisResult& d) {
  const Fit& b = d.baseline;
  std::vector<Eigen::Index> free;
  for (std::size_t j = 0; j < b.held_at_bound.size(); ++j)
    if (!b.held_at_bound[j]) free.push_back(static_cast<Eigen::Index>(j));
  std::vector<double> ranges;
  for (const Candidate& c : p.candidates) ranges.push_back(c.parameter.upper - c.neutral());
  return score_candidates(b.noise, d.baseline_sensitivity(Eigen::all, free), d.signatures, ranges,
                          measured_values(p) - b.mean_features - d.baseline_sensitivity * b.refit_shift);
}

// Every candidate's runs at its neutral and probe values at the baseline's fit, realisation
// by realisation (common random numbers).
class SignaturePairs {
 public:
  SignaturePairs(const DiagnosisProblem& p, const Eigen::VectorXd& fit)
      : p_(p), fit_(fit), neutral_(p.candidates.size()), probe_(p.candidates.size()) {}
  int seeds(std::size_t k) const { return static_cast<int>(neutral_[k].size()); }
  // Queues realisations seeds(k) + 1 .. last of candidate k (at most once between runs).
  void queue(std::size_t k, int last) {
    const Candidate& c = p_.candidates[k];
    for (int s = seeds(k) + 1; s <= last; ++s) {
      jobs_.emplace_back(ModelPoint{fit_, static_cast<int>(k), c.neutral()}, s);
      jobs_.emplace_back(ModelPoint{fit_, static_cast<int>(k), c.probe}, s);
      owner_.push_back(k);
    }
  }
  // Runs what is queued; false when nothing was.
  bool run(CountingModel& model) {
    if (jobs_.empty()) return false;
    const std::vector<Eigen::VectorXd> ys = model.batch(jobs_);
    for (std::size_t i = 0; i < owner_.size(); ++i) {
      neutral_[owner_[i]].push_back(ys[2 * i]);
      probe_[owner_[i]].push_back(ys[2 * i + 1]);
    }
    jobs_.clear();
    owner_.clear();
    return true;
  }
  Signature signature(std::size_t k) const {
    const Candidate& c = p_.candidates[k];
    return signature_from_pairs(neutral_[k], probe_[k], c.probe - c.neutral());
  }

 private:
  const DiagnosisProblem& p_;
  Eigen::VectorXd fit_;
  std::vector<std::vector<Eigen::VectorXd>> neutral_, probe_;
  std::vector<std::pair<ModelPoint, int>> jobs_;
  std::vector<std::size_t> owner_;
};

// Step 2: every candidate's signature at the fit from signature_seeds pairs, and the score
// tests. A signature whose signal-to-noise under the projection (score_test.hpp) stays below
// settings.signature_signal_to_noise, or is unknown (one pair), gets its pairs doubled up to
// settings.signature_seeds_max: its standard error shrinks as 1/sqrt(pairs).
void measure_signatures(const DiagnosisProblem& p, CountingModel& model, DiagnosisResult& out) {
  const std::size_t nc = p.candidates.size();
  const int most = p.settings.signature_seeds_max;  // >= signature_seeds (validate_diagnosis)
  SignaturePairs pairs(p, out.baseline.parameters);
  for (std::size_t k = 0; k < nc; ++k) pairs.queue(k, p.settings.signature_seeds);
  while (pairs.run(model)) {
    out.signatures.clear();
    for (std::size_t k = 0; k < nc; ++k) out.signatures.push_back(pairs.signature(k));
    out.scores = score_against_refit(p, out);
    if (!(p.settings.signature_signal_to_noise > 0.0)) break;
    for (std::size_t k = 0; k < nc; ++k) {
      const bool unknown = pairs.seeds(k) < 2;
      if ((unknown || out.scores.scores[k].signal_to_noise < p.settings.signature_signal_to_noise) &&
          pairs.seeds(k) < most)
        pairs.queue(k, std::min(2 * pairs.seeds(k), most));
    }
  }
}

// Where the extended search starts when the baseline's fit is a poor start: the joint
// linearised fit x_b + d, d = argmin |L^-1 (m - ybar_b - [J s] d)| (J the baseline's
// sensitivities, s candidate k's signature, L the baseline's noise factor), clamped to the
// ranges and the strength kept off both ends of its range. The baseline's parameters take
// part of any effect (friction takes part of rolling resistance's strength), and a search from
// the baseline's fit can stay in that corner of the joint space.
Eigen::VectorXd joint_linearised_start(const DiagnosisProblem& p, const DiagnosisResult& d, int k) {
  const Candidate& c = p.candidates[static_cast<std::size_t>(k)];
  const Eigen::Index np = static_cast<Eigen::Index>(p.parameters.size());
  Eigen::MatrixXd A(d.baseline_sensitivity.rows(), np + 1);
  A << d.baseline_sensitivity, d.signatures[static_cast<std::size_t>(k)].mean;
  const NoiseModel& noise = d.baseline.noise;
  const Eigen::VectorXd residual = measured_values(p) - d.baseline.mean_features;
  const Eigen::VectorXd shift = noise.whiten(A).completeOrthogonalDecomposition().solve(noise.whiten(residual));
  Eigen::VectorXd x(np + 1);
  for (Eigen::Index j = 0; j < np; ++j) {
    const Parameter& par = p.parameters[static_cast<std::size_t>(j)];
    x[j] = std::clamp(d.baseline.parameters[j] + shift[j], par.lower, par.upper);
  }
  const double range = c.parameter.upper - c.neutral();
  x[np] = c.neutral() + std::clamp(shift[np], 0.1 * range, 0.8 * range);
  return x;
}

// d features / d strength at an extended fit: realisations 1..n (n = signature_seeds, at
// most the replicates the fit was realised with) rerun at the strength moved by half the
// probe's step toward the inside of its range, differenced with the fit's own (common random
// numbers).
Signature strength_slope_at_fit(const DiagnosisProblem& p, CountingModel& model, const Fit& fit, int k,
                                const ModelPoint& at) {
  const Candidate& c = p.candidates[static_cast<std::size_t>(k)];
  const int n = std::min(p.settings.signature_seeds, static_cast<int>(fit.realisation_features.size()));
  const double half_probe = 0.5 * (c.probe - c.neutral());
  const double step = at.strength + half_probe <= c.parameter.upper ? half_probe : -half_probe;
  ModelPoint moved = at;
  moved.strength += step;
  std::vector<std::pair<ModelPoint, int>> jobs;
  for (int s = 1; s <= n; ++s) jobs.emplace_back(moved, s);
  const std::vector<Eigen::VectorXd> at_step = model.batch(jobs);
  const std::vector<Eigen::VectorXd> at_fit(fit.realisation_features.begin(), fit.realisation_features.begin() + n);
  return signature_from_pairs(at_fit, at_step, step);
}

// Candidate k's extended model calibrated by a sequential search from x0 (one step along each
// parameter toward the inside of its range around it), realised and judged.
ExtendedFit calibrate_extended(const DiagnosisProblem& p, CountingModel& model, const DiagnosisResult& d, int k,
                               const Eigen::VectorXd& x0) {
  const Candidate& c = p.candidates[static_cast<std::size_t>(k)];
  std::vector<Parameter> params = p.parameters;
  params.push_back(c.parameter);
  const std::size_t np = p.parameters.size();
  const double range = c.parameter.upper - c.neutral();
  std::vector<Eigen::VectorXd> start{x0};
  for (std::size_t j = 0; j <= np; ++j) {
    const Parameter& par = params[j];
    const double h = (j < np ? p.settings.sensitivity_step : 0.15) * (par.upper - par.lower);
    Eigen::VectorXd xs = x0;
    xs[static_cast<Eigen::Index>(j)] += xs[static_cast<Eigen::Index>(j)] + h <= par.upper ? h : -h;
    start.push_back(xs);
  }
  calibration::LoopOptions opt;
  opt.jobs = model.jobs();
  const auto point = [&](const Eigen::VectorXd& x) {
    return ModelPoint{x.head(static_cast<Eigen::Index>(np)), k, x[static_cast<Eigen::Index>(np)]};
  };
  const calibration::CalibrationResult r = calibration::calibrate_sequential(
      calibration_problem(p, params, d.baseline.noise.sd, start),
      [&](const Eigen::VectorXd& x) { return model(point(x), 0); }, opt);
  ExtendedFit e;
  e.candidate = k;
  e.start = x0;
  e.fit = realise_fit(p, model, c.name, point(r.solution));
  e.fit.parameters = r.solution;
  e.fit.calibration_runs = static_cast<int>(r.forward_runs());
  e.fit.strength_at_upper_bound = r.solution[static_cast<Eigen::Index>(np)] >= c.parameter.upper - 1e-3 * range;
  Eigen::MatrixXd A(d.baseline_sensitivity.rows(), d.baseline_sensitivity.cols() + 1);
  A << d.baseline_sensitivity, d.signatures[static_cast<std::size_t>(k)].mean;
  Eigen::VectorXd lo(static_cast<Eigen::Index>(np + 1)), hi(static_cast<Eigen::Index>(np + 1));
  for (std::size_t j = 0; j <= np; ++j) lo[static_cast<Eigen::Index>(j)] = params[j].lower, hi[static_cast<Eigen::Index>(j)] = params[j].upper;
  Fit common = e.fit;
  judge_refit(p, common, A, lo, hi, d.baseline.noise);
  judge_refit(p, e.fit, A, lo, hi, e.fit.noise);
  // Each parameter's sd: the larger of two linearisations, the signature from the neutral
  // value and the slope at the fit. They differ where the response curves: a mechanism that
  // saturates (rolling resistance lifting a heap's angle) rises more steeply from zero than
  // at the fit, and the signature alone would claim a strength known more closely than the
  // data know it.
  e.slope_at_fit = strength_slope_at_fit(p, model, e.fit, k, point(r.solution));
  Eigen::MatrixXd at_fit = A;
  at_fit.col(static_cast<Eigen::Index>(np)) = e.slope_at_fit.mean;
  e.fit.sigma = sigma_under_noise(e.fit.noise, A).cwiseMax(sigma_under_noise(e.fit.noise, at_fit));
  e.chi_square_common = common.adequacy.chi_square;
  e.likelihood_ratio_p = boundary_likelihood_ratio_p(d.baseline.adequacy.chi_square, e.chi_square_common);
  e.bic = bayesian_information_criterion(e.chi_square_common, static_cast<int>(np + 1),
                                         static_cast<int>(p.features.size()));
  return e;
}

// Step 3: candidate k's extended model, searched from the baseline's fit with the strength
// the score test estimates (kept off both ends of its range). When that search ends at a fit
// the adequacy test rejects, it is searched again from the joint linearised fit (if that lies
// more than a first step away in some parameter), and the fit of lower chi-square under the
// baseline's noise is kept: two starts, not one, where the first is seen to have failed.
ExtendedFit extend(const DiagnosisProblem& p, CountingModel& model, const DiagnosisResult& d, int k) {
  const Candidate& c = p.candidates[static_cast<std::size_t>(k)];
  const Eigen::Index np = static_cast<Eigen::Index>(p.parameters.size());
  const double range = c.parameter.upper - c.neutral();
  Eigen::VectorXd x0(np + 1);
  x0.head(np) = d.baseline.parameters;
  x0[np] = c.neutral() + std::clamp(d.scores.scores[static_cast<std::size_t>(k)].estimate, 0.1 * range, 0.8 * range);
  ExtendedFit first = calibrate_extended(p, model, d, k, x0);
  if (first.fit.adequacy.passes) return first;
  const Eigen::VectorXd x1 = joint_linearised_start(p, d, k);
  bool distinct = false;
  for (Eigen::Index j = 0; j <= np; ++j) {
    const Parameter& par = j < np ? p.parameters[static_cast<std::size_t>(j)] : c.parameter;
    distinct = distinct || std::abs(x1[j] - x0[j]) > p.settings.sensitivity_step * (par.upper - par.lower);
  }
  if (!distinct) return first;
  ExtendedFit second = calibrate_extended(p, model, d, k, x1);
  ExtendedFit& kept = second.chi_square_common < first.chi_square_common ? second : first;
  kept.searches = 2;
  kept.fit.calibration_runs = first.fit.calibration_runs + second.fit.calibration_runs;
  return kept;
}

// Step 3: each test held out, before (baseline) and after (the cause, or the best extended model).
std::vector<HeldOutPrediction> held_out_predictions(const DiagnosisProblem& p, const DiagnosisResult& d) {
  std::vector<std::string> tests;
  for (const Feature& f : p.features)
    if (std::find(tests.begin(), tests.end(), f.test) == tests.end()) tests.push_back(f.test);
  std::vector<HeldOutPrediction> out;
  if (tests.size() < 2) return out;
  const ExtendedFit* after = nullptr;
  for (const auto& e : d.extended)
    if (e.candidate == d.verdict.cause || (d.verdict.cause < 0 && (!after || e.bic < after->bic))) after = &e;
  const Eigen::VectorXd m = measured_values(p);
  for (const std::string& t : tests) {
    std::vector<bool> held;
    for (const Feature& f : p.features) held.push_back(f.test == t);
    HeldOutPrediction h;
    h.test = t;
    h.rms_before = held_out_rms(m, d.baseline.mean_features, d.baseline.noise.sd, d.baseline_sensitivity, held);
    h.rms_after = std::numeric_limits<double>::quiet_NaN();
    if (after) {
      Eigen::MatrixXd a(d.baseline_sensitivity.rows(), d.baseline_sensitivity.cols() + 1);
      a << d.baseline_sensitivity, d.signatures[static_cast<std::size_t>(after->candidate)].mean;
      h.rms_after = held_out_rms(m, after->fit.mean_features, after->fit.noise.sd, a, held);
    }
    out.push_back(h);
  }
  return out;
}

}  // namespace

void validate_diagnosis(const DiagnosisProblem& p) {
  if (p.features.empty()) throw CalibrationError("features", "no measured features to diagnose");
  if (p.parameters.empty()) throw CalibrationError("parameters", "the baseline has no calibrated parameter");
  if (p.features.size() <= p.parameters.size())
    throw CalibrationError("features", std::to_string(p.features.size()) + " features for " +
                                           std::to_string(p.parameters.size()) + " calibrated parameters: nothing is "
                                           "left to judge the model with (need more features than parameters)");
  std::set<std::string> names;
  for (const Feature& f : p.features) {
    if (!names.insert(f.name).second) throw CalibrationError("features", "feature " + f.name + " appears twice");
    if (!std::isfinite(f.measured)) throw CalibrationError(f.name, "the measured value is not a finite number");
    if (!(f.uncertainty > 0.0)) throw CalibrationError(f.name, "the measured uncertainty must be > 0");
  }
  for (const Parameter& par : p.parameters)
    if (!(par.upper > par.lower)) throw CalibrationError(par.key, "needs lower < upper");
  for (const Candidate& c : p.candidates) {
    if (!(c.parameter.upper > c.parameter.lower))
      throw CalibrationError(c.name, "its parameter's range must run from the neutral value up (lower < upper)");
    if (!(c.probe > c.neutral() && c.probe <= c.parameter.upper))
      throw CalibrationError(c.name, "its probe must lie in (neutral, upper] = (" + fmt(c.neutral()) + ", " +
                                         fmt(c.parameter.upper) + "], got " + fmt(c.probe));
  }
  const DiagnosisSettings& s = p.settings;
  if (s.replicates < 2) throw CalibrationError("replicates", "needs at least 2 realisations to measure the scatter");
  if (s.signature_seeds < 1 || s.signature_seeds > s.replicates)
    throw CalibrationError("signature_seeds", "must lie between 1 and replicates (" + std::to_string(s.replicates) + ")");
  if (s.signature_seeds_max < s.signature_seeds)
    throw CalibrationError("signature_seeds_max", "must not be below signature_seeds (" +
                                                      std::to_string(s.signature_seeds) + ")");
  if (!(s.signature_signal_to_noise >= 0.0))
    throw CalibrationError("signature_signal_to_noise", "must be >= 0 (0: never add pairs)");
  if (!(s.significance > 0.0 && s.significance < 0.5)) throw CalibrationError("significance", "must lie in (0, 0.5)");
  if (!(s.ambiguity_cosine > 0.0 && s.ambiguity_cosine < 1.0))
    throw CalibrationError("ambiguity_cosine", "must lie in (0, 1)");
}


DiagnosisResult diagnose(const DiagnosisProblem& p, const DiagnosisForward& forward) {
  validate_diagnosis(p);
  const auto say = [&](const std::string& line) {
    if (p.settings.on_progress) p.settings.on_progress(line);
  };
  CountingModel model(forward, std::max(1, p.settings.jobs));
  DiagnosisResult d;
  say("step 1: calibrating the baseline and judging it against the data");
  d.baseline = fit_baseline(p, model);
  d.baseline_sensitivity = measure_sensitivities(p, model, d.baseline);
  const calibration::Problem bounds = calibration_problem(p, p.parameters, measured_sd(p), {});
  judge_refit(p, d.baseline, d.baseline_sensitivity, bounds.lower(), bounds.upper(), d.baseline.noise);
  d.baseline.sigma = sigma_under_noise(d.baseline.noise, d.baseline_sensitivity);
  const int nf = static_cast<int>(p.features.size()), np = static_cast<int>(p.parameters.size());
  d.baseline_bic = bayesian_information_criterion(d.baseline.adequacy.chi_square, np, nf);
  if (p.settings.replicates < 8)
    d.warnings.push_back("the scatter comes from " + std::to_string(p.settings.replicates) +
                         " realisations (fewer than 8): the noise and every test built on it are rough");
  if (d.baseline.adequacy.passes || p.candidates.empty()) {
    d.verdict = decide(p, d.baseline, d.baseline_bic, d.scores, d.extended);
    d.forward_runs = model.runs();
    return d;
  }
  say("step 2: the candidates' signatures and score tests");
  measure_signatures(p, model, d);
  const std::vector<int> significant = significant_candidates(d.scores, p.settings.significance);
  say("step 3: calibrating the extended models of the leading candidates");
  for (std::size_t r = 0; r < significant.size() && static_cast<int>(r) < p.settings.extend_at_most; ++r)
    d.extended.push_back(extend(p, model, d, significant[r]));
  d.verdict = decide(p, d.baseline, d.baseline_bic, d.scores, d.extended);
  d.held_out = held_out_predictions(p, d);
  d.forward_runs = model.runs();
  return d;
}

}  // namespace colza::diagnose
