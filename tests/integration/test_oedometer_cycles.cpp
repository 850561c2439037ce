// End-to-end: oedometer load-unload cycles (oedometer.cycles; analysis/oedometer_cycles.hpp).
//   * a lattice of frictionless spheres (independent vertical columns) whose moduli are known
//     in closed form, which unloads along its loading line: no permanent strain beyond the
//     bounds derived below, no loop, no lateral pressure;
//   * the small test sample (frictional, random) through two cycles: a set and a loop;
//   * the features of a run's curve.csv read back as a measured file equal the run's own;
//   * bad cycle lists: exit 2 naming the file, the key and the reason, nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "calibration/measured_load_unload.hpp"
#include "cli_runner.hpp"
#include "core/types.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

const std::string kConfig = source_path("tests/data/small_oedometer.toml");

// Columns of 4 spheres of d = 6.5 mm, touching along z (centres at r + k d), on a square grid
// of spacing 1.02 d (0.13 mm gaps between columns, so no lateral contact) inside the 40 mm
// cylinder: the grid points (i, j) s with i^2 + j^2 <= 5 (21 columns), centres at most
// sqrt(5) x 6.63 = 14.8 mm from the axis, 1.95 mm from the wall (within a diameter: the
// packing fills the cylinder). Top of the packing H = 4 d = 26 mm.
constexpr double kD = 0.0065, kLayers = 4;
constexpr int kColumns = 21;

fs::path write_lattice(const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path file = dir / "lattice.txt";
  std::string text;
  const double s = 1.02 * kD, r = 0.5 * kD;
  int columns = 0;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      if (i * i + j * j > 5) continue;
      ++columns;
      for (int k = 0; k < kLayers; ++k) {
        char line[160];
        std::snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g\n", i * s, j * s, r + k * kD, r);
        text += line;
      }
    }
  EXPECT_EQ(columns, kColumns);
  write_file(file, text);
  return file;
}

std::string lattice_args(const fs::path& packing, double stress) {
  return " --config " + kConfig + " --set oedometer.packing_file=" + packing.string() +
         " --set particle.friction=0 --set wall.friction=0 --set particle.diameter_min=0.0065"
         " --set particle.diameter_max=0.0065 --set oedometer.piston_speed=0.002 --set oedometer.record_interval=5"
         " --set 'oedometer.cycles=[" + std::to_string(stress) + ", 0.0]'"
         " --set 'oedometer.modulus_stresses=[" + std::to_string(0.5 * stress) + "]'";
}

}  // namespace

