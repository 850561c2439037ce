// The three comparisons of crosscheck (README.md, "What is compared"), each adding its rows
// to the report: the micro scenes, the oedometer and the shear box.
#pragma once
#include <string>
#include <toml++/toml.h>
#include "code_runs.hpp"
#include "options.hpp"
#include "report.hpp"
#include "speed_tally.hpp"

namespace crosscheck {

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

}  // namespace crosscheck
