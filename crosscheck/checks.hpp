// The three comparisons of crosscheck (README.md, "What is compared"), each adding its rows
// to the report: the micro scenes, the oedometer and the shear box.
#pragma once
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <toml++/toml.h>
#include "code_runs.hpp"
#include "options.hpp"
#include "report.hpp"
#include "result_files.hpp"
#include "speed_tally.hpp"

namespace crosscheck {

// A key missing from a summary reads as this NaN, so the row comparing it fails
// (Report::check) instead of passing on a default that happens to agree.
inline constexpr double kMissingValue = std::numeric_limits<double>::quiet_NaN();

// A row that both codes' summaries give the same count under `key` (particles, say).
inline void check_same_count(Report& report, const std::string& metric, const nlohmann::json& cs,
                             const nlohmann::json& ys, const std::string& key) {
  const double c = cs.value(key, kMissingValue), y = ys.value(key, kMissingValue);
  report.check(metric, c, y, std::abs(c - y), Measure::kAbsolute, fixed_tolerance(0.0), "%.0f");
}

// What every check uses: the options, the tolerance table, the runs of both codes, and the
// speed tally the loadings add to.
struct CheckContext {
  const Options& opt;
  const toml::table& tol;
  const CodeRuns& runs;
  SpeedTally& speed;
};

// The tolerance table's section [<setup>.<size>] (e.g. [shear.small]) that a check of one
// size runs by; nullptr, and a failed row "<setup> <size>", when the file has none.
inline const toml::table* size_section(const CheckContext& ctx, Report& report, const std::string& setup,
                                       const std::string& size) {
  const std::string base = setup + "." + size;
  const toml::table* t = ctx.tol.at_path(base).as_table();
  if (!t) report.fail(setup + " " + size, "no [" + base + "] in the tolerances file");
  return t;
}

// Deterministic 2-3 body scenes ([micro.scenes]): time series compared particle by particle.
void check_micro(const CheckContext& ctx, Report& report);
// One settled packing loaded by both codes ([oedometer.<size>]): force-displacement curves.
void check_oedometer(const CheckContext& ctx, Report& report, const std::string& size);
// The direct shear box ([shear.<size>]): deterministic start, every load, C and Phi.
void check_shear(const CheckContext& ctx, Report& report, const std::string& size);

// The comparisons behind the checks, on results already read (the unit tests feed them
// made-up ones). A value of either code that is not finite fails its row (Report::check).
//
// One micro scene's series.csv of each code: per quantity kind the worst particle's (and wall
// force's) max |colza - YADE| / max(max |colza signal|, floor[kind]) against `relative`, and
// the contact counts against `contacts_tol`. Throws std::runtime_error if the two series have
// different columns, rows or steps.
void compare_scene_series(Report& report, const std::string& scene, const Csv& c, const Csv& y,
                          const Tolerance& relative, const Tolerance& contacts_tol,
                          const std::map<std::string, double>& floor);
// One oedometer loading's curve.csv and summary.json of each code by [oedometer.<size>] `t`:
// the same start (particles, contacts), the first rows (must coincide), the rms difference of
// the force over the logged range (from the fit's lower force of `config` to the smaller final
// travel), the force at the travels, and YADE's foreign_patch_contacts, which must be 0.
void compare_oedometer_curves(Report& report, const std::string& label, const Csv& c, const Csv& y,
                              const ToleranceSection& t, const nlohmann::json& cs, const nlohmann::json& ys,
                              const fs::path& config);
// The shear box's deterministic start, curve.csv of each code: shear and normal stress (max
// |diff| / max) against `relative`, contacts and bonds exactly. Throws std::runtime_error if
// the row counts differ.
void compare_shear_start(Report& report, const std::string& label, const Csv& c, const Csv& y, const Tolerance& relative);

}  // namespace crosscheck
