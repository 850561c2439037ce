// The diagnosis's statistical pieces (src/diagnose) against closed forms and exact cases.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "diagnose/adequacy.hpp"
#include "diagnose/held_out.hpp"
#include "diagnose/mechanism_kind.hpp"
#include "diagnose/model_comparison.hpp"
#include "diagnose/noise_model.hpp"
#include "diagnose/score_test.hpp"
#include "diagnose/signature.hpp"

using namespace colza::diagnose;

TEST(DiagnoseStatistics, ChiSquareAndNormalTailsMatchTables) {
  // P(chi2_1 >= 3.841459) = 0.05, P(chi2_5 >= 11.0705) = 0.05, P(Z >= 1.644854) = 0.05.
  EXPECT_NEAR(chi_square_survival(3.841459, 1), 0.05, 1e-6);
  EXPECT_NEAR(chi_square_survival(11.0705, 5), 0.05, 1e-5);
  EXPECT_NEAR(normal_survival(1.644854), 0.05, 1e-6);
  EXPECT_DOUBLE_EQ(chi_square_survival(0.0, 3), 1.0);
}

TEST(DiagnoseStatistics, MaxTAdjustmentBetweenIndependenceAndIdentity) {
  // z = 2.326348 (p = 0.01). Three independent tests: P(max >= z) = 1 - 0.99^3 = 0.029701
  // (Sidak); three identical ones: 0.01. Monte Carlo error of 2e5 draws: ~4e-4.
  const std::vector<double> z(3, 2.326348);
  EXPECT_NEAR(max_t_adjusted(z, Eigen::MatrixXd::Identity(3, 3))[0], 0.029701, 1.5e-3);
  EXPECT_NEAR(max_t_adjusted(z, Eigen::MatrixXd::Ones(3, 3))[0], 0.01, 1e-3);
  // Two of three alike: between, close to two independent tests (1 - 0.99^2 = 0.0199).
  Eigen::MatrixXd c = Eigen::MatrixXd::Identity(3, 3);
  c(0, 1) = c(1, 0) = 1.0;
  EXPECT_NEAR(max_t_adjusted(z, c)[0], 0.0199, 1.5e-3);
}

TEST(DiagnoseStatistics, BoundaryLikelihoodRatioIsHalfTheChiSquareTail) {
  // D = 3.841459: half of P(chi2_1 >= D) = 0.025 (Self & Liang's 1/2 chi2_0 + 1/2 chi2_1).
  EXPECT_NEAR(boundary_likelihood_ratio_p(13.841459, 10.0), 0.025, 1e-6);
  EXPECT_DOUBLE_EQ(boundary_likelihood_ratio_p(10.0, 12.0), 1.0);
  EXPECT_NEAR(bayesian_information_criterion(4.0, 2, 8) - bayesian_information_criterion(4.0, 1, 8), std::log(8.0), 1e-12);
}

