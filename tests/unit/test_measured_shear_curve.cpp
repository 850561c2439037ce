// Measured shear curves as calibration input (calibration/measured_shear_curve.hpp): the
// strength is the mean shear stress of the rows inside the strength window, as for the
// simulation (analysis/shear_strength.hpp); bad curves are ConfigErrors naming the spec
// file, the key, the CSV and the reason. A shear spec built from curves reads its targets
// from them. Every test writes small CSVs to its own temp folder.
#include <gtest/gtest.h>

#include <string>

#include "analysis/mohr_coulomb.hpp"
#include "analysis/shear_strength.hpp"
#include "calibration/measured_report.hpp"
#include "calibration/measured_shear_curve.hpp"
#include "calibration/spec.hpp"
#include "config/config_error.hpp"

#include "scratch_dir.hpp"

using namespace colza;
using namespace colza::calibration;

namespace {

const StrengthDefinition kWindow{false, {0.0015, 0.003}};  // mean over 1.5-3 mm, tests/data/small_shear.toml
constexpr double kBoxLength = 0.060;                           // m, tests/data/small_shear.toml

class MeasuredShearCurveTest : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) const { return dir_.write(name, text); }
  // Rows every 0.5 mm from 0 to `end_mm`, tau = 1000 + 100 * (d in mm) Pa.
  std::string even_curve(const std::string& name, double end_mm, double tau0 = 1000.0) const {
    std::string t = "shear_displacement,shear_stress\n";
    for (int k = 0; 0.5 * k <= end_mm + 1e-9; ++k)
      t += std::to_string(0.0005 * k) + "," + std::to_string(tau0 + 100.0 * 0.5 * k) + "\n";
    return write(name, t);
  }
  // The ConfigError's full message, or "" when read_measured_shear_curve succeeds.
  std::string error_of(const std::string& csv) const {
    std::vector<std::string> warnings;
    try {
      read_measured_shear_curve(csv, 25e3, kWindow, "spec.toml", "measured.curves[0].file", warnings, kBoxLength);
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.file(), "spec.toml");
      EXPECT_EQ(e.key(), "measured.curves[0].file");
      return e.what();
    }
    return "";
  }
  // "key | reason" of the ConfigError read_spec throws for this spec text, or "no error".
  std::string spec_error(const std::string& spec_text) const {
    try {
      read_spec(write("bad.toml", spec_text));
    } catch (const ConfigError& e) {
      return e.key() + " | " + e.reason();
    }
    return "no error";
  }
  colza::testing::ScratchDir dir_;
};

}  // namespace

TEST(ShearStrengthMean, MeanOfTheSamplesInsideTheClosedWindow) {
  ShearStrengthMean m({0.002, 0.003});
  m.add(0.0019, 1e9);  // outside
  m.add(0.002, 10.0);  // both ends count
  m.add(0.0025, 20.0);
  m.add(0.003, 60.0);
  m.add(0.0031, -1e9);  // outside
  EXPECT_EQ(m.samples(), 3u);
  EXPECT_DOUBLE_EQ(m.value(), 30.0);
  EXPECT_EQ(ShearStrengthMean({0.0, 1.0}).value(), 0.0);  // no sample
}

TEST(PeakShearStrength, LargestMeanOverATrailingIntervalOfTheWidth) {
  // d = 0, 0.25, .., 3 (binary fractions: exact), width 0.5: each interval holds 3 rows once
  // d_i >= 0.5. Means: d = 0.5: 10, 0.75: 20, 1.0: 30, 1.25: (30 + 40 + 30) / 3, 1.5: 30, ...
  std::vector<double> d, tau = {0, 10, 20, 30, 40, 30, 20, 10, 10, 10, 10, 10, 10};
  for (std::size_t k = 0; k < tau.size(); ++k) d.push_back(0.25 * static_cast<double>(k));
  const ShearPeak p = peak_shear_strength(d, tau, 0.5);
  EXPECT_DOUBLE_EQ(p.value, 100.0 / 3.0);
  EXPECT_DOUBLE_EQ(p.displacement, 1.25);
  EXPECT_EQ(p.samples, 3u);
  // Width 0: the largest single row.
  EXPECT_DOUBLE_EQ(peak_shear_strength(d, tau, 0.0).value, 40.0);
  // An interval longer than the curve: no peak.
  EXPECT_EQ(peak_shear_strength(d, tau, 3.5).samples, 0u);
}

