// Realisation scatter in the calibration loop (calibrate.hpp), on an IDENTITY MODEL with a
// known scatter: the linear model of test_calibration_identity.cpp plus a deterministic
// pseudo-random offset per (point, realisation), uniform in [-delta, delta] (std delta/sqrt 3),
// which stands in for the DEM's chaotic dependence on the packing: any change of the
// parameters or of the seed gives another draw. Checks that the scatter is measured from
// the replicates, that it enters the tolerance and the parameter uncertainty as documented,
// that the sequential mode stops chasing it, that a noise-free model gives the same answer
// with and without replicates, and the spec key [scatter] replicates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "calibration/calibrate.hpp"
#include "calibration/spec.hpp"
#include "config/config_error.hpp"

using namespace colza;
using namespace colza::calibration;

namespace {

const Eigen::Matrix2d kA = (Eigen::Matrix2d() << 0.9, -4e5, 50.0, 1.2e8).finished();
const Eigen::Vector2d kB(2e4, 1e7);
const Eigen::Vector2d kTruth(437e3, 0.34);
const Eigen::Vector2d kTarget = kA * kTruth + kB;          // c1 = 2.9e5 N/m, c2 = 6.265e7 N/m^2
const Eigen::Vector2d kDelta = 0.03 * kTarget.cwiseAbs();  // scatter half width: 3 % (std 1.7 %)

// Uniform in [-1, 1] from the bits of x, the realisation and the target (splitmix64).
double draw(const Eigen::VectorXd& x, int realisation, int target) {
  std::uint64_t h = 0x9e3779b97f4a7c15ull * static_cast<std::uint64_t>(realisation * 2 + target + 1);
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    std::uint64_t bits;
    std::memcpy(&bits, &x[j], sizeof bits);
    h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  }
  h += 0x9e3779b97f4a7c15ull;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  h ^= h >> 31;
  return 2.0 * static_cast<double>(h >> 11) / 9007199254740992.0 - 1.0;
}

Eigen::VectorXd noisy(const Eigen::VectorXd& x, int realisation) {
  Eigen::VectorXd y = kA * x + kB;
  for (int i = 0; i < 2; ++i) y[i] += kDelta[i] * draw(x, realisation, i);
  return y;
}

Problem compression_problem(double relative_uncertainty) {
  Problem p;
  p.parameters = {{"kn_p", "particle.normal_stiffness", "N/m", 300e3, 600e3}, {"mu_pp", "particle.friction", "-", 0.2, 0.5}};
  p.targets = {{"c1", "N/m", kTarget[0], relative_uncertainty * std::abs(kTarget[0])},
               {"c2", "N/m^2", kTarget[1], relative_uncertainty * kTarget[1]}};
  const double pts[7][2] = {{300e3, 0.4}, {400e3, 0.2}, {400e3, 0.3}, {400e3, 0.4}, {400e3, 0.5}, {500e3, 0.4}, {600e3, 0.4}};
  for (auto& x : pts) p.design.push_back(Eigen::Vector2d(x[0], x[1]));
  return p;
}

LoopOptions with_replicates(const ReplicateModel& m) {
  LoopOptions o;
  o.replicate_model = m;
  return o;
}

int count_role(const CalibrationResult& r, const std::string& role) {
  int n = 0;
  for (const auto& run : r.runs) n += run.role == role ? 1 : 0;
  return n;
}

}  // namespace

