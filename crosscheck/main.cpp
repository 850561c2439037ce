// crosscheck: runs colza and YADE on the same problems and compares them (physics.md
// section 6; YADE is the independent referee of colza's physics).
//
//   crosscheck micro|oedometer|shear|all [--size small|full|small_rolling] [--colza PATH] [--yade PATH]
//              [--workdir DIR] [--source DIR] [--tolerances FILE] [--reuse] [--loads PA,PA,..]
//
//   micro      deterministic 2-3 body scenes (crosscheck/scenes/micro_*.toml) run by
//              `colza run scene` and yade-scripts/run_scene.py; their time series must agree
//              to the tolerances of data/crosscheck-tolerances.toml;
//   oedometer  both codes load the same settled packing (--size small: the committed
//              208-sphere packing; --size full: the paper's packing, generated first by
//              `colza run oedometer` with data/oedometer.toml); compares the force-displacement
//              curves, and for the small packing the mean forces of an ensemble of realisations
//              (crosscheck/README.md, "Ensembles");
//   shear      both codes run the direct shear box from the same packing (made once by
//              `colza run shear`; --size small: crosscheck/scenes/shear_small.toml, --size
//              full: scenes/shear_full.toml, data/shear.toml's geometry); a short
//              deterministic start must coincide, then per load the shear strength, mean
//              normal stress and shear-stress curve, and C and Phi of the loads, are compared;
//              --size small then runs an ensemble of realisations of every load in both codes
//              and compares the mean strengths, C and Phi by Welch's t test;
//   all        micro, the small oedometer and shear (and the full ones with --size full).
//
// --reuse: a run whose output directory in --workdir already holds summary.json (both codes
// write it last) is not run again if its stamp (<out>.inputs, run_stamp.hpp: command, config,
// packings, program) matches, so an interrupted full-size cross-check (hours of YADE)
// continues where it stopped; a run of other inputs is run again. A finished run without a
// stamp (a load run by hand) is taken with a notice. The tolerance table is not stamped: what
// of it shapes a run (a config, the ensemble's perturbation, the early steps) reaches the run
// through its command, config or packing, which are.
// --loads: the shear box runs these normal stresses (Pa) instead of [shear.<size>] loads, e.g.
// two of the four full-size loads when the others are not finished (C and Phi are then those
// of the line through the given loads; the table says so).
//
// Ctrl-C, SIGTERM or SIGHUP to crosscheck stops the runs in progress (SIGTERM to each run's
// process group, child_process.hpp) and then crosscheck, by that signal.
//
// Prints a table (metric, colza, YADE, difference and its kind, tolerance, PASS/FAIL, the
// tolerances file's key; report.hpp) and both codes' speed, and keeps them in the work dir as
// verdict-<command>-<size>.txt and .csv. Exit code: 0 all passed, 1 something failed (a run
// that fails is a FAIL row saying why), 2 bad usage (--loads with two loads the same to the pascal or in
// kPa, --loads or --size full with a command that has no use for them, a --colza that is not
// there or not executable, a --yade that is not there), a tolerances file that cannot be
// read, has a key of a wrong name, type or range, or names a config or scene that is not in
// the source tree (tolerances.hpp), or a --workdir that cannot be made or written; 77 YADE is
// not installed and no --yade was given (CTest SKIP_RETURN_CODE).
//
// This file reads the command line and runs the checks; the comparisons are in
// micro_check.cpp, oedometer_check.cpp and shear_check.cpp (checks.hpp), the runs of both
// codes in code_runs.cpp, the table in report.cpp.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <toml++/toml.h>

#include <unistd.h>

#include "checks.hpp"
#include "child_process.hpp"
#include "code_runs.hpp"
#include "options.hpp"
#include "report.hpp"
#include "result_files.hpp"
#include "speed_tally.hpp"
#include "tolerances.hpp"

using namespace crosscheck;