TEST(DiagnoseStatistics, NoiseModelAddsMeasurementAndCorrectedScatter) {
  // Realisations +-1 around 10 in feature 0 (sample variance 4/3 for n = 4: ((1+1+1+1)/3)),
  // constant feature 1: Sigma_00 = u0^2 + (1 + 1/4) (3/1) (4/3), Sigma_11 = u1^2.
  const std::vector<Eigen::VectorXd> ys = {Eigen::Vector2d(11, 5), Eigen::Vector2d(9, 5), Eigen::Vector2d(11, 5),
                                           Eigen::Vector2d(9, 5)};
  const NoiseModel n = make_noise_model(Eigen::Vector2d(0.5, 0.2), {}, ys);
  EXPECT_NEAR(n.covariance(0, 0), 0.25 + 1.25 * 3.0 * 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(n.covariance(1, 1), 0.04, 1e-15);
  EXPECT_NEAR(n.covariance(0, 1), 0.0, 1e-15);
  // Whitening: L^-1 Sigma L^-T = I.
  const Eigen::MatrixXd w = n.whitener * n.covariance * n.whitener.transpose();
  EXPECT_TRUE(w.isApprox(Eigen::MatrixXd::Identity(2, 2), 1e-12));
  // A measured value that is the mean of 3 lab samples counts their scatter 1/3:
  // Sigma_00 = u0^2 + (1/3 + 1/4) (3/1) (4/3).
  const NoiseModel mean_of_three = make_noise_model(Eigen::Vector2d(0.5, 0.2), {}, ys, Eigen::Vector2d(3, 3));
  EXPECT_NEAR(mean_of_three.covariance(0, 0), 0.25 + (1.0 / 3.0 + 0.25) * 3.0 * 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(mean_of_three.covariance(1, 1), 0.04, 1e-15);
}

TEST(DiagnoseStatistics, ShrinkageKeepsStrongCorrelationAndDropsNoise) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> z;
  // Feature 1 = feature 0 + small noise: strongly correlated, little shrinkage.
  std::vector<Eigen::VectorXd> correlated, independent;
  for (int k = 0; k < 8; ++k) {
    const double a = z(rng);
    correlated.push_back(Eigen::Vector2d(a, a + 0.05 * z(rng)));
    independent.push_back(Eigen::Vector3d(z(rng), z(rng), z(rng)));
  }
  double lambda_c = 0.0, lambda_i = 0.0;
  shrunk_covariance(correlated, lambda_c);
  shrunk_covariance(independent, lambda_i);
  EXPECT_LT(lambda_c, 0.2);
  EXPECT_GT(lambda_i, 0.3);
}

TEST(DiagnoseStatistics, CommonRandomNumbersCancelTheRealisationNoise) {
  // y_s(phi) = 2 + 3 phi + noise_s: the per-seed differences are exact, the error zero.
  std::vector<Eigen::VectorXd> a, b;
  for (int s = 0; s < 4; ++s) {
    const double noise = 0.1 * s - 0.13;
    a.push_back(Eigen::VectorXd::Constant(1, 2.0 + noise));
    b.push_back(Eigen::VectorXd::Constant(1, 2.0 + 3.0 * 0.5 + noise));
  }
  const Signature g = signature_from_pairs(a, b, 0.5);
  EXPECT_NEAR(g.mean[0], 3.0, 1e-12);
  EXPECT_NEAR(g.standard_error[0], 0.0, 1e-12);
}

TEST(DiagnoseStatistics, ScoreTestProjectsOutWhatTheBaselineAbsorbs) {
  // Unit noise, baseline sensitivity along e0. Candidate A = e0 + e1 (half absorbed),
  // candidate B = e0 (all absorbed). Residual 3 e1: z_A = (e1 . 3 e1) / |e1| = 3.
  NoiseModel n;
  n.covariance = Eigen::MatrixXd::Identity(3, 3);
  n.sd = Eigen::VectorXd::Ones(3);
  n.whitener = Eigen::MatrixXd::Identity(3, 3);
  const Eigen::MatrixXd J = Eigen::Vector3d(1, 0, 0);
  Signature a{Eigen::Vector3d(1, 1, 0), Eigen::Vector3d::Zero(), 4};
  Signature b{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::Zero(), 4};
  const ScoreTests t = score_candidates(n, J, {a, b}, {2.0, 2.0}, Eigen::Vector3d(0.7, 3.0, 0.0));
  EXPECT_NEAR(t.scores[0].z, 3.0, 1e-12);
  EXPECT_NEAR(t.scores[0].absorbed_fraction, 0.5, 1e-12);
  EXPECT_NEAR(t.scores[0].estimate, 3.0, 1e-12);
  EXPECT_NEAR(t.scores[0].reach, 2.0, 1e-12);
  EXPECT_NEAR(t.scores[0].alignment, 1.0, 1e-12);
  EXPECT_NEAR(t.scores[1].absorbed_fraction, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(t.scores[1].p_value, 0.5);  // z = 0
  EXPECT_NEAR(t.scores[0].p_value, normal_survival(3.0), 1e-15);
  // B's projected signature is zero: its z is 0 whatever the data, it is no test, and A's
  // adjusted p is its own (Monte Carlo error ~8e-5 at 2e5 draws).
  EXPECT_NEAR(t.scores[0].adjusted_p, normal_survival(3.0), 2.5e-4);
}

TEST(DiagnoseStatistics, HeldOutPredictionOfAnExactLinearModel) {
  // m = y0 + A d exactly: every held-out test is predicted without error.
  Eigen::MatrixXd A(4, 1);
  A << 1, 2, 3, 4;
  const Eigen::VectorXd y0 = Eigen::VectorXd::Zero(4), sd = Eigen::VectorXd::Ones(4);
  const Eigen::VectorXd m = 0.5 * A.col(0);
  EXPECT_NEAR(held_out_rms(m, y0, sd, A, {true, true, false, false}), 0.0, 1e-12);
  // An offset in the held-out feature alone: its error is the offset over the prediction's sd,
  // sqrt(1 + 1^2 / (2^2 + 3^2 + 4^2)) = sqrt(30 / 29) noise units.
  Eigen::VectorXd m2 = m;
  m2[0] += 2.0;
  EXPECT_NEAR(held_out_rms(m2, y0, sd, A, {true, false, false, false}), 2.0 / std::sqrt(30.0 / 29.0), 1e-12);
  // A parameter the kept features hardly feel (sensitivity 1e-3 there, 1 in the held-out
  // feature): the prediction is uncertain, so an offset of 2 is well within it.
  Eigen::MatrixXd B(4, 2);
  B << 1, 1, 2, 1e-3, 3, 0, 4, 0;
  Eigen::VectorXd m3 = Eigen::VectorXd::Zero(4);
  m3[0] = 2.0;
  EXPECT_LT(held_out_rms(m3, y0, sd, B, {true, false, false, false}), 0.01);
  // Not felt at all by the kept features: no prediction.
  B(1, 1) = 0.0;
  EXPECT_TRUE(std::isnan(held_out_rms(m3, y0, sd, B, {true, false, false, false})));
  EXPECT_TRUE(std::isnan(held_out_rms(m, y0, sd, A, {true, true, true, true})));
}

TEST(DiagnoseStatistics, SeparatingExperimentsFollowPhysicsSectionEight) {
  EXPECT_NE(separating_experiment(MechanismKind::kHertz, MechanismKind::kElastoPlastic).find("load-unload"), std::string::npos);
  EXPECT_NE(separating_experiment(MechanismKind::kCohesion, MechanismKind::kRollingResistance).find("repose"), std::string::npos);
  EXPECT_NE(separating_experiment(MechanismKind::kViscous, MechanismKind::kHertz).find("speeds"), std::string::npos);
  EXPECT_EQ(mechanism_kind_of({"contact.rolling=elastic_plastic"}), MechanismKind::kRollingResistance);
  EXPECT_EQ(mechanism_kind_of({"contact.bond=load_induced"}), MechanismKind::kCohesion);
  EXPECT_EQ(mechanism_kind_of({"contact.normal=walton_braun"}), MechanismKind::kElastoPlastic);
}

TEST(DiagnoseStatistics, ANoDiscrepancyVerdictNamesTheCandidatesItsTestsCannotSee) {
  // physics.md section 8: the test that shows each mechanism apart from the baseline's own
  // parameters; named only when no feature comes from it.
  const std::vector<std::string> oedometer_and_shear{"bulk_density", "cycle1/rebound_strain", "branch2/modulus@20000Pa",
                                                     "cohesion", "tan_phi"};
  EXPECT_NE(unseen_by(MechanismKind::kRollingResistance, oedometer_and_shear).find("angle of repose"), std::string::npos);
  EXPECT_EQ(unseen_by(MechanismKind::kRollingResistance, {"angle_of_repose_deg", "cohesion"}), "");
  EXPECT_EQ(unseen_by(MechanismKind::kElastoPlastic, oedometer_and_shear), "");
  EXPECT_NE(unseen_by(MechanismKind::kElastoPlastic, {"c1", "c2"}).find("load-unload cycle"), std::string::npos);
  EXPECT_NE(unseen_by(MechanismKind::kHertz, oedometer_and_shear).find("two stresses"), std::string::npos);
  EXPECT_EQ(unseen_by(MechanismKind::kHertz, {"branch1/modulus@20000Pa", "branch1/modulus@40000Pa"}), "");
  EXPECT_NE(unseen_by(MechanismKind::kViscous, oedometer_and_shear).find("--speeds"), std::string::npos);
  EXPECT_EQ(unseen_by(MechanismKind::kCohesion, oedometer_and_shear), "");
}
