// DEM identity test of the shear stage of `colza calibrate` (label `full`, ~30 s).
// Synthetic "measured" shear curves made by colza at known bond strengths (Cn, Cs) =
// (1.8 N, 3.3 N) must be recovered by the paper's procedure and by the sequential mode,
// reading the curves as a lab's curves (measured.curves: strength = mean shear stress over
// the strength window, as for the simulation).
//
// Sample: tests/data/small_shear.toml (seed 3, 3 mm of shear, strength window 1.5-3 mm,
// loads 25.75 and 78.75 kPa) widened to a 100 x 100 mm box (1263 particles), the paper's
// five design points, target uncertainties = the scatter of C and tan(Phi) at fixed
// parameters (below). Run time: 31 s for the two tests under ctest (session 27; each process
// makes the truth; 74 s in session 9); ~37 s per seed in the seed study below. Label `full`.
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
// What the shear test determines (100 x 100 mm box, truth (1.8, 3.3) N, seeds 1-7, both modes;
// tests/full/shear_identity_seed_study.py regenerates the table, 4 min 17 s on 2 cores in
// session 27; the study this header quoted before, made with an older build whose runs
// differ, found Cn + Cs within 0.46 N, Cn within 0.57 N and Cs within 0.70 N):
//   seed  paper (Cn, Cs)   sequential (Cn, Cs), runs
//   1     (2.242, 3.217)   (2.116, 3.250), 5
//   2     (1.756, 3.282)   (1.745, 3.175), 5
//   3     (2.037, 3.117)   (2.000, 3.000), 3   <- this test (small_shear.toml's seed)
//   4     (2.030, 3.219)   (1.900, 3.309), 4
//   5     (1.407, 4.000)   (1.459, 3.750), 5
//   6     (1.537, 3.731)   (1.761, 3.488), 4
//   7     (2.493, 2.314)   (2.014, 2.885), 9
//   Cn + Cs within 0.36 N of 5.1 N: well determined;
//   Cn within 0.69 N, Cs within 0.99 N (both at seed 7, paper mode): weakly, because lowering
//   Cn and raising Cs changes C and tan(Phi) little (the response's small singular value is
//   along (Cn, Cs) ~ (1, -1)). Where the paper mode lands far off (seeds 5 and 7) colza says
//   so: its validation run misses the measurement by 1.5 and 3.1 standard uncertainties and
//   both parameters are reported "only weakly determined"; the sequential mode's answers there
//   meet the measurement within its uncertainty. Seed 5 puts Cs on the design's bound 4 N.
//   Paper mode: 6 runs always; sequential: 3-9 runs.
// Stated tolerances: the largest distances over the seven seeds rounded up to 0.1 N: Cn + Cs
// +/- 0.4 N (8 %), Cn +/- 0.7 N (39 %), Cs +/- 1.0 N (30 %).
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
constexpr double kToleranceSum = 0.4, kToleranceCn = 0.7, kToleranceCs = 1.0;  // N

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