namespace {

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "crosscheck: %s\n", msg);
  std::fprintf(stderr,
               "usage: crosscheck micro|oedometer|shear|all [--size small|full|small_rolling] [--colza PATH] [--yade PATH]\n"
               "                  [--workdir DIR] [--source DIR] [--tolerances FILE] [--reuse] [--loads PA,PA,..]\n");
  return kExitUsage;
}

// Makes the work folder; "" when it exists and takes files (a scratch folder made and
// removed), otherwise why not.
std::string workdir_problem(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return "cannot create the directory: " + ec.message();
  const fs::path probe = dir / (".crosscheck-write-test-" + std::to_string(::getpid()));
  fs::create_directory(probe, ec);
  if (ec) return "cannot write into the directory: " + ec.message();
  fs::remove(probe, ec);
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
#ifdef COLZA_SOURCE_DIR
  opt.source = COLZA_SOURCE_DIR;
#endif
#ifdef COLZA_EXECUTABLE
  opt.colza = COLZA_EXECUTABLE;
#endif
  bool colza_given = false, yade_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--size") opt.size = value();
      else if (a == "--colza") opt.colza = value(), colza_given = true;
      else if (a == "--yade") opt.yade = value(), yade_given = true;
      else if (a == "--workdir") opt.workdir = value();
      else if (a == "--source") opt.source = value();
      else if (a == "--tolerances") opt.tolerances = value();
      else if (a == "--reuse") opt.reuse = true;
      else if (a == "--loads") {
        std::stringstream list(value());
        for (std::string item; std::getline(list, item, ',');) {
          std::size_t used = 0;
          double v = 0.0;
          try {
            v = std::stod(item, &used);
          } catch (const std::exception&) {
            used = 0;
          }
          if (used == 0 || used != item.size() || !(v > 0.0)) throw std::invalid_argument("--loads: \"" + item + "\" is not a normal stress > 0 (Pa)");
          if (const std::string why = load_in_kpa(v); !why.empty()) throw std::invalid_argument("--loads: " + why);
          opt.loads.push_back(v);
        }
        if (opt.loads.empty()) throw std::invalid_argument("--loads needs at least one normal stress (Pa)");
        if (const std::string why = loads_sharing_a_run(opt.loads); !why.empty()) throw std::invalid_argument("--loads: " + why);
      }
      else if (a == "-h" || a == "--help") return usage(nullptr), 0;
      else if (!a.empty() && a[0] == '-') return usage(("unknown option " + a).c_str());
      else if (opt.what.empty()) opt.what = a;
      else return usage("one command only");
    } catch (const std::exception& e) {
      return usage(e.what());
    }
  }
  if (opt.what != "micro" && opt.what != "oedometer" && opt.what != "shear" && opt.what != "all")
    return usage("command must be micro, oedometer, shear or all");
  if (opt.size != "small" && opt.size != "full" && opt.size != "small_rolling")
    return usage("--size must be small, full or small_rolling");
  if (opt.size == "small_rolling" && opt.what != "oedometer")
    return usage("--size small_rolling (the small oedometer with rolling resistance) is for oedometer only");
  // Options the command has no use for are refused rather than ignored.
  if (opt.what == "micro" && opt.size != "small")
    return usage("micro has one size (its scenes); --size full applies to oedometer, shear and all");
  if (!opt.loads.empty() && opt.what != "shear" && opt.what != "all")
    return usage(("--loads applies to shear and all (the shear box's loads), not to " + opt.what).c_str());
  if (opt.source.empty() || !fs::exists(opt.source / "yade-scripts" / "run_scene.py"))
    return usage("cannot find the colza source tree (yade-scripts/); give --source");
  if (colza_given && !fs::exists(opt.colza)) return usage(("--colza " + opt.colza.string() + ": no such file").c_str());
  if (opt.colza.empty() || !fs::exists(opt.colza))
    return usage(("cannot find the colza executable" +
                  (opt.colza.empty() ? std::string() : " this crosscheck was built with (" + opt.colza.string() + ")") +
                  "; give --colza")
                     .c_str());
  if (!fs::is_regular_file(opt.colza) || access(opt.colza.c_str(), X_OK) != 0)
    return usage(("--colza " + opt.colza.string() + ": not an executable file").c_str());
  if (opt.tolerances.empty()) opt.tolerances = opt.source / "data" / "crosscheck-tolerances.toml";
  if (opt.workdir.empty()) opt.workdir = fs::current_path() / "crosscheck-work";
  opt.colza = fs::absolute(opt.colza);
  opt.source = fs::absolute(opt.source);
  opt.workdir = fs::absolute(opt.workdir);

  // The tolerances are read first: a broken file is an error on a machine without YADE too
  // (where every check is skipped), so CI without YADE still notices it.
  toml::table tol;
  try {
    tol = read_tolerances(opt.tolerances, opt.what, opt.size, opt.source);
  } catch (const ToleranceError& e) {
    std::fprintf(stderr, "crosscheck: error: %s\n", e.what());
    return kExitUsage;
  }
  // A YADE the user named with --yade (a path or a command, the default's name included) that
  // is not there is a mistake, not a machine without YADE.
  if (opt.yade.find('/') != std::string::npos && !fs::exists(opt.yade))
    return usage(("--yade " + opt.yade + ": no such file").c_str());
  if (!yade_available(opt.yade)) {
    if (yade_given) return usage(("--yade " + opt.yade + ": no such command on PATH").c_str());
    std::printf("crosscheck: SKIPPED: YADE is not installed ('%s' is not on PATH); install the Debian package yade\n",
                opt.yade.c_str());
    return kExitSkip;
  }
  if (const std::string why = workdir_problem(opt.workdir); !why.empty()) {
    std::fprintf(stderr, "crosscheck: error: --workdir %s: %s\n", opt.workdir.string().c_str(), why.c_str());
    return kExitUsage;
  }
  const std::string started = "crosscheck " + opt.what + " (--size " + opt.size + "): colza " + opt.colza.string() +
                              ", YADE '" + opt.yade + "', tolerances " + opt.tolerances.string() + ", work in " +
                              opt.workdir.string() + "\n";
  std::printf("%s", started.c_str());
  std::fflush(stdout);

  forward_stop_signals();  // Ctrl-C or SIGTERM stops the runs in progress too (child_process.hpp)
  const CodeRuns runs(opt);
  SpeedTally speed;
  const CheckContext ctx{opt, tol, runs, speed};
  Report report;
  try {
    if (opt.what == "micro" || opt.what == "all") check_micro(ctx, report);
    if (opt.what == "oedometer") check_oedometer(ctx, report, opt.size);
    if (opt.what == "all") {
      check_oedometer(ctx, report, "small");
      if (opt.size == "full") check_oedometer(ctx, report, "full");
    }
    if (opt.what == "shear") check_shear(ctx, report, opt.size);
    if (opt.what == "all") {
      check_shear(ctx, report, "small");
      if (opt.size == "full") check_shear(ctx, report, "full");
    }
  } catch (const fs::filesystem_error& e) {  // a folder of the work dir that cannot be made (a file in its place)
    std::fprintf(stderr, "crosscheck: error: in --workdir %s: %s\n", opt.workdir.string().c_str(), e.what());
    return kExitUsage;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crosscheck: error: %s\n", e.what());
    return kExitFail;
  }
  const std::string verdict = report.text() + "\n" + speed.text();
  std::printf("\n%s", verdict.c_str());
  // Kept beside the runs, whole or not at all (write_whole): the table and its rows as CSV.
  const fs::path kept = opt.workdir / ("verdict-" + opt.what + "-" + opt.size);
  try {
    write_whole(kept.string() + ".txt", started + "\n" + verdict);
    write_whole(kept.string() + ".csv", report.csv());
    std::printf("crosscheck: this table is kept in %s.txt (its rows also in .csv)\n", kept.string().c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crosscheck: warning: the table could not be kept: %s\n", e.what());
  }
  return report.all_passed() ? 0 : kExitFail;
}