TEST_F(MeasuredShearCurveTest, StrengthIsTheMeanStressOverTheWindow) {
  std::vector<std::string> warnings;
  const auto c = read_measured_shear_curve(even_curve("c.csv", 3.0), 25e3, kWindow, "spec.toml", "k", warnings, kBoxLength);
  // Rows at 1.5, 2.0, 2.5, 3.0 mm: tau = 1150, 1200, 1250, 1300 Pa.
  EXPECT_EQ(c.window_points, 4u);
  EXPECT_EQ(c.rows, 7u);
  EXPECT_NEAR(c.shear_strength, 1225.0, 1e-9);
  EXPECT_DOUBLE_EQ(c.max_displacement, 0.003);
  EXPECT_EQ(c.normal_stress, 25e3);
  EXPECT_TRUE(warnings.empty());
}

TEST_F(MeasuredShearCurveTest, ColzasOwnCurveFileIsAValidCurve) {
  // Comment lines, extra columns in any order (load-<sigma>Pa/curve.csv has nine).
  const std::string csv = write("curve.csv",
                                "# a comment\n"
                                "time,shear_displacement,shear_force,shear_stress,normal_stress\n"
                                "0,0,0,0,25000\n"
                                "0.1,0.0015,40,1000,25000\n"
                                "0.2,0.00225,44,1100,25000\n"
                                "0.3,0.003,48,1200,25000\n");
  std::vector<std::string> warnings;
  const auto c = read_measured_shear_curve(csv, 25e3, kWindow, "spec.toml", "k", warnings, kBoxLength);
  EXPECT_NEAR(c.shear_strength, 1100.0, 1e-9);
  EXPECT_EQ(c.window_points, 3u);
}

TEST_F(MeasuredShearCurveTest, DisplacementInMillimetresIsAnError) {
  // 0 to 3 mm written in mm: it reaches 3, more than the 0.06 m box can be sheared.
  std::string t = "shear_displacement,shear_stress\n";
  for (int k = 0; k <= 6; ++k) t += std::to_string(0.5 * k) + "," + std::to_string(1000 + 50 * k) + "\n";
  const std::string e = error_of(write("mm.csv", t));
  EXPECT_NE(e.find("the shear displacement reaches 3, more than the box's length shear_box.length = 0.06 m"),
            std::string::npos) << e;
  EXPECT_NE(e.find("in m (mm / 1000)"), std::string::npos) << e;
}

TEST_F(MeasuredShearCurveTest, MissingFile) {
  const std::string m = error_of((dir_ / "nowhere.csv").string());
  EXPECT_NE(m.find("nowhere.csv does not exist"), std::string::npos) << m;
}

TEST_F(MeasuredShearCurveTest, MissingColumn) {
  const std::string m = error_of(write("c.csv", "displacement,stress\n0,1\n"));
  EXPECT_NE(m.find("no column \"shear_displacement\""), std::string::npos) << m;
}

TEST_F(MeasuredShearCurveTest, ASpreadsheetsByteOrderMarkIsReadAndSemicolonsAreNamed) {
  // "CSV UTF-8" from a spreadsheet starts with EF BB BF: read as if it were not there.
  std::string t = "\xEF\xBB\xBFshear_displacement,shear_stress\n";
  for (int k = 0; k <= 6; ++k) t += std::to_string(0.0005 * k) + "," + std::to_string(1000 + 100 * k) + "\n";
  EXPECT_EQ(error_of(write("bom.csv", t)), "");
  // A European spreadsheet's CSV separates by semicolons: the message says so.
  const std::string m = error_of(write("semicolon.csv", "shear_displacement;shear_stress\n0;1000\n"));
  EXPECT_NE(m.find("separated by commas, not semicolons"), std::string::npos) << m;
}

TEST_F(MeasuredShearCurveTest, AColumnNamedTwiceIsAnError) {
  const std::string m =
      error_of(write("twice.csv", "shear_displacement,shear_stress,shear_stress\n0,1000,900\n0.001,1100,950\n"));
  EXPECT_NE(m.find("names column \"shear_stress\" twice"), std::string::npos) << m;
}