TEST(CalibrationScatter, PaperModeMeasuresTheScatterAndValidatesTheMean) {
  Problem p = compression_problem(0.01);
  p.replicates = 5;
  const ForwardModel model = [](const Eigen::VectorXd& x) { return noisy(x, 0); };
  const CalibrationResult r = calibrate_paper(p, model, with_replicates(noisy));
  ASSERT_EQ(r.runs.size(), 7u + 1u + 5u);
  EXPECT_EQ(count_role(r, "replicate"), 5);
  // The scatter is the sample std (n - 1) of the validation and its five replicates...
  std::vector<Eigen::VectorXd> at_solution;
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(2);
  for (const auto& run : r.runs)
    if (run.role == "validation" || run.role == "replicate") {
      EXPECT_EQ((run.x - r.solution).norm(), 0.0);
      at_solution.push_back(run.y);
      mean += run.y;
    }
  ASSERT_EQ(at_solution.size(), 6u);
  mean /= 6.0;
  const Eigen::VectorXd s = realisation_scatter(at_solution);
  ASSERT_EQ(r.scatter.size(), 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_DOUBLE_EQ(r.scatter[i], s[i]);
    // ... an estimate of delta / sqrt(3) from six draws (deterministic here: 0.2 .. 1.2 delta).
    EXPECT_GT(r.scatter[i], 0.2 * kDelta[i]);
    EXPECT_LT(r.scatter[i], 1.2 * kDelta[i]);
    // The validation is the mean of the realisations, judged against sqrt(u^2 + s^2 / 6).
    EXPECT_NEAR(r.achieved[i], mean[i], 1e-12 * std::abs(mean[i]));
    EXPECT_NEAR(r.tolerance[i], std::sqrt(std::pow(p.targets[i].uncertainty, 2) + s[i] * s[i] / 6.0),
                1e-12 * r.tolerance[i]);
  }
  EXPECT_EQ(r.within_uncertainty, normalised_misfit(p, r.achieved, r.tolerance) <= 1.0);
  // The parameter uncertainty: the three sources in quadrature, the scatter one not zero.
  for (int j = 0; j < 2; ++j) {
    EXPECT_GT(r.sigma_scatter[j], 0.0);
    EXPECT_NEAR(r.sigma[j] * r.sigma[j],
                r.sigma_target[j] * r.sigma_target[j] + r.sigma_surface[j] * r.sigma_surface[j] +
                    r.sigma_scatter[j] * r.sigma_scatter[j],
                1e-9 * r.sigma[j] * r.sigma[j]);
    // And it covers the actual error of the solution.
    EXPECT_LT(std::abs(r.solution[j] - kTruth[j]), 3.0 * r.sigma[j]) << j;
  }
}

TEST(CalibrationScatter, SequentialModeStopsChasingTheScatter) {
  // Uncertainty 0.5 %, scatter std ~1.7 %: a single run hits the bare uncertainty only by luck.
  Problem p = compression_problem(0.005);
  p.max_runs = 12;
  const ForwardModel model = [](const Eigen::VectorXd& x) { return noisy(x, 0); };
  const CalibrationResult blind = calibrate_sequential(p, model, {});
  p.replicates = 3;
  const CalibrationResult aware = calibrate_sequential(p, model, with_replicates(noisy));
  EXPECT_EQ(count_role(aware, "replicate"), 3);
  ASSERT_EQ(aware.scatter.size(), 2);
  EXPECT_EQ((aware.scatter_at - aware.runs[0].x).norm(), 0.0);  // measured at the first start point
  EXPECT_TRUE(aware.within_uncertainty);
  const int aware_search = static_cast<int>(aware.runs.size()) - 3;
  EXPECT_LT(aware_search, p.max_runs);
  for (int i = 0; i < 2; ++i)  // a single run: sqrt(u^2 + s^2)
    EXPECT_NEAR(aware.tolerance[i], std::hypot(p.targets[i].uncertainty, aware.scatter[i]), 1e-12 * aware.tolerance[i]);
  for (int j = 0; j < 2; ++j) EXPECT_LT(std::abs(aware.solution[j] - kTruth[j]), 3.0 * aware.sigma[j]) << j;
  std::printf("scatter std %.3g %%, %.3g %% of the targets; without replicates: %zu runs, within %d; with 3: %zu runs "
              "(%d searching), within %d\n",
              100.0 * aware.scatter[0] / kTarget[0], 100.0 * aware.scatter[1] / kTarget[1], blind.runs.size(),
              blind.within_uncertainty, aware.runs.size(), aware_search, aware.within_uncertainty);
  // Replicates are not design points: none is chosen as the validation or fitted.
  for (std::size_t k : aware.surface_points) EXPECT_NE(aware.runs[k].role, "replicate");
}

