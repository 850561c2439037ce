// The cross-check's comparisons (crosscheck/checks.hpp) on made-up results of the two codes:
// a value that is not finite, in either code, fails its row and the row says so (a running
// maximum by std::max skipped NaN, and an all-NaN YADE series passed every micro row); the
// oedometer fails when YADE's summary does not report its cylinder patches.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "crosscheck/checks.hpp"
#include "scratch_dir.hpp"

namespace {

using crosscheck::compare_oedometer_curves;
using crosscheck::compare_scene_series;
using crosscheck::compare_shear_start;
using crosscheck::Csv;
using crosscheck::Report;
using crosscheck::Row;

const double kNaN = std::nan("");
const crosscheck::Tolerance kRelative{1e-6, "micro.relative"};
const crosscheck::Tolerance kContacts = crosscheck::fixed_tolerance(0.0);

// The row whose metric contains `part` (the test fails if there is none).
Row row_of(const Report& report, const std::string& part) {
  for (const Row& r : report.rows())
    if (r.metric.find(part) != std::string::npos) return r;
  ADD_FAILURE() << "no row with \"" << part << "\"";
  return {};
}

bool says_not_finite(const Row& r) { return r.difference.find("not finite") != std::string::npos; }

// A micro scene's series: one particle p0 with position, velocity, angular velocity, force and
// torque (smooth made-up values, 4 rows), and a contact count.
Csv scene_series() {
  Csv s;
  s.names = {"step"};
  for (const char* q : {"", "v", "w", "f", "t"})
    for (const char* a : {"x", "y", "z"}) s.names.push_back(std::string("p0_") + q + a);
  s.names.push_back("contacts");
  s.columns.resize(s.names.size());
  for (std::size_t r = 0; r < 4; ++r) {
    s.columns[0].push_back(static_cast<double>(10 * r));
    for (std::size_t k = 1; k + 1 < s.names.size(); ++k) s.columns[k].push_back(0.1 * k * (1.0 + r * r));
    s.columns.back().push_back(1.0);
  }
  return s;
}

const std::map<std::string, double> kFloor = {
    {"position", 1e-12}, {"velocity", 1e-12}, {"angular_velocity", 1e-9}, {"force", 1e-12}, {"torque", 1e-15}};

TEST(CrosscheckComparisons, MicroSeriesThatAgreePass) {
  Report report;
  compare_scene_series(report, "scene", scene_series(), scene_series(), kRelative, kContacts, kFloor);
  EXPECT_EQ(report.rows().size(), 6u);  // five quantities and the contacts
  EXPECT_TRUE(report.all_passed());
}

// The reviewer's fake YADE: colza's series with every compared column NaN. Each of the six
// rows passed (max |diff| = 0); each must fail and say that a YADE value was not finite.
TEST(CrosscheckComparisons, MicroSeriesOfNaNFailEveryRow) {
  const Csv colza = scene_series();
  Csv yade = colza;
  for (std::size_t k = 1; k < yade.columns.size(); ++k)
    for (double& v : yade.columns[k]) v = kNaN;
  Report report;
  compare_scene_series(report, "scene", colza, yade, kRelative, kContacts, kFloor);
  ASSERT_EQ(report.rows().size(), 6u);
  for (const Row& r : report.rows()) {
    EXPECT_FALSE(r.pass) << r.metric;
    EXPECT_EQ(r.difference, "a YADE value not finite") << r.metric;
  }
}

// One NaN in one row of one component, in either code, fails that quantity only.
TEST(CrosscheckComparisons, MicroSeriesWithOneValueThatIsNotFinite) {
  const Csv colza = scene_series();
  Csv yade = colza;
  yade.columns[5][2] = kNaN;  // p0_vy, row 2
  Report report;
  compare_scene_series(report, "scene", colza, yade, kRelative, kContacts, kFloor);
  EXPECT_FALSE(row_of(report, "velocity (p0)").pass);
  EXPECT_TRUE(says_not_finite(row_of(report, "velocity (p0)")));
  EXPECT_TRUE(row_of(report, "position (p0)").pass);
  EXPECT_TRUE(row_of(report, "angular_velocity (p0)").pass);

  Csv colza_inf = colza;
  colza_inf.columns[13][1] = std::numeric_limits<double>::infinity();  // p0_tx, row 1
  Report colza_report;
  compare_scene_series(colza_report, "scene", colza_inf, colza, kRelative, kContacts, kFloor);
  EXPECT_FALSE(row_of(colza_report, "torque (p0)").pass);
  EXPECT_EQ(row_of(colza_report, "torque (p0)").difference, "a colza value not finite");

  Csv yade_contacts = colza;
  yade_contacts.columns.back()[3] = kNaN;
  Report contacts_report;
  compare_scene_series(contacts_report, "scene", colza, yade_contacts, kRelative, kContacts, kFloor);
  EXPECT_FALSE(row_of(contacts_report, "contacts").pass);
  EXPECT_TRUE(says_not_finite(row_of(contacts_report, "contacts")));
}

// A signal that is zero in colza (a torque by symmetry) with a zero floor: YADE's zero agrees
// (0 / 0 is no difference), any other YADE value fails, as max_difference judges it.
TEST(CrosscheckComparisons, MicroZeroSignalWithAZeroFloor) {
  Csv colza = scene_series();
  for (std::size_t k = 13; k <= 15; ++k)
    for (double& v : colza.columns[k]) v = 0.0;  // p0_tx, ty, tz
  std::map<std::string, double> no_floor = kFloor;
  no_floor["torque"] = 0.0;
  Report same;
  compare_scene_series(same, "scene", colza, colza, kRelative, kContacts, no_floor);
  EXPECT_TRUE(row_of(same, "torque (p0)").pass);
  Csv yade = colza;
  yade.columns[14][2] = 1e-30;
  Report other;
  compare_scene_series(other, "scene", colza, yade, kRelative, kContacts, no_floor);
  EXPECT_FALSE(row_of(other, "torque (p0)").pass);
}

// An oedometer curve: piston travel 0-8 mm in 0.5 mm rows, force 2e5 N/m x travel (up to
// 1600 N), 100 contacts; summaries of 208 particles.
Csv oedometer_curve() {
  Csv c;
  c.names = {"piston_displacement", "piston_force", "contacts"};
  c.columns.resize(3);
  for (int r = 0; r <= 16; ++r) {
    c.columns[0].push_back(0.0005 * r);
    c.columns[1].push_back(2e5 * 0.0005 * r);
    c.columns[2].push_back(100.0);
  }
  return c;
}

toml::table oedometer_tolerances() {
  return toml::parse(
      "early_rows = 10\nearly_relative = 1e-5\nrms_relative = 0.15\nforce_at_relative = 0.20\n"
      "travels = [0.005, 0.006]\n");
}

const nlohmann::json kColzaSummary = {{"particles", 208}, {"stop_reason", "travel"}};
const nlohmann::json kYadeSummary = {{"particles", 208}, {"stop_reason", "travel"}, {"foreign_patch_contacts", 0}};

// The oedometer comparison of oedometer_curve() (colza) against `yade`, with these summaries.
Report compare_oedometer(const Csv& yade, const nlohmann::json& colza_summary = kColzaSummary,
                         const nlohmann::json& yade_summary = kYadeSummary) {
  const colza::testing::ScratchDir dir;
  Report report;
  const toml::table tolerances = oedometer_tolerances();
  compare_oedometer_curves(report, "oed", oedometer_curve(), yade, {tolerances, "oedometer.small"}, colza_summary,
                           yade_summary, dir / "no-config.toml");
  return report;
}

TEST(CrosscheckComparisons, OedometerCurvesThatAgreePass) {
  const Report report = compare_oedometer(oedometer_curve());
  EXPECT_TRUE(report.all_passed());
}

// Without the count of foreign patch contacts in YADE's summary the check cannot say the
// patches touched only their own spheres: it fails (it passed as a count of 0; the ensemble
// already failed it).
TEST(CrosscheckComparisons, OedometerFailsWithoutYadesPatchCount) {
  nlohmann::json yade_summary = kYadeSummary;
  yade_summary.erase("foreign_patch_contacts");
  const Report report = compare_oedometer(oedometer_curve(), kColzaSummary, yade_summary);
  EXPECT_FALSE(report.all_passed());
  const Row patches = row_of(report, "YADE cylinder patches");
  EXPECT_FALSE(patches.pass);
  EXPECT_NE(patches.difference.find("no foreign_patch_contacts"), std::string::npos) << patches.difference;

  yade_summary["foreign_patch_contacts"] = 2;
  const Report touched = compare_oedometer(oedometer_curve(), kColzaSummary, yade_summary);
  EXPECT_FALSE(row_of(touched, "YADE cylinder patches").pass);
}

// Each row names the tolerances file's key that judged it and what kind of difference it is
// (a walk-through read "mean normal stress (kPa) ... 4.298e-03" as kPa): a key the file has,
// one it leaves out (the check's own value, "(default)"), and an agreement the check fixes.
TEST(CrosscheckComparisons, RowsNameTheirToleranceKeyAndKind) {
  const Report report = compare_oedometer(oedometer_curve());
  const Row rms = row_of(report, "rms difference");
  EXPECT_EQ(rms.key, "oedometer.small.rms_relative");
  EXPECT_EQ(rms.measure, "rel");
  const Row particles = row_of(report, "oed particles");
  EXPECT_EQ(particles.key, "(fixed)");
  EXPECT_EQ(particles.measure, "abs");

  toml::table without = oedometer_tolerances();
  without.erase("early_relative");
  const crosscheck::Tolerance early = crosscheck::ToleranceSection{without, "oedometer.small"}.get("early_relative", 1e-5);
  EXPECT_EQ(early.key, "oedometer.small.early_relative (default)");
  EXPECT_EQ(early.value, 1e-5);
}

// The table as printed and kept: every column with its header, the legend of the kinds and
// keys, the count; and its CSV with a metric holding a comma and a quote quoted.
TEST(CrosscheckComparisons, TheTableAndItsCsvCarryEveryColumn) {
  Report report;
  report.check("shear 25.75 kPa \"mean\", normal stress", 25.75, 25.80, 0.002, crosscheck::Measure::kRelative,
               {0.01, "shear.small.normal_stress_relative"});
  report.fail("shear 78.75 kPa", "run failed");
  const std::string text = report.text();
  for (const char* part : {"tolerance key", "kind", "shear.small.normal_stress_relative", "PASS", "FAIL",
                           "kind: rel = |colza - YADE|", "crosscheck: 1 passed, 1 failed"})
    EXPECT_NE(text.find(part), std::string::npos) << part << " not in\n" << text;
  EXPECT_EQ(report.csv(),
            "metric,colza,yade,difference,kind,tolerance,result,tolerance_key\n"
            "\"shear 25.75 kPa \"\"mean\"\", normal stress\",25.75,25.8,2.000e-03,rel,1.0e-02,PASS,"
            "shear.small.normal_stress_relative\n"
            "shear 78.75 kPa,-,-,run failed,,-,FAIL,\n");
}

// A summary without its particle count fails the count's row (both missing read as 0 and
// passed).
TEST(CrosscheckComparisons, OedometerFailsWithoutAParticleCount) {
  nlohmann::json colza_summary = kColzaSummary, yade_summary = kYadeSummary;
  colza_summary.erase("particles");
  yade_summary.erase("particles");
  const Report report = compare_oedometer(oedometer_curve(), colza_summary, yade_summary);
  EXPECT_FALSE(row_of(report, "oed particles").pass);
}

// YADE's forces NaN: the first rows fail and say so (max_difference gave 0 and passed them).
TEST(CrosscheckComparisons, OedometerFirstRowsOfNaNFail) {
  Csv yade = oedometer_curve();
  for (double& f : yade.columns[1]) f = kNaN;
  const Report report = compare_oedometer(yade);
  const Row first = row_of(report, "first 10 rows");
  EXPECT_FALSE(first.pass);
  EXPECT_EQ(first.difference, "a YADE value not finite");
  EXPECT_FALSE(row_of(report, "rms difference").pass);
  EXPECT_FALSE(row_of(report, "force at 5.0 mm").pass);
}

// A curve that stops before a travel fails that travel's row, saying which curve.
TEST(CrosscheckComparisons, OedometerCurveThatStopsBeforeATravel) {
  Csv yade = oedometer_curve();
  for (auto& column : yade.columns) column.resize(12);  // up to 5.5 mm
  const Report report = compare_oedometer(yade);
  EXPECT_TRUE(row_of(report, "force at 5.0 mm").pass);
  const Row at_6 = row_of(report, "force at 6.0 mm");
  EXPECT_FALSE(at_6.pass);
  EXPECT_EQ(at_6.difference, "YADE's curve stops before this travel");
}

// The shear box's deterministic start: stresses and counts, 3 rows.
Csv shear_start() {
  Csv c;
  c.names = {"shear_stress", "normal_stress", "contacts", "bonds"};
  c.columns = {{100.0, 200.0, 300.0}, {1000.0, 1001.0, 1002.0}, {50.0, 51.0, 52.0}, {40.0, 40.0, 39.0}};
  return c;
}

TEST(CrosscheckComparisons, ShearStartWithValuesThatAreNotFinite) {
  Report same;
  compare_shear_start(same, "shear", shear_start(), shear_start(), kRelative);
  EXPECT_EQ(same.rows().size(), 3u);
  EXPECT_TRUE(same.all_passed());

  Csv yade = shear_start();
  for (double& v : yade.columns[0]) v = kNaN;  // shear stress
  yade.columns[3][1] = kNaN;                   // one bond count
  Report report;
  compare_shear_start(report, "shear", shear_start(), yade, kRelative);
  const Row stress = row_of(report, "shear_stress");
  EXPECT_FALSE(stress.pass);
  EXPECT_EQ(stress.difference, "a YADE value not finite");
  EXPECT_TRUE(row_of(report, "normal_stress").pass);
  const Row counts = row_of(report, "contacts and bonds");
  EXPECT_FALSE(counts.pass);
  EXPECT_EQ(counts.difference, "a YADE value not finite");
}

}  // namespace
