// The calibration loop, shared by the identity model (tests) and the DEM (the CLI):
// a forward model maps a parameter vector to a target vector; the loop runs design points,
// fits a response surface per target, solves surface(x) = measured target inside the
// design's range and runs a validation evaluation at the solution.
//
//  * paper mode (rapeseed paper sections 2.2, 3.2, 3.3): a fixed design (e.g. 7 points in
//    (kn_p, mu_pp), 5 points in (Cn, Cs)), one plane per target, solve, validate once.
//  * sequential mode (trust region): start from n+1 points (the centre and one step per
//    parameter), fit a plane on the points nearest the current best, solve inside
//    [best - r, best + r] intersected with the bounds, evaluate the predicted solution (it
//    is both a new design point and the validation run); stop when every target is hit
//    within its measurement uncertainty or the run budget is spent. r doubles after an
//    improvement and halves otherwise.
//
// Realisation scatter (Problem::replicates = R >= 2). A DEM target at fixed parameters is
// one draw from the packings its seed can make (and from its chaotic dynamics), with
// standard deviation s_i. The loop measures s_i from R + 1 realisations (seeds seed, seed +
// 1, .., seed + R) at one point, batched with other runs:
//  * paper mode, at the solution: the mean of the n = R + 1 realisations is validated
//    against sqrt(u_i^2 + s_i^2 / n + o_i (1 - 2 / n)), o_i = max(0, s_i^2 - sigma_s,i^2) the
//    part of the scatter the design's surfaces do not show in their residual sigma_s (a
//    design sharing one packing carries one common offset of std ~s, which moves the
//    solution and which realisation 0 shares; a design of independently settled runs shows
//    its scatter in the residual and o ~ 0);
//  * sequential mode, at the first start point, before refining (assumed to hold across the
//    range): a single run is a hit when |y_i - t_i| <= sqrt(u_i^2 + s_i^2); refining below
//    the scatter buys nothing, since any one realisation is off by ~s.
// Replicates are never fitted nor chosen as the best run; they count in the runs used, not
// in sequential.max_runs. Without them (R = 0) the scatter is unknown and taken as zero.
//
// Parameter uncertainty (first order): dx = G dy with G = (J^T W J)^-1 J^T W, J = dsurface/dx
// at the solution, W = S_t^-1, so cov(x) = G (S_t + S_s) G^T with S_t = D R D the
// measurement covariance (D = diag(sigma_target), R = Problem::target_correlation, the
// identity when empty) and S_s = diag(s_residual^2) (surface error).
// For as many targets as parameters G = J^-1. With a measured scatter, cov(x) gains
// G diag(o) G^T, o the scatter the surfaces do not show (see above).
//
// The loops are here (calibrate.cpp); the solver on the surfaces is in surface_solver.hpp,
// the parameter uncertainty and the determination warnings in uncertainty.hpp, the
// realisations and their scatter in replicates.hpp, the surfaces' Jacobian in sensitivity.hpp.
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "calibration/replicates.hpp"
#include "calibration/response_surface.hpp"

