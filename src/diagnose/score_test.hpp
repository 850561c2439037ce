// Which candidate mechanism points along the residual? (colza diagnose, step 2.)
//
// In whitened units (noise_model.hpp: e = L^-1 r the residual, G = L^-1 J the baseline's
// sensitivities, h_k = L^-1 g_k candidate k's signature), what re-fitting the baseline's
// own parameters can absorb is the column space of G. P = I - G (G^T G)^+ G^T projects on
// its complement; a candidate can only explain P h_k = h_k_perp, and the fraction
// 1 - |h_perp|^2 / |h|^2 of its signature is absorbed by the baseline's parameters.
//
// Score test of phi_k = neutral against phi_k > neutral (the physics allows one sign: a
// friction, a damping ratio, a bond strength cannot be negative; signatures are taken
// toward the allowed side): z_k = h_perp . e / |h_perp|, standard normal under the null
// (e ~ N(0, P) after the fit), one-sided p_k = P(Z >= z_k). Under the null the z_k are jointly
// normal with unit variances and correlations cos(h_perp_i, h_perp_j), so the p-values are
// adjusted for testing K candidates by the single-step max-T method (Westfall & Young 1993,
// "Resampling-based multiple testing", section 2.6): p_k_adj = P(max_j Z_j >= z_k) under that
// law, by Monte Carlo. Two candidates with the same signature count as one test, where a
// Bonferroni or Holm correction would count them twice.
// Linearised estimate phi_k - neutral = h_perp . e / |h_perp|^2, standard deviation 1 / |h_perp|.
// The cosine matrix of the h_perp says which candidates the data cannot tell apart.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "diagnose/noise_model.hpp"
#include "diagnose/signature.hpp"

namespace colza::diagnose {

struct CandidateScore {
  double z = 0.0;                   // score statistic (noise units)
  double p_value = 1.0;             // one-sided
  double adjusted_p = 1.0;          // max-T over the candidates
  double absorbed_fraction = 0.0;   // of the signature, by re-fitting the baseline's parameters
  double alignment = 0.0;           // cos(h_perp, P e): the share of the residual's direction it explains
  double estimate = 0.0;            // linearised phi - neutral (parameter units)
  double estimate_sd = 0.0;         // 1 / |h_perp|
  double signal_to_noise = 0.0;     // |h_perp| / |P L^-1 se|: the signature against its own estimation error
  double reach = 0.0;               // |h_perp| (upper - neutral): the largest misfit it can remove, noise units
};

struct ScoreTests {
  std::vector<CandidateScore> scores;  // one per candidate, in the candidates' order
  Eigen::MatrixXd cosine;              // cos(h_perp_i, h_perp_j)
  Eigen::VectorXd projected_residual;  // P e (whitened): what no baseline re-fit removes
};

// `ranges[k]` = upper - neutral of candidate k's parameter.
ScoreTests score_candidates(const NoiseModel& noise, const Eigen::MatrixXd& baseline_sensitivity,
                            const std::vector<Signature>& signatures, const std::vector<double>& ranges,
                            const Eigen::VectorXd& residual);

// Single-step max-T adjusted one-sided p-values of statistics z with null correlation C:
// the share of `draws` samples Z ~ N(0, C) (a fixed seed: the same answer every time) whose
// largest component reaches z_k.
std::vector<double> max_t_adjusted(const std::vector<double>& z, const Eigen::MatrixXd& correlation, int draws = 200000);

// The projector on the complement of the columns of g (whitened sensitivities).
Eigen::MatrixXd complement_projector(const Eigen::MatrixXd& g);

}  // namespace colza::diagnose