TEST_F(MeasuredShearCurveTest, NonNumericCellNamesLineAndColumn) {
  const std::string m = error_of(write("c.csv", "# comment\nshear_displacement,shear_stress\n0,0\n0.001,12x\n"));
  EXPECT_NE(m.find("c.csv: line 4: column \"shear_stress\" is \"12x\", not a finite number"), std::string::npos) << m;
}

TEST_F(MeasuredShearCurveTest, CurveEndingBeforeTheWindowSaysHowFarItGoesAndWhatIsNeeded) {
  const std::string m = error_of(even_curve("c.csv", 2.5));
  EXPECT_NE(m.find("ends at a shear displacement of 0.0025 m"), std::string::npos) << m;
  EXPECT_NE(m.find("needs it to reach 0.003 m"), std::string::npos) << m;
}

TEST_F(MeasuredShearCurveTest, FewerThanTwoRowsInTheWindow) {
  const std::string m = error_of(write("c.csv", "shear_displacement,shear_stress\n0,0\n0.001,900\n0.002,1000\n0.0035,1100\n"));
  EXPECT_NE(m.find("1 row(s) inside the strength window 0.0015 .. 0.003 m; at least 2 are needed"), std::string::npos)
      << m;
}

TEST_F(MeasuredShearCurveTest, DisplacementMustIncrease) {
  const std::string m =
      error_of(write("c.csv", "shear_displacement,shear_stress\n0,0\n0.002,900\n0.002,950\n0.003,1000\n"));
  EXPECT_NE(m.find("line 4: shear_displacement 0.002 m does not increase on the previous row's 0.002 m (line 3)"),
            std::string::npos) << m;
}

TEST_F(MeasuredShearCurveTest, EmptyCurve) {
  EXPECT_NE(error_of(write("c.csv", "shear_displacement,shear_stress\n")).find("no rows"), std::string::npos);
  EXPECT_NE(error_of(write("d.csv", "")).find("no header line"), std::string::npos);
}

TEST_F(MeasuredShearCurveTest, UnevenSamplingInTheWindowIsAWarning) {
  const std::string csv =
      write("c.csv", "shear_displacement,shear_stress\n0.0015,1000\n0.0016,1000\n0.0017,1000\n0.003,1000\n");
  std::vector<std::string> warnings;
  read_measured_shear_curve(csv, 25e3, kWindow, "spec.toml", "k", warnings, kBoxLength);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("unevenly spaced"), std::string::npos) << warnings[0];
}

// --- a shear spec whose targets come from curves ------------------------------------------

namespace {

std::string shear_spec(const std::string& measured) {
  return "stage = \"shear\"\n[model]\nconfig = \"" COLZA_SOURCE_DIR "/tests/data/small_shear.toml\"\n"
         "[[parameters]]\nname = \"Cn\"\nkey = \"contact.contact_bond.normal_strength\"\ndesign = [0.5, 1.5, 2.5]\n"
         "[[parameters]]\nname = \"Cs\"\nkey = \"contact.contact_bond.shear_strength\"\ndesign = [3.0, 2.0, 3.0]\n"
         "[measured]\ncohesion_uncertainty = 500.0\ntan_phi_uncertainty = 0.02\n" + measured;
}

}  // namespace

TEST_F(MeasuredShearCurveTest, SpecTakesTheTargetsFromTheCurves) {
  even_curve("low.csv", 3.0, 1000.0);   // strength 1225 Pa
  even_curve("high.csv", 3.0, 2000.0);  // strength 2225 Pa
  const std::string spec = write("spec.toml", shear_spec("[[measured.curves]]\nnormal_stress = 20000.0\nfile = \"low.csv\"\n"
                                                         "[[measured.curves]]\nnormal_stress = 60000.0\nfile = \"high.csv\"\n"));
  const Spec s = read_spec(spec);
  ASSERT_EQ(s.measured_curves.size(), 2u);
  EXPECT_NEAR(s.measured_curves[1].shear_strength, 2225.0, 1e-9);
  const MohrCoulombFit line = fit_mohr_coulomb({20000.0, 60000.0}, {1225.0, 2225.0});
  EXPECT_EQ(s.problem.targets[0].name, "cohesion");
  EXPECT_DOUBLE_EQ(s.problem.targets[0].value, line.cohesion);
  EXPECT_DOUBLE_EQ(s.problem.targets[1].value, line.slope);
  EXPECT_EQ(s.loads, (std::vector<double>{20000.0, 60000.0}));
  EXPECT_TRUE(s.measured_file.empty());
}

