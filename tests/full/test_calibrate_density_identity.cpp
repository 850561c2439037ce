// DEM identity test of the density stage of `colza calibrate` on the paper's full-size
// oedometer (label `full`, ~2-3 min on 2 cores). The "measured" bulk density is made by colza
// at a known particle density, 1285 kg/m^3, from another seed (101) than the design runs'
// (the config's 1) and their confirmation's (2): like a lab sample, the truth is another
// realisation of the packing, so the recovery has to get through the realisation scatter and
// not only the surrogate.
//
// Where the numbers come from (session 15, `colza run oedometer --set
// oedometer.stop_force=300 --set oedometer.fit_force_max=250 --set oedometer.fit_force_min=10
// --seed S`, Table 1 otherwise): the settled bulk density at rho_p = 1250 kg/m^3 is 659.9,
// 666.9 and 656.9 kg/m^3 for seeds 1, 2, 3: std 5.1 kg/m^3, which is the target uncertainty
// here (the paper's own, 3 kg/m^3, is below what one realisation can resolve). Over the
// paper's design the slope is d(rho_b)/d(rho_p) = 0.47, so one realisation leaves
// rho_p uncertain by 5.1 / 0.47 ~ 11 kg/m^3. Seed 101 at 1285 settles to 681.4 kg/m^3; the
// paper procedure then gave rho_p = 1293.3 +/- 11.5 kg/m^3 in 4 runs, the sequential mode
// 1275.0 +/- 7.7 kg/m^3 in 3 (seed 2 as the truth: 1287.4 and 1275.0).
//
// Stated tolerance: 25 kg/m^3 (~2.3 of those 11). It is below the distance from the design's
// centre (1250) to the truth, 35 kg/m^3, so a calibration that returned the centre fails.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cli_runner.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

constexpr double kTrueDensity = 1285.0;            // kg/m^3
constexpr double kDesignCentre = 1250.0;           // kg/m^3, data/calibration/density.toml
constexpr double kTolerance = 25.0;                // kg/m^3, see the top of the file
constexpr double kRealisationScatter = 5.1;        // kg/m^3, bulk density std over seeds 1-3
const std::string kLoad = " --set oedometer.stop_force=200 --set oedometer.fit_force_max=190"
                          " --set oedometer.fit_force_min=10";  // as data/calibration/density.toml

class CalibrateDensityIdentity : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = scratch_dir("calibrate-density-identity");
    fs::create_directories(dir_);
    const CliResult truth = run_colza("run oedometer --quiet --config " + source_path("data/oedometer.toml") + kLoad +
                                      " --seed 101 --set particle.density=" + std::to_string(kTrueDensity) + " --out " +
                                      (dir_ / "truth").string());
    ASSERT_EQ(truth.exit_code, 0) << truth.stderr_text;
    const double bulk = read_json(dir_ / "truth" / "summary.json")["bulk_density"].get<double>();
    // The paper's spec with the truth's bulk density as the measurement.
    std::string spec = read_file(source_path("data/calibration/density.toml"));
    const auto replace_line = [&](const std::string& start, const std::string& line) {
      const std::size_t at = spec.find("\n" + start);
      ASSERT_NE(at, std::string::npos) << start;
      spec.replace(at + 1, spec.find('\n', at + 1) - at - 1, line);
    };
    replace_line("config = ", "config = \"" + source_path("data/oedometer.toml") + "\"");
    replace_line("bulk_density = ", "bulk_density = " + std::to_string(bulk));
    replace_line("bulk_density_uncertainty = ",
                 "bulk_density_uncertainty = " + std::to_string(kRealisationScatter));
    write_file(dir_ / "spec.toml", spec);
  }

  static nlohmann::json calibrate(const std::string& mode) {
    const fs::path out = dir_ / mode;
    const CliResult r = run_colza("calibrate density --quiet --jobs 2 --threads 1 --mode " + mode + " --spec " +
                                  (dir_ / "spec.toml").string() + " --runs " + (dir_ / "runs").string() +
                                  " --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
    const auto s = read_json(out / "summary.json");
    std::printf("density identity (%s): rho_p = %.1f +/- %.1f kg/m^3 (truth %.0f), %d runs\n", mode.c_str(),
                s["parameters"][0]["value"].get<double>(), s["parameters"][0]["uncertainty"].get<double>(),
                kTrueDensity, s["runs_used"].get<int>());
    return s;
  }

  static fs::path dir_;
};
fs::path CalibrateDensityIdentity::dir_;

void expect_recovered(const nlohmann::json& s) {
  static_assert(kTolerance < kTrueDensity - kDesignCentre, "the design centre must fail the tolerance");
  const double rho = s["parameters"][0]["value"].get<double>();
  EXPECT_NEAR(rho, kTrueDensity, kTolerance) << s.dump(1);
  // The reported uncertainty is honest: the truth lies within 3 of it.
  EXPECT_LT(std::abs(rho - kTrueDensity), 3.0 * s["parameters"][0]["uncertainty"].get<double>()) << s.dump(1);
}

}  // namespace

TEST_F(CalibrateDensityIdentity, PaperProcedureRecoversTheParticleDensityFromAnotherRealisation) {
  const auto s = calibrate("paper");
  expect_recovered(s);
  EXPECT_EQ(s["runs_used"].get<int>(), 4);  // the paper's 3 design points + 1 validation
}

TEST_F(CalibrateDensityIdentity, SequentialModeRecoversTheParticleDensityFromAnotherRealisation) {
  const auto s = calibrate("sequential");
  expect_recovered(s);
}
