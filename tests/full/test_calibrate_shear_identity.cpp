// DEM identity test of the shear stage of `colza calibrate` (label `full`, 1-2.5 min).
// Synthetic "measured" shear curves made by colza at known bond strengths (Cn, Cs) =
// (1.8 N, 3.3 N) must be recovered by the paper's procedure and by the sequential mode,
// reading the curves as a lab's curves (measured.curves: strength = mean shear stress over
// the strength window, as for the simulation).
//
// Sample: tests/data/small_shear.toml (seed 3, 3 mm of shear, strength window 1.5-3 mm,
// loads 25.75 and 78.75 kPa) widened to a 100 x 100 mm box (1263 particles), the paper's
// five design points, target uncertainties = the scatter of C and tan(Phi) at fixed
// parameters (below). Run time (nice'd, 2 cores with one busy): 74 s for the two tests
// under ctest (each process makes the truth, ~10 s; paper 40 s, sequential 35 s in all);
// 80-135 s per seed in the seed study below (one job at a time). Hence label `full`.
//
// Why not the 60 x 60 mm box (439 particles) of the other shear tests: there the strength at
// FIXED parameters scatters by 0.95 kPa (std of 6 runs with Cn perturbed by 1e-4 relative:
// the small box is chaotic), which through the response (d tau / d(Cn, Cs) = (4.7, 1.9)
// kPa/N at 25.75 kPa, (3.2, 4.0) kPa/N at 78.75 kPa, planes over a 5 x 3 grid) is +/- 0.33 N
// in Cn and +/- 0.42 N in Cs for one measurement; over 8 seeds at truth (1.8, 3.3) the paper
// procedure stopped with "out of reach" twice, put Cs on the design's bound 4 N three times
// and missed Cn by up to 1.0 N: no recovery worth asserting. In the 100 x 100 mm box the
// scatter is 0.36 and 0.20 kPa (C: 512 Pa, tan(Phi): 0.0067).
//
// What the shear test determines (100 x 100 mm box, truth (1.8, 3.3) N, seeds 1-7, both modes):
//   Cn + Cs within 0.46 N of 5.1 N (median 0.11 N): well determined;
//   Cn within 0.57 N (median 0.22 N), Cs within 0.70 N (median 0.20 N): weakly, because
//   lowering Cn and raising Cs changes C and tan(Phi) little (the response's small singular
//   value, about 1.8 kPa/N, is along (Cn, Cs) ~ (1, -1)); seed 4 gave (1.25, 3.97) in the
//   paper mode and (1.23, 4.00) in the sequential mode, which reproduces the measured C and
//   tan(Phi) within their uncertainty.
//   Paper mode: 6 runs always; sequential: 3-9 runs (median 5).
// Seed 3 (this test): paper (1.666, 3.403), sequential (1.573, 3.506) in 5 runs.
// Stated tolerances: Cn + Cs +/- 0.5 N (10 %), Cn +/- 0.6 N (33 %), Cs +/- 0.75 N (23 %).
#include <gtest/gtest.h>

#include <cmath>

#include "cli_runner.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

constexpr double kTrueCn = 1.8, kTrueCs = 3.3;  // N
const std::vector<std::string> kWideBox = {"shear_box.length=0.1", "shear_box.width=0.1", "sample.count=1560"};