TEST_F(MeasuredShearCurveTest, TheReportSaysHowEachSideOfAStrengthComparisonWasRead) {
  // Strengths as the lab stated them: colza cannot know how they were read off the lab's
  // curves, so it says what its own runs' strengths are (it used to say the lab's values were
  // "taken as the mean shear stress of the rows in the strength window").
  const Spec stated = read_spec(write("stated.toml", shear_spec("results = \"" COLZA_SOURCE_DIR
                                                                "/data/measured/shear_strength_paper_line.csv\"\n")));
  const std::string lab = measured_data_section(stated);
  EXPECT_NE(lab.find("as the lab stated them; the simulated ones they are compared with are the mean shear stress"),
            std::string::npos) << lab;
  EXPECT_EQ(lab.find("taken as"), std::string::npos) << lab;
  // From curves, colza reads both sides the same way and says so.
  even_curve("low.csv", 3.0, 1000.0);
  even_curve("high.csv", 3.0, 2000.0);
  const Spec curves = read_spec(write("curves.toml", shear_spec("[[measured.curves]]\nnormal_stress = 20000.0\nfile = "
                                                                "\"low.csv\"\n[[measured.curves]]\nnormal_stress = "
                                                                "60000.0\nfile = \"high.csv\"\n")));
  EXPECT_NE(measured_data_section(curves).find("derived from the measured curves as for the simulated ones"),
            std::string::npos);
}

TEST_F(MeasuredShearCurveTest, SpecErrorsNameTheCurveKey) {
  even_curve("low.csv", 3.0);
  even_curve("short.csv", 2.0);
  auto error = [&](const std::string& measured) { return spec_error(shear_spec(measured)); };
  const std::string both = error("results = \"r.csv\"\n[[measured.curves]]\nnormal_stress = 2e4\nfile = \"low.csv\"\n");
  EXPECT_EQ(both.rfind("measured.curves | give either", 0), 0u) << both;
  const std::string neither = error("");
  EXPECT_EQ(neither.rfind("measured.results | missing", 0), 0u) << neither;
  const std::string short_curve = error("[[measured.curves]]\nnormal_stress = 2e4\nfile = \"low.csv\"\n"
                                        "[[measured.curves]]\nnormal_stress = 6e4\nfile = \"short.csv\"\n");
  EXPECT_EQ(short_curve.rfind("measured.curves[1].file | ", 0), 0u) << short_curve;
  EXPECT_NE(short_curve.find("ends at a shear displacement of 0.002 m"), std::string::npos) << short_curve;
  const std::string one_load = error("[[measured.curves]]\nnormal_stress = 2e4\nfile = \"low.csv\"\n");
  EXPECT_EQ(one_load.rfind("measured.curves | needs shear strengths at two or more", 0), 0u) << one_load;
  const std::string no_stress = error("[[measured.curves]]\nfile = \"low.csv\"\n");
  EXPECT_EQ(no_stress.rfind("measured.curves[0].normal_stress | missing", 0), 0u) << no_stress;
  const std::string misspelt = error("[[measured.curves]]\nnormal_stress = 2e4\nfiel = \"low.csv\"\n");
  EXPECT_EQ(misspelt.rfind("measured.curves[0].file | missing", 0), 0u) << misspelt;
}

