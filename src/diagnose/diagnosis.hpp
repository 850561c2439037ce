// colza diagnose: given measured features, what does the calibrated model get wrong, which
// candidate mechanism explains it, and what does adding it gain. The procedure (each step's
// equations are in the header it uses):
//  1. calibrate the baseline to the features (calibration::calibrate_sequential), run R
//     realisations at the fit, judge the residual against the noise (noise_model.hpp,
//     adequacy.hpp); an adequate baseline ends the diagnosis;
//  2. measure the baseline's sensitivities and every candidate's signature at the fit by
//     common random numbers (signature.hpp) and test each candidate against the residual
//     the baseline cannot absorb (score_test.hpp);
//  3. calibrate the leading candidates' extended models (baseline parameters and the
//     mechanism's together), judge them as in 1 and compare them with the baseline and
//     with each other (model_comparison.hpp), and predict each test held out (held_out.hpp);
//  4. decide (verdict.hpp).
// The forward model is any function of (parameters, candidate, strength, realisation): the
// DEM (diagnose_dem.hpp) or an analytic model in the tests.
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"
#include "diagnose/adequacy.hpp"
#include "diagnose/mechanism_kind.hpp"
#include "diagnose/noise_model.hpp"
#include "diagnose/score_test.hpp"
#include "diagnose/signature.hpp"

namespace colza::diagnose {

struct Feature {
  std::string name;          // e.g. "cohesion", "load_unload.permanent_strain"
  std::string unit;
  std::string test;          // the lab test (or load) it comes from: the unit held out in step 3
  double measured = 0.0;
  double uncertainty = 0.0;  // standard uncertainty of the measurement (> 0)
  int samples = 1;           // lab samples the measured value is the mean of (their scatter counts 1/samples)
};

struct Candidate {
  std::string name;                   // e.g. "rolling_resistance"
  std::vector<std::string> settings;  // config settings that switch the mechanism on ("contact.rolling=elastic_plastic")
  calibration::Parameter parameter;   // its strength: key, unit, lower = the neutral value, upper = the physical top
  double probe = 0.0;                 // value the signature is measured at (lower < probe <= upper)
  MechanismKind kind = MechanismKind::kOther;
  double neutral() const { return parameter.lower; }
};

// A model to run: the baseline's parameters, and optionally one candidate at a strength.
struct ModelPoint {
  Eigen::VectorXd baseline;
  int candidate = -1;  // -1: the baseline alone
  double strength = 0.0;
};
// Features of realisation k (k = 0: the model's own seed; k >= 1: seed + k). Thread-safe.
using DiagnosisForward = std::function<Eigen::VectorXd(const ModelPoint&, int realisation)>;

struct DiagnosisSettings {
  int replicates = 8;               // R realisations at each fit (>= 2; >= 8 recommended)
  int signature_seeds = 4;          // common-random-number pairs per sensitivity, and per signature at first
  // A signature measured to a signal-to-noise (score_test.hpp) below the target gets more pairs,
  // doubling up to signature_seeds_max: how far a signature's direction can be trusted decides
  // both its score and whether two candidates look alike. 0: never add pairs.
  double signature_signal_to_noise = 3.0;
  int signature_seeds_max = 8;
  double significance = 0.01;       // alpha of every test
  double ambiguity_cosine = 0.9;    // |cos| of two projected signatures above which the data cannot tell them apart
  int calibration_runs = 12;        // budget of each calibration's sequential search
  int extend_at_most = 2;           // leading candidates whose extended models are calibrated
  double sensitivity_step = 0.1;    // fraction of a range: extended calibrations' first steps; baseline sensitivities without planes
  int jobs = 1;                     // forward evaluations side by side
  std::function<void(const std::string&)> on_progress;  // one line per stage; may be empty
};

struct DiagnosisProblem {
  std::vector<Feature> features;
  Eigen::MatrixXd measured_correlation;          // features x features; empty: independent
  std::vector<calibration::Parameter> parameters;  // the baseline's calibrated parameters
  std::vector<Candidate> candidates;
  DiagnosisSettings settings;
};

// One model calibrated and judged.
struct Fit {
  std::string model;              // "baseline" or the candidate's name
  Eigen::VectorXd parameters;     // the baseline's, then the candidate's strength when extended
  Eigen::VectorXd sigma;          // standard deviation of each under the noise, Gauss-Newton about the fit
  Eigen::VectorXd mean_features;  // over realisations 1..R at the fit
  std::vector<Eigen::VectorXd> realisation_features;  // realisations 1..R at the fit
  NoiseModel noise;
  Eigen::VectorXd refit_shift;    // the linearised refit's parameter shift (judged residual: m - ybar - A shift)
  std::vector<bool> held_at_bound;  // per parameter: the refit wanted to move it past its bound
  AdequacyTest adequacy;          // of the residual after the linearised refit
  bool strength_at_upper_bound = false;  // extended: the mechanism's strength pinned at its physical top
  int calibration_runs = 0;
  // d feature / d parameter of the least-squares plane through the calibration's runs at the
  // model's own seed (its design spans the ranges: common random numbers over steps the
  // scatter cannot hide); empty when they do not determine one.
  Eigen::MatrixXd design_sensitivity;
};

struct ExtendedFit {
  int candidate = -1;
  Fit fit;
  double chi_square_common = 0.0;  // under the baseline's noise, for the comparisons
  double likelihood_ratio_p = 1.0; // against the baseline (model_comparison.hpp)
  double bic = 0.0;                // under the baseline's noise
  Eigen::VectorXd start;           // where the kept search started (baseline parameters, then strength)
  int searches = 1;                // 2: the first search ended inadequate and a second began at the joint linearised fit
  // d features / d strength at the fit (common random numbers, half the probe's step): where
  // the response curves, the strength's sd comes from it rather than from the signature.
  Signature slope_at_fit;
};

struct HeldOutPrediction {
  std::string test;
  double rms_before = 0.0;  // baseline, noise units
  double rms_after = 0.0;   // extended model (the verdict's cause or the best extended)
};

enum class VerdictKind { kNoDiscrepancy, kExplained, kAmbiguous, kUnexplained };
const char* to_string(VerdictKind k);

struct Verdict {
  VerdictKind kind = VerdictKind::kNoDiscrepancy;
  int cause = -1;       // candidate index (explained, ambiguous)
  int runner_up = -1;   // ambiguous: the other candidate
  std::string experiment;  // ambiguous: the test that would separate them
  std::string text;        // one paragraph, for report.md
};

struct DiagnosisResult {
  Fit baseline;
  double baseline_bic = 0.0;
  Eigen::MatrixXd baseline_sensitivity;  // features x parameters, at the fit
  std::vector<Signature> signatures;     // per candidate, at the fit
  ScoreTests scores;
  std::vector<ExtendedFit> extended;
  std::vector<HeldOutPrediction> held_out;
  Verdict verdict;
  int forward_runs = 0;
  std::vector<std::string> warnings;
};

// Checks sizes, ranges and settings; throws calibration::CalibrationError naming the key.
void validate_diagnosis(const DiagnosisProblem& problem);

DiagnosisResult diagnose(const DiagnosisProblem& problem, const DiagnosisForward& model);

}  // namespace colza::diagnose