namespace colza::calibration {

struct Parameter {
  std::string name;   // short name, e.g. "kn_p"
  std::string key;    // config key the DEM sets, e.g. "particle.normal_stiffness"
  std::string unit;
  double lower = 0.0, upper = 0.0;  // bounds = the design's range unless the spec says otherwise
};

struct Target {
  std::string name;   // e.g. "c1"
  std::string unit;
  double value = 0.0;
  double uncertainty = 0.0;  // one standard deviation, > 0
};

// How the sequential search ranks its runs (the best is the trust region's centre and the
// solution) and when it stops (the best run's misfit <= 1):
//  kWorstTarget: max_i |y_i - t_i| / tol_i: every target within its tolerance, the
//    calibration's acceptance;
//  kRootMeanSquare: sqrt(r^T S^-1 r / n), S = D R D with D = diag(tol) and R the targets'
//    correlation, r = y - t: the weighted least squares the surrogate's step minimises, and
//    what a chi-square test judges (the diagnosis). With one target far off, the worst target
//    ranks runs by that target alone and leaves the others where its error is least.
enum class RunRanking { kWorstTarget, kRootMeanSquare };

struct Problem {
  std::vector<Parameter> parameters;
  std::vector<Target> targets;
  std::vector<Eigen::VectorXd> design;           // paper mode: the design points
  std::vector<Eigen::VectorXd> sequential_start;  // sequential mode: empty = centre + one step per parameter
  SurfaceKind surface = SurfaceKind::kAuto;
  int max_runs = 12;                              // sequential mode budget (design + refinement runs)
  RunRanking ranking = RunRanking::kWorstTarget;  // sequential mode: how runs are ranked and when the search stops
  int replicates = 0;                             // extra realisations (seeds) to measure the scatter; 0 = off, else >= 2
  // Correlation of the measured targets' errors (targets x targets; empty: independent).
  // Targets derived from one fit are correlated: C and tan(Phi) from one line through the
  // same strengths (line_fit_correlation). It enters the solver's weights (W = S_t^-1) and
  // the propagated measurement covariance; the surface residuals and the realisation
  // scatter stay independent per target, and the validation judges each target on its own
  // tolerance.
  Eigen::MatrixXd target_correlation;
  Eigen::VectorXd lower() const;
  Eigen::VectorXd upper() const;
};

// Correlation of the intercept and the slope of a least-squares line through points at
// abscissae x with independent errors of equal variance: Cov = s^2 (X^T X)^-1, so
// rho = -sum(x) / sqrt(n sum(x^2)) (-0.89 for the paper's loads 25.75 and 78.75 kPa, -0.94
// for all four). The 2 x 2 matrix [[1, rho], [rho, 1]].
Eigen::MatrixXd line_fit_correlation(const std::vector<double>& x);

// The forward model (ForwardModel, ReplicateModel) and the realisation scatter
// (realisation_scatter, evaluate_with_replicates): replicates.hpp.

// A target the surfaces cannot reach inside the bounds, or a design that cannot be fitted.
// `key` names what to change (the target or the design).
class CalibrationError : public std::runtime_error {
 public:
  CalibrationError(std::string key, const std::string& reason) : std::runtime_error(reason), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

struct Run {
  Eigen::VectorXd x, y;
  std::string role;   // "design" | "refinement" | "validation" | "replicate" | "confirmation"
  int iteration = 0;
  int replicate = 0;  // realisation (0: the model's own seed)
};

struct CalibrationResult {
  std::string mode;                     // "paper" | "sequential"
  Eigen::VectorXd solution;             // parameters (SI)
  Eigen::VectorXd sigma_target;         // parameter std from the measurement uncertainty
  Eigen::VectorXd sigma_surface;        // parameter std from the surfaces' residual error
  Eigen::VectorXd sigma_scatter;        // parameter std from the realisation scatter (0 when not measured)
  Eigen::VectorXd sigma;                // combined
  Eigen::MatrixXd jacobian;             // d surface / d x at the solution (targets x parameters)
  Eigen::VectorXd predicted;            // surfaces at the solution
  Eigen::VectorXd achieved;             // the validation at the solution (paper mode with replicates: their mean)
  Eigen::VectorXd error;                // achieved - measured
  Eigen::VectorXd tolerance;            // what |error_i| was judged against (uncertainty, with scatter if measured)
  bool within_uncertainty = false;      // |error_i| <= tolerance_i for all i (sequential: and the confirmation)
  // Sequential mode without replicates: another realisation (seed + 1) at the solution, run
  // once the search has stopped within the tolerance (its best run was selected among
  // several, so its success is partly luck); empty when not run.
  Eigen::VectorXd confirmation;
  double confirmation_misfit = 0.0;     // normalised misfit of the confirmation (<= 1: within)
  // Realisation scatter (Problem::replicates > 0): per-target sample std over the
  // realisations at scatter_at; empty when not measured.
  Eigen::VectorXd scatter;
  Eigen::VectorXd scatter_at;
  std::vector<Run> runs;                // every forward evaluation, in order
  std::vector<ResponseSurface> surfaces;  // the surfaces used for the final solution
  std::vector<std::size_t> surface_points;  // indices into runs the final surfaces were fitted on
  int iterations = 0;                   // paper: 1; sequential: refinement runs made
  std::vector<std::string> warnings;
  std::size_t forward_runs() const { return runs.size(); }
};

struct LoopOptions {
  int jobs = 1;  // concurrent evaluations of a batch of design points
  // Called after each evaluation (progress / logging); may be empty.
  std::function<void(const Run&)> on_run;
  // Required when Problem::replicates > 0.
  ReplicateModel replicate_model;
};

// Evaluates every point, up to `jobs` at once; results in input order.
std::vector<Eigen::VectorXd> evaluate_batch(const ForwardModel& model, const std::vector<Eigen::VectorXd>& points,
                                            int jobs);

// Checks the problem (sizes, bounds, uncertainties); throws CalibrationError.
void validate_problem(const Problem& problem, bool sequential);

CalibrationResult calibrate_paper(const Problem& problem, const ForwardModel& model, const LoopOptions& options);
CalibrationResult calibrate_sequential(const Problem& problem, const ForwardModel& model, const LoopOptions& options);

// Weighted misfit max_i |y_i - t_i| / sigma_i (<= 1: within the measurement uncertainty).
double normalised_misfit(const Problem& problem, const Eigen::VectorXd& y);
// Same against a tolerance per target.
double normalised_misfit(const Problem& problem, const Eigen::VectorXd& y, const Eigen::VectorXd& tolerance);
// The misfit `problem.ranking` ranks runs by (RunRanking), against a tolerance per target.
double ranking_misfit(const Problem& problem, const Eigen::VectorXd& y, const Eigen::VectorXd& tolerance);
// What one run's error is judged against: sqrt(u_i^2 + s_i^2), or u_i when `scatter` is empty.
Eigen::VectorXd single_run_tolerance(const Problem& problem, const Eigen::VectorXd& scatter);

}  // namespace colza::calibration