TEST_F(MeasuredShearCurveTest, PeakStrengthSpecReadsThePeakOfEachCurve) {
  // Rows every 0.5 mm to 3 mm, tau = tau0 + 50 d (mm) with a bump of +400 Pa at 1.0 and 1.5
  // mm: with peak_width 0.5 mm the largest trailing mean is at 1.5 mm, over rows 1.0 and 1.5:
  // tau0 + 50 * 1.25 + 400.
  auto bumped = [&](const std::string& name, double tau0) {
    std::string t = "shear_displacement,shear_stress\n";
    for (int k = 0; k <= 6; ++k) {
      const double mm = 0.5 * k;
      t += std::to_string(0.0005 * k) + "," + std::to_string(tau0 + 50.0 * mm + ((k == 2 || k == 3) ? 400.0 : 0.0)) + "\n";
    }
    return write(name, t);
  };
  bumped("low.csv", 1000.0);
  even_curve("up.csv", 3.0);  // rises to its end
  bumped("high.csv", 2000.0);
  const std::string curves = "[[measured.curves]]\nnormal_stress = 20000.0\nfile = \"low.csv\"\n"
                             "[[measured.curves]]\nnormal_stress = 60000.0\nfile = \"high.csv\"\n";
  const Spec s = read_spec(write("spec.toml", shear_spec("strength = \"peak\"\npeak_width = 0.0005\n" + curves)));
  ASSERT_TRUE(s.strength.peak);
  EXPECT_NEAR(s.measured_curves[0].shear_strength, 1000.0 + 62.5 + 400.0, 1e-9);
  EXPECT_NEAR(s.measured_curves[0].peak_displacement, 0.0015, 1e-12);
  EXPECT_EQ(s.measured_curves[0].window_points, 2u);
  EXPECT_NEAR(s.problem.targets[0].value, fit_mohr_coulomb({2e4, 6e4}, {1462.5, 2462.5}).cohesion, 1e-9);
  // C and tan(Phi) of one line: correlated, by the measured loads (20, 60 kPa: -80000 /
  // sqrt(2 * 4e9) = -0.894427), unless [measured] correlation says otherwise.
  ASSERT_EQ(s.problem.target_correlation.rows(), 2);
  EXPECT_NEAR(s.problem.target_correlation(0, 1), -0.894427, 1e-6);
  EXPECT_NEAR(s.problem.target_correlation(1, 0), -0.894427, 1e-6);
  const Spec given = read_spec(write("spec-rho.toml", shear_spec("correlation = 0.0\n" + curves)));
  EXPECT_EQ(given.problem.target_correlation(0, 1), 0.0);
  // The same curves by the window (1.5 .. 3 mm): the plain mean of four rows.
  const Spec w = read_spec(write("spec2.toml", shear_spec(curves)));
  EXPECT_FALSE(w.strength.peak);
  EXPECT_NEAR(w.measured_curves[0].shear_strength, 1000.0 + 50.0 * 2.25 + 100.0, 1e-9);
  // Errors: an unknown definition, a width without the peak, a curve shorter than the width.
  auto error = [&](const std::string& measured) { return spec_error(shear_spec(measured)); };
  const std::string kind = error("strength = \"max\"\n" + curves);
  EXPECT_EQ(kind.rfind("measured.strength | must be \"window\"", 0), 0u) << kind;
  const std::string width = error("peak_width = 0.001\n" + curves);
  EXPECT_EQ(width.rfind("measured.peak_width | only with strength = \"peak\"", 0), 0u) << width;
  const std::string too_wide = error("strength = \"peak\"\npeak_width = 0.004\n" + curves);
  EXPECT_EQ(too_wide.rfind("measured.peak_width | the peak width 0.004 m must be shorter than the simulated shear "
                           "displacement (shear_box.shear_displacement = 0.003 m)", 0), 0u) << too_wide;
  even_curve("short.csv", 1.0);
  const std::string too_short = error("strength = \"peak\"\npeak_width = 0.002\n[[measured.curves]]\nnormal_stress = "
                                      "20000.0\nfile = \"short.csv\"\n[[measured.curves]]\nnormal_stress = 60000.0\n"
                                      "file = \"high.csv\"\n");
  EXPECT_EQ(too_short.rfind("measured.curves[0].file | ", 0), 0u) << too_short;
  EXPECT_NE(too_short.find("spans 0.001 m of shear displacement, less than the peak width 0.002 m"), std::string::npos)
      << too_short;
  // A curve still rising at its end: the peak is not known, a warning says so.
  EXPECT_TRUE(s.warnings.empty());
  const Spec rising = read_spec(write("rising.toml", shear_spec("strength = \"peak\"\npeak_width = 0.0005\n"
                                                                "[[measured.curves]]\nnormal_stress = 20000.0\nfile = \"up.csv\"\n"
                                                                "[[measured.curves]]\nnormal_stress = 60000.0\nfile = \"high.csv\"\n")));
  ASSERT_EQ(rising.warnings.size(), 1u);
  EXPECT_NE(rising.warnings[0].find("up.csv: the largest mean lies in the curve's last 0.0005 m"), std::string::npos)
      << rising.warnings[0];
}
