// A diagnosis spec's measured curves (diagnosis_spec.hpp): a feature without a `value` is
// taken from the test's measured curve, reduced by the code that reduces colza's runs, and a
// feature the curves do not give, or a curve on the wrong test, is refused naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "config/config_error.hpp"
#include "diagnose/diagnosis_spec.hpp"
#include "scratch_dir.hpp"

using namespace colza;

namespace {

// A load-unload curve in closed form: loading F = 1e6 N/m x to x = 2 mm (F = 2000 N), then
// unloading F = 4e6 N/m (x - 1.5 mm) to zero. With a sample 0.1 m high: strain at the turn
// 0.02, rebound strain (2 - 1.5) mm / 0.1 m = 0.005, permanent strain 0.015.
std::string closed_form_curve() {
  std::string s = "piston_displacement,piston_force\n";
  char row[64];
  for (int k = 0; k <= 200; ++k) {
    std::snprintf(row, sizeof row, "%.17g,%.17g\n", 1e-5 * k, 1e6 * 1e-5 * k);
    s += row;
  }
  for (int k = 1; k <= 50; ++k) {
    const double x = 0.002 - 1e-5 * k;
    std::snprintf(row, sizeof row, "%.17g,%.17g\n", x, 4e6 * (x - 0.0015));
    s += row;
  }
  return s;
}

std::string spec_with(const std::string& test_keys, const std::string& feature) {
  return "[[parameters]]\nname = \"mu\"\nkey = \"particle.friction\"\nlower = 0.1\nupper = 0.5\n"
         "[[tests]]\nname = \"oedometer\"\nscenario = \"oedometer\"\nconfig = \"" COLZA_SOURCE_DIR
         "/tests/data/small_oedometer.toml\"\nset = [\"oedometer.cycles=[40e3, 0.0]\"]\n" +
         test_keys + "[[tests.features]]\nname = \"" + feature + "\"\nuncertainty = 1e-4\n";
}

std::string error_of(const std::string& file) {
  try {
    (void)diagnose::read_diagnosis_spec(file);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(DiagnosisSpecCurves, AFeatureWithoutAValueComesFromTheMeasuredCurve) {
  const colza::testing::ScratchDir dir;
  dir.write("unload.csv", closed_form_curve());
  const std::string spec =
      dir.write("spec.toml", spec_with("curve = \"unload.csv\"\nsample_height = 0.1\n", "cycle1/rebound_strain"));
  const diagnose::DiagnosisSpec s = diagnose::read_diagnosis_spec(spec);
  ASSERT_EQ(s.tests.size(), 1u);
  ASSERT_EQ(s.tests[0].features.size(), 1u);
  EXPECT_NEAR(s.tests[0].features[0].measured, 0.005, 1e-9);
}

TEST(DiagnosisSpecCurves, AFeatureTheCurvesDoNotGiveOrACurveOnTheWrongTestIsRefused) {
  const colza::testing::ScratchDir dir;
  dir.write("unload.csv", closed_form_curve());
  std::string e = error_of(dir.write("a.toml", spec_with("curve = \"unload.csv\"\nsample_height = 0.1\n", "bulk_density")));
  EXPECT_NE(e.find("tests[0].features[0].value"), std::string::npos) << e;
  EXPECT_NE(e.find("cycle1/rebound_strain"), std::string::npos) << e;  // what the curve gives
  e = error_of(dir.write("b.toml", spec_with("curve = \"unload.csv\"\n", "cycle1/rebound_strain")));
  EXPECT_NE(e.find("tests[0].sample_height"), std::string::npos) << e;
  e = error_of(dir.write("c.toml", spec_with("curve = \"missing.csv\"\nsample_height = 0.1\n", "cycle1/rebound_strain")));
  EXPECT_NE(e.find("missing.csv"), std::string::npos) << e;
  e = error_of(dir.write("d.toml", spec_with("[[tests.curves]]\nnormal_stress = 25750.0\nfile = \"unload.csv\"\n",
                                             "cycle1/rebound_strain")));
  EXPECT_NE(e.find("tests[0].curves[0].file"), std::string::npos) << e;
}

TEST(DiagnosisSpecCurves, AReposeTestsAngleComesFromItsHeapProfile) {
  // Points on a 30 deg cone 100 mm high every 2 mm (calibration/measured_heap_profile.hpp).
  const colza::testing::ScratchDir dir;
  std::string profile = "rho,top\n";
  const double t = std::tan(30.0 * 3.14159265358979323846 / 180.0);
  char row[64];
  for (double rho = 0.0; 0.100 - rho * t > 0.0; rho += 0.002) {
    std::snprintf(row, sizeof row, "%.17g,%.17g\n", rho, 0.100 - rho * t);
    profile += row;
  }
  dir.write("heap.csv", profile);
  const std::string spec = dir.write(
      "spec.toml", "[[parameters]]\nname = \"mu\"\nkey = \"particle.friction\"\nlower = 0.1\nupper = 0.5\n"
                   "[[tests]]\nname = \"repose\"\nscenario = \"repose\"\nconfig = \"" COLZA_SOURCE_DIR
                   "/tests/data/small_repose.toml\"\ncurve = \"heap.csv\"\n"
                   "[[tests.features]]\nname = \"angle_of_repose_deg\"\nuncertainty = 1.0\n");
  const diagnose::DiagnosisSpec s = diagnose::read_diagnosis_spec(spec);
  ASSERT_EQ(s.tests.size(), 1u);
  ASSERT_EQ(s.tests[0].features.size(), 1u);
  EXPECT_NEAR(s.tests[0].features[0].measured, 30.0, 1e-9);
}