TEST(CalibrationScatter, NoiseFreeModelGivesTheSameAnswerWithReplicates) {
  const ForwardModel exact = [](const Eigen::VectorXd& x) -> Eigen::VectorXd { return kA * x + kB; };
  const ReplicateModel exact_k = [](const Eigen::VectorXd& x, int) -> Eigen::VectorXd { return kA * x + kB; };
  Problem p = compression_problem(0.01);
  const CalibrationResult plain = calibrate_paper(p, exact, {});
  p.replicates = 2;
  const CalibrationResult with = calibrate_paper(p, exact, with_replicates(exact_k));
  EXPECT_EQ(with.scatter, Eigen::VectorXd::Zero(2));
  EXPECT_EQ(with.solution, plain.solution);
  EXPECT_EQ(with.sigma, plain.sigma);
  EXPECT_EQ(with.tolerance, plain.tolerance);
  EXPECT_EQ(with.runs.size(), plain.runs.size() + 2);
}

TEST(CalibrationScatter, ReplicatesNeedAModelWithOtherRealisations) {
  Problem p = compression_problem(0.01);
  p.replicates = 2;
  const ForwardModel model = [](const Eigen::VectorXd& x) { return noisy(x, 0); };
  try {
    calibrate_paper(p, model, {});
    FAIL() << "no error";
  } catch (const CalibrationError& e) {
    EXPECT_EQ(e.key(), "scatter.replicates");
  }
}

TEST(CalibrationScatter, SpecKeyReplicates) {
  const auto dir = std::filesystem::temp_directory_path() / "colza-test-scatter-spec";
  std::filesystem::create_directories(dir);
  auto spec_with = [&](const std::string& scatter) {
    const auto file = dir / "spec.toml";
    std::ofstream(file) << "stage = \"shear\"\n[model]\nconfig = \"" COLZA_SOURCE_DIR "/tests/data/small_shear.toml\"\n"
                           "[[parameters]]\nname = \"Cn\"\nkey = \"contact.contact_bond.normal_strength\"\n"
                           "design = [0.5, 1.5, 2.5]\n[[parameters]]\nname = \"Cs\"\n"
                           "key = \"contact.contact_bond.shear_strength\"\ndesign = [3.0, 2.0, 3.0]\n"
                           "[measured]\nresults = \"" COLZA_SOURCE_DIR "/data/measured/shear_strength_paper_line.csv\"\n"
                           "cohesion_uncertainty = 500.0\ntan_phi_uncertainty = 0.02\n" + scatter;
    return file.string();
  };
  auto error = [&](const std::string& scatter) -> std::string {
    try {
      read_spec(spec_with(scatter));
    } catch (const ConfigError& e) {
      return e.key() + " | " + e.reason();
    }
    return "no error";
  };
  EXPECT_EQ(read_spec(spec_with("")).problem.replicates, 0);
  EXPECT_EQ(read_spec(spec_with("[scatter]\nreplicates = 3\n")).problem.replicates, 3);
  EXPECT_EQ(error("[scatter]\nreplicates = -1\n").rfind("scatter.replicates | must be between 0 and 50", 0), 0u);
  EXPECT_EQ(error("[scatter]\nreplicates = 1.5\n").rfind("scatter.replicates | must be a whole number", 0), 0u);
  EXPECT_EQ(error("[scatter]\nseeds = 3\n").rfind("scatter.seeds | unknown key", 0), 0u);
  std::filesystem::remove_all(dir);
}
