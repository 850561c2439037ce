// DEM identity test of the compression stage of `colza calibrate` on the paper's full-size
// oedometer (label `full`; 12 min on 2 cores for the two tests under ctest, each process
// making the truth: paper 290 s, sequential 410 s in all). The "measured" curve is made by
// colza at known parameters other than the paper's, kn_p = 470 kN/m and mu_pp = 0.33
// (rho_p = 1230 kg/m^3, Table 1 otherwise), the way a lab would report it: five
// realisations of that truth, the curve of the one nearest their mean, their scatter as the uncertainties of c1 and c2 and
// the correlation of their errors (tests/integration/compression_truth.hpp). Every run,
// truth and design, loads one settled sample (oedometer.packing_file, seed 1), so a run is
// the loading alone (~22 s with two threads) and the design runs see the same packing as the
// truth; the scatter comes from the chaotic path, not from another packing.
//
// The design is the paper's seven points (physics.md section 5), as data/calibration/
// compression.toml; both modes share their runs (--runs).
//
// What it found (session 21; the same numbers by hand and under ctest): the five
// realisations give c1 = 9.72e5 +/- 1.98e4 N/m (2 %), c2 = 5.91e7 +/- 1.06e6 N/m^2 (1.8 %),
// correlation -0.99 (a stiffer start goes with a flatter rise). The paper procedure found
// kn_p = 465.1 +/- 19.8 kN/m and mu_pp = 0.349 +/- 0.046 (8 runs; "mu_pp is only weakly
// determined": its 95 % interval is wider than half the design's range 0.2-0.5; the
// validation missed c1 by 2.1 sigma), the sequential mode kn_p = 465.0 +/- 18.2 kN/m and
// mu_pp = 0.345 +/- 0.037 (10 runs, validation within 0.4 and 0.8 sigma); 8 min 43 s in all.
// So on the full-size sample the compression curve determines kn_p to ~4 % and mu_pp to
// ~12 %; on the 117-sphere sample (tests/integration/test_calibrate_dem.cpp) it did not.
//
// Stated tolerances: kn_p within 35 kN/m of the truth (~1.8 sigma; the design's mean kn_p,
// 429 kN/m, is 41 kN/m away, so a calibration that stayed at the design's centre fails);
// mu_pp within 2 of its own sigmas, and that sigma below 0.075 (a quarter of the range), so
// that a calibration that claims nothing does not pass.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cli_runner.hpp"
#include "compression_truth.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

constexpr double kTrueKn = 470e3, kTrueMu = 0.33;  // N/m, -

class CalibrateCompressionIdentity : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = scratch_dir("calibrate-compression-identity");
    fs::create_directories(dir_);
    const std::string config = source_path("data/oedometer.toml");
    // The settled sample: loading stopped at 200 N (only its packing.txt is used).
    const CliResult pack = run_colza("run oedometer --quiet --threads 2 --config " + config +
                                     " --set particle.density=1230 --set oedometer.stop_force=200"
                                     " --set oedometer.fit_force_max=190 --set oedometer.fit_force_min=10 --out " +
                                     (dir_ / "pack").string());
    ASSERT_EQ(pack.exit_code, 0) << pack.stderr_text;
    const std::string packing = (dir_ / "pack" / "packing.txt").string();
    truth_ = make_compression_truth(dir_, "run oedometer --quiet --threads 2 --config " + config +
                                              " --set particle.density=1230 --set oedometer.packing_file='\"" +
                                              packing + "\"'",
                                    kTrueKn, kTrueMu, 5);
    std::printf("compression truth: c1 = %.4g +/- %.3g N/m, c2 = %.4g +/- %.3g N/m^2, correlation %.3f, "
                "measured curve from realisation %zu\n",
                truth_.mean_c1, truth_.sd_c1, truth_.mean_c2, truth_.sd_c2, truth_.correlation, truth_.typical);
    write_file(dir_ / "spec.toml",
               "stage = \"compression\"\n[model]\nconfig = \"" + config +
                   "\"\nset = [\"particle.density=1230.0\", \"oedometer.packing_file=\\\"" + packing + "\\\"\"]\n"
                   "[[parameters]]\nname = \"kn_p\"\nkey = \"particle.normal_stiffness\"\nunit = \"N/m\"\n"
                   "design = [300e3, 400e3, 400e3, 400e3, 400e3, 500e3, 600e3]\n"
                   "[[parameters]]\nname = \"mu_pp\"\nkey = \"particle.friction\"\n"
                   "design = [0.4, 0.2, 0.3, 0.4, 0.5, 0.4, 0.4]\n"
                   "[sequential]\nmax_runs = 12\n" +
                   measured_table(truth_));
  }

  static nlohmann::json calibrate(const std::string& mode) {
    const fs::path out = dir_ / mode;
    const CliResult r = run_colza("calibrate compression --quiet --jobs 2 --mode " + mode + " --spec " +
                                  (dir_ / "spec.toml").string() + " --runs " + (dir_ / "runs").string() + " --out " +
                                  out.string());
    EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
    const auto s = read_json(out / "summary.json");
    std::printf("compression identity (%s): kn_p = %.4g +/- %.3g N/m, mu_pp = %.3f +/- %.3f (truth %.4g, %.2f), "
                "%d runs\n",
                mode.c_str(), s["parameters"][0]["value"].get<double>(), s["parameters"][0]["uncertainty"].get<double>(),
                s["parameters"][1]["value"].get<double>(), s["parameters"][1]["uncertainty"].get<double>(), kTrueKn,
                kTrueMu, s["runs_used"].get<int>());
    return s;
  }

  static fs::path dir_;
  static CompressionTruth truth_;
};
fs::path CalibrateCompressionIdentity::dir_;
CompressionTruth CalibrateCompressionIdentity::truth_;

}  // namespace

namespace {

void expect_recovered(const nlohmann::json& s) {
  const double kn = s["parameters"][0]["value"].get<double>(), mu = s["parameters"][1]["value"].get<double>();
  const double mu_sigma = s["parameters"][1]["uncertainty"].get<double>();
  EXPECT_NEAR(kn, kTrueKn, 35e3) << s.dump(1);
  EXPECT_NEAR(mu, kTrueMu, 2.0 * mu_sigma) << s.dump(1);
  EXPECT_LT(mu_sigma, 0.075) << s.dump(1);
  ASSERT_TRUE(s.contains("target_correlation"));
  // c1 and c2 from one fit: the five realisations gave -0.99 (session 21); -0.5 lies 3.0
  // standard errors of Fisher's z from it for n = 5 (tests/integration/correlation_bound_reference.py).
  EXPECT_LT(s["target_correlation"][0][1].get<double>(), -0.5);
}

}  // namespace

TEST_F(CalibrateCompressionIdentity, PaperProcedureRecoversKnAndMu) {
  const auto s = calibrate("paper");
  expect_recovered(s);
  EXPECT_EQ(s["runs_used"].get<int>(), 8);  // 7 design points + 1 validation
}

TEST_F(CalibrateCompressionIdentity, SequentialModeRecoversKnAndMu) {
  const auto s = calibrate("sequential");
  expect_recovered(s);
  EXPECT_TRUE(s["within_uncertainty"].get<bool>()) << s.dump(1);
  EXPECT_LE(s["runs_used"].get<int>(), 12);
}