TEST(OedometerCycles, AFrictionlessLatticeUnloadsAlongItsLoadingLine) {
  const fs::path dir = scratch_dir("cycles-lattice");
  const fs::path packing = write_lattice(dir);
  const fs::path out = dir / "run";
  const double sigma = 100e3;
  const CliResult r = run_colza("run oedometer --quiet" + lattice_args(packing, sigma) + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto s = read_json(out / "summary.json");
  ASSERT_TRUE(s.contains("load_unload")) << s.dump(1);
  const auto& lu = s["load_unload"];
  EXPECT_EQ(lu["targets_reached"].get<int>(), 2);
  EXPECT_EQ(s["stop_reason"], "cycles_completed");
  ASSERT_EQ(lu["branches"].size(), 2u);
  ASSERT_EQ(lu["cycles"].size(), 1u);
  EXPECT_NEAR(s["packing_height"].get<double>(), kLayers * kD, 1e-12);

  // Closed form. Each column is a chain of springs in series: 3 sphere-sphere contacts of
  // kn = 437e3 / 2 N/m (series rule of two equal spheres) and two sphere-wall contacts (floor,
  // piston) of kn = 437e3 x 4000e3 / (437e3 + 4000e3) N/m. Frictionless, with all normals
  // vertical (the columns' x, y never change), the shear springs carry nothing. So the piston
  // force is F = 21 kc s with 1 / kc = 3 / k_pp + 2 / k_pw, and the constrained modulus
  //   M = d(F / A) / d(s / H) = 21 kc H / A,   A = pi (0.040)^2 / 4, H = 4 d.
  // (Gravity preloads the lower contacts; a linear law adds it and leaves the slope.)
  const double k_pp = 437e3 / 2.0, k_pw = 437e3 * 4000e3 / (437e3 + 4000e3);
  const double kc = 1.0 / (3.0 / k_pp + 2.0 / k_pw);
  const double area = colza::kPi * 0.040 * 0.040 / 4.0, height = kLayers * kD;
  const double modulus = kColumns * kc * height / area;  // 23.1 MPa
  for (int b = 0; b < 2; ++b) {
    const auto& m = lu["branches"][b]["moduli"];
    ASSERT_EQ(m.size(), 1u) << lu.dump(1);
    // The fit's window (45-55 kPa) is reached ~0.025 s after a start or a turn, over a hundred
    // periods of a column's slowest mode (2 pi sqrt(4 m / kc) ~ 0.7 ms); the transients the
    // start and the turn excite are gone, and at a steady piston speed the affine motion of
    // the columns has no unbalanced force, so local damping exerts none: the slope is the
    // static one. 0.5 % leaves room for the rounding of the rows' times only.
    EXPECT_NEAR(m[0]["modulus"].get<double>(), modulus, 5e-3 * modulus) << b;
    // No sphere touches the cylinder: no radial force, K = 0.
    EXPECT_EQ(m[0]["lateral_ratio"].get<double>(), 0.0) << b;
  }
  // Strain at the turn: sigma / M = 100e3 / 23.1e6 = 4.3e-3 (plus the start's gravity sag).
  const auto& cycle = lu["cycles"][0];
  const double turn = cycle["strain_at_turn"].get<double>();
  EXPECT_NEAR(turn, sigma / modulus, 0.01 * sigma / modulus);
  // Permanent strain: the piston leaves the columns where it first met them, at the sag of
  // their tops under their own weight, 4W / k_pw + (3 + 2 + 1) W / k_pp = 6.6e-8 m (W = 1.76e-3 N),
  // strain 2.5e-6; plus what the turn's transient leaves: the piston's velocity jumps by 2v =
  // 4 mm/s, which sets a column ringing at most at F ~ sqrt(k_pp m) 2v = 0.025 N (m = 1.8e-4 kg),
  // a travel error F / kc = 4.7e-7 m, strain 1.8e-5 if none of it were damped. Bound: 3e-5,
  // 0.7 % of the strain at the turn (a frictional sample keeps tens of per cent, test below).
  EXPECT_LT(std::abs(cycle["permanent_strain"].get<double>()), 3e-5);
  // Loop area: the net work, sigma_max x (the turn's strain error) at most, ~100e3 x 3e-5 = 3
  // J/m^3 against the loading's work sigma^2 / (2 M) = 216 J/m^3.
  const double work = lu["branches"][0]["work"].get<double>();
  EXPECT_NEAR(work, sigma * sigma / (2.0 * modulus), 0.02 * work);
  EXPECT_LT(std::abs(cycle["loop_area"].get<double>()), 3.0);
}

class SmallOedometerCycles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = scratch_dir("small-oedometer-cycles");
    const CliResult r = run_colza("run oedometer --quiet --config " + kConfig +
                                  " --set oedometer.piston_speed=0.01"
                                  " --set 'oedometer.cycles=[200e3, 0.0, 200e3, 0.0]'"
                                  " --set 'oedometer.modulus_stresses=[50e3, 150e3]' --out " + out_.string());
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    stdout_ = r.stdout_text;
  }
  static fs::path out_;
  static std::string stdout_;
};
fs::path SmallOedometerCycles::out_;
std::string SmallOedometerCycles::stdout_;

TEST_F(SmallOedometerCycles, TwoCyclesLeaveASetAndALoop) {
  const auto s = read_json(out_ / "summary.json");
  const auto& lu = s["load_unload"];
  EXPECT_EQ(s["stop_reason"], "cycles_completed");
  EXPECT_EQ(lu["targets_reached"].get<int>(), 4);
  ASSERT_EQ(lu["branches"].size(), 4u) << lu.dump(1);
  ASSERT_EQ(lu["cycles"].size(), 2u);
  for (int b = 0; b < 4; ++b) {
    const auto& branch = lu["branches"][b];
    EXPECT_EQ(branch["kind"], b % 2 == 0 ? "loading" : "unloading");
    // The turns: each target reached within one step's stress increment (< 1 %).
    const double end = branch["stress_end"].get<double>();
    if (b % 2 == 0) EXPECT_NEAR(end, 200e3, 2e3) << b;
    else EXPECT_EQ(end, 0.0) << b;  // the piston has left the sample
    ASSERT_EQ(branch["moduli"].size(), 2u) << b;
    for (const auto& m : branch["moduli"]) {
      EXPECT_GT(m["modulus"].get<double>(), 0.0);
      EXPECT_GE(m["points"].get<int>(), 3);
      // A frictional packing against a frictional wall: K > 0, and below 1 on loading (on
      // unloading the locked-in radial stress can exceed the vertical one).
      EXPECT_GT(m["lateral_ratio"].get<double>(), 0.0);
      if (b % 2 == 0) EXPECT_LT(m["lateral_ratio"].get<double>(), 1.0);
    }
  }
  // Frictional contacts slide on loading and do not slide back: the first unloading is
  // stiffer than the virgin loading at the same stress (1.95x at 150 kPa with this sample),
  // the sample keeps a set (90 % of the strain at the turn: most of it the seating of the
  // piston on the rough top), the set grows with the second cycle, and both loops enclose
  // work. (This 117-sphere sample collapses once on its reloading near 176 kPa, so its
  // second loop is the larger: no ordering of the loops is asserted.)
  const auto& c0 = lu["cycles"][0];
  const auto& c1 = lu["cycles"][1];
  EXPECT_GT(lu["branches"][1]["moduli"][1]["modulus"].get<double>(),
            1.3 * lu["branches"][0]["moduli"][1]["modulus"].get<double>());
  EXPECT_GT(c0["permanent_strain"].get<double>(), 0.2 * c0["strain_at_turn"].get<double>());
  EXPECT_GE(c1["permanent_strain"].get<double>(), c0["permanent_strain"].get<double>());
  EXPECT_GT(c0["loop_area"].get<double>(), 0.0);
  EXPECT_GT(c1["loop_area"].get<double>(), 0.0);
  // K grows on unloading (the radial stress is locked in while the vertical one falls).
  EXPECT_GT(lu["branches"][1]["moduli"][0]["lateral_ratio"].get<double>(),
            lu["branches"][0]["moduli"][0]["lateral_ratio"].get<double>());
  // The inertial number at the largest stress: 0.01 m/s / H x d x sqrt(rho / p).
  const auto& in = s["inertial_number"];
  const double expected = 0.01 / s["packing_height"].get<double>() * 0.0065 *
                          std::sqrt(1250.0 / in["pressure"].get<double>());
  EXPECT_NEAR(in["value"].get<double>(), expected, 1e-12 * expected);
  EXPECT_NE(stdout_.find("cycle (branches 0-1): loop area"), std::string::npos) << stdout_;
}