class CalibrateShearIdentity : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = scratch_dir("calibrate-shear-identity");
    fs::create_directories(dir_);
    const std::string config = source_path("tests/data/small_shear.toml");
    std::string set;
    for (const auto& s : kWideBox) set += " --set " + s;
    const CliResult truth = run_colza("run shear-series --quiet --jobs 2 --config " + config + set +
                                      " --set contact.contact_bond.normal_strength=" + std::to_string(kTrueCn) +
                                      " --set contact.contact_bond.shear_strength=" + std::to_string(kTrueCs) +
                                      " --out " + (dir_ / "truth").string());
    ASSERT_EQ(truth.exit_code, 0) << truth.stderr_text;
    // Every calibration run starts from the truth's settled sample (the same one the seed makes).
    std::string model_set = "set = [";
    for (const auto& s : kWideBox) model_set += "\"" + s + "\", ";
    model_set += "\"shear_box.packing_file=\\\"" + (dir_ / "truth" / "packing.txt").string() + "\\\"\"]\n";
    write_file(dir_ / "spec.toml",
          "stage = \"shear\"\n[model]\nconfig = \"" + config + "\"\n" + model_set +
              "[[parameters]]\nname = \"Cn\"\nkey = \"contact.contact_bond.normal_strength\"\nunit = \"N\"\n"
              "design = [0.5, 1.5, 1.5, 1.5, 2.5]\n"  // the paper's five points (physics.md section 5)
              "[[parameters]]\nname = \"Cs\"\nkey = \"contact.contact_bond.shear_strength\"\nunit = \"N\"\n"
              "design = [3.0, 2.0, 3.0, 4.0, 3.0]\n"
              "[sequential]\nmax_runs = 10\n"
              "[measured]\ncohesion_uncertainty = 500.0\ntan_phi_uncertainty = 0.007\n"
              "[[measured.curves]]\nnormal_stress = 25750.0\nfile = \"truth/load-25750Pa/curve.csv\"\n"
              "[[measured.curves]]\nnormal_stress = 78750.0\nfile = \"truth/load-78750Pa/curve.csv\"\n");
  }

  static nlohmann::json calibrate(const std::string& mode) {
    const fs::path out = dir_ / mode;
    const CliResult r = run_colza("calibrate shear --quiet --jobs 2 --mode " + mode + " --spec " +
                                  (dir_ / "spec.toml").string() + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
    const auto s = read_json(out / "summary.json");
    std::printf("shear identity (%s): Cn = %.3f +/- %.3f N, Cs = %.3f +/- %.3f N (truth %.2f, %.2f), %d runs\n",
                mode.c_str(), s["parameters"][0]["value"].get<double>(), s["parameters"][0]["uncertainty"].get<double>(),
                s["parameters"][1]["value"].get<double>(), s["parameters"][1]["uncertainty"].get<double>(), kTrueCn,
                kTrueCs, s["runs_used"].get<int>());
    return s;
  }

  static fs::path dir_;
};
fs::path CalibrateShearIdentity::dir_;

// The spread measured over seeds 1-7 (see the top of the file), rounded up.
constexpr double kToleranceSum = 0.5, kToleranceCn = 0.6, kToleranceCs = 0.75;  // N

void expect_recovered(const nlohmann::json& s, const fs::path& truth_dir) {
  const double cn = s["parameters"][0]["value"].get<double>(), cs = s["parameters"][1]["value"].get<double>();
  EXPECT_NEAR(cn + cs, kTrueCn + kTrueCs, kToleranceSum) << s.dump(1);
  EXPECT_NEAR(cn, kTrueCn, kToleranceCn) << s.dump(1);
  EXPECT_NEAR(cs, kTrueCs, kToleranceCs) << s.dump(1);
  // The targets came from the curves, and each curve's strength is the truth's own within
  // 1 % (the curve keeps every 20th time step, the simulation averages every step).
  ASSERT_EQ(s["measured"]["source"], "curves");
  const auto truth = read_json(truth_dir / "summary.json");
  for (std::size_t k = 0; k < 2; ++k) {
    const double simulated = truth["loads"][k]["shear_strength"].get<double>();
    EXPECT_NEAR(s["measured"]["strengths"][k]["shear_strength"].get<double>(), simulated, 0.01 * simulated);
  }
}

}  // namespace

TEST_F(CalibrateShearIdentity, PaperProcedureRecoversTheBondStrengths) {
  const auto s = calibrate("paper");
  expect_recovered(s, dir_ / "truth");
  EXPECT_EQ(s["runs_used"].get<int>(), 6);  // 5 design points + 1 validation
  const std::string report = read_file(dir_ / "paper" / "report.md");
  EXPECT_NE(report.find("## Measured data"), std::string::npos);
  EXPECT_NE(report.find("load-25750Pa/curve.csv"), std::string::npos);
}

TEST_F(CalibrateShearIdentity, SequentialModeRecoversTheBondStrengths) {
  const auto s = calibrate("sequential");
  expect_recovered(s, dir_ / "truth");
  EXPECT_TRUE(s["within_uncertainty"].get<bool>());
  EXPECT_LE(s["runs_used"].get<int>(), 10);
}