TEST_F(SmallOedometerCycles, TheCurveHasTheRadialForceAndTheBranch) {
  std::istringstream in(read_file(out_ / "curve.csv"));
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "time,piston_displacement,piston_force,contacts,bonds,radial_force,cylinder_friction_force,branch");
}

TEST_F(SmallOedometerCycles, ItsCurveReadAsAMeasuredFileGivesTheSameFeatures) {
  // The measured reader and the run share analysis/oedometer_cycles: the run's own curve.csv,
  // read as a measured curve with the run's geometry and settings, gives its summary's numbers.
  const auto s = read_json(out_ / "summary.json");
  const auto& lu = s["load_unload"];
  using namespace colza::calibration;
  const MeasuredLoadUnload m = read_measured_load_unload((out_ / "curve.csv").string(), "spec.toml", "measured.curve");
  EXPECT_FALSE(m.radial.empty());
  colza::CycleAnalysisSettings settings;
  settings.modulus_stresses = {50e3, 150e3};
  settings.modulus_window = lu["modulus_window"].get<double>();
  settings.reversal_tolerance = 0.0;
  const double area = colza::kPi * 0.040 * 0.040 / 4.0;
  const colza::LoadUnloadAnalysis a = measured_load_unload_features(
      m, {area, s["packing_height"].get<double>(), 0.040}, settings, "spec.toml", "measured.curve");
  ASSERT_EQ(a.branches.size(), 4u);
  ASSERT_EQ(a.cycles.size(), 2u);
  // curve.csv holds 17 significant digits: the same numbers to rounding.
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(a.cycles[c].loop_area, lu["cycles"][c]["loop_area"].get<double>(),
                1e-12 * std::abs(a.cycles[c].loop_area));
    EXPECT_DOUBLE_EQ(a.cycles[c].permanent_strain, lu["cycles"][c]["permanent_strain"].get<double>());
  }
  for (int b = 0; b < 4; ++b)
    EXPECT_NEAR(a.branches[b].moduli[0].modulus, lu["branches"][b]["moduli"][0]["modulus"].get<double>(),
                1e-9 * a.branches[b].moduli[0].modulus);
  // With the measured files' default tolerance (0.1 % of the travel's range) the branches are the same.
  settings.reversal_tolerance = 1e-3;
  EXPECT_EQ(measured_load_unload_features(m, {area, s["packing_height"].get<double>(), 0.040}, settings, "spec.toml",
                                          "measured.curve")
                .branches.size(),
            4u);
}

TEST(OedometerCycles, BadCycleListsAreExit2NamingTheKeyAndNothingIsWritten) {
  const fs::path dir = scratch_dir("cycles-bad");
  struct Case {
    std::string set, reason;
  };
  const Case cases[] = {
      {"'oedometer.cycles=[100e3, 150e3]'", "entry 2 (150000 Pa) follows a loading to 1e+05 Pa"},
      {"'oedometer.cycles=[100e3, 0.0, -5.0]'", "entry 3 (-5 Pa) is negative"},
      {"'oedometer.cycles=[0.0]'", "must be above 0"},
      {"'oedometer.cycles=[100e3, 50e3, 40e3]'", "follows an unloading to 50000 Pa"},
      {"'oedometer.cycles=[]'", "needs at least one piston stress"},
      {"'oedometer.cycles=[5e6]'", "above oedometer.stop_force"},
  };
  for (const Case& c : cases) {
    const fs::path out = dir / "out";
    const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --set " + c.set + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.set;
    EXPECT_NE(r.stderr_text.find("--set oedometer.cycles: key 'oedometer.cycles'"), std::string::npos) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(c.reason), std::string::npos) << r.stderr_text;
    EXPECT_FALSE(fs::exists(out)) << c.set;
  }
  const CliResult alone = run_colza("run oedometer --quiet --config " + kConfig +
                                    " --set 'oedometer.modulus_stresses=[50e3]' --out " + (dir / "out").string());
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_NE(alone.stderr_text.find("give oedometer.cycles too"), std::string::npos) << alone.stderr_text;
}
