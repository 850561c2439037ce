// crosscheck: runs colza and YADE on the same problems and compares them (physics.md
// section 6; YADE is the independent referee of colza's physics).
//
//   crosscheck micro|oedometer|shear|all [--size small|full] [--colza PATH] [--yade PATH]
//              [--workdir DIR] [--source DIR] [--tolerances FILE] [--reuse] [--loads PA,PA,..]
//
//   micro      deterministic 2-3 body scenes (crosscheck/scenes/micro_*.toml) run by
//              `colza run scene` and yade-scripts/run_scene.py; their time series must agree
//              to the tolerances of data/crosscheck-tolerances.toml;
//   oedometer  both codes load the same settled packing (--size small: the committed
//              208-sphere packing; --size full: the paper's packing, generated first by
//              `colza run oedometer` with data/oedometer.toml); compares the force-displacement
//              curves;
//   shear      both codes run the direct shear box from the same packing (made once by
//              `colza run shear`; --size small: crosscheck/scenes/shear_small.toml, --size
//              full: scenes/shear_full.toml, data/shear.toml's geometry); a short
//              deterministic start must coincide, then per load the shear strength, mean
//              normal stress and shear-stress curve, and C and Phi of the loads, are compared;
//   all        micro, the small oedometer and shear (and the full ones with --size full).
//
// --reuse: a run whose output directory in --workdir already holds summary.json (both codes
// write it last) is not run again, so an interrupted full-size cross-check (hours of YADE)
// continues where it stopped. Only for a workdir made from the same sources and configs.
// --loads: the shear box runs these normal stresses (Pa) instead of [shear.<size>] loads, e.g.
// two of the four full-size loads when the others are not finished (C and Phi are then those
// of the line through the given loads; the table says so).
//
// Prints a table (metric, colza, YADE, difference, tolerance, PASS/FAIL) and both codes'
// speed. Exit code: 0 all passed, 1 something failed, 2 bad usage or a run failed to
// start, 77 YADE is not installed (CTest SKIP_RETURN_CODE).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <sys/wait.h>
#include <toml++/toml.h>
#include <vector>

namespace fs = std::filesystem;

namespace {

constexpr int kExitFail = 1;
constexpr int kExitUsage = 2;
constexpr int kExitSkip = 77;

// ---- small utilities ----------------------------------------------------------------

struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  std::size_t rows() const { return columns.empty() ? 0 : columns[0].size(); }
  const std::vector<double>* column(const std::string& name) const {
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == name) return &columns[k];
    return nullptr;
  }
  const std::vector<double>& at(const std::string& name) const {
    const auto* c = column(name);
    if (!c) throw std::runtime_error("no column " + name);
    return *c;
  }
};

Csv read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  Csv csv;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file.string() + " is empty");
  {
    std::stringstream s(line);
    std::string name;
    while (std::getline(s, name, ',')) csv.names.push_back(name);
  }
  csv.columns.resize(csv.names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::stringstream s(line);
    std::string cell;
    std::size_t k = 0;
    while (std::getline(s, cell, ',') && k < csv.columns.size()) csv.columns[k++].push_back(std::strtod(cell.c_str(), nullptr));
    if (k != csv.columns.size()) throw std::runtime_error(file.string() + ": short row");
  }
  return csv;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nlohmann::json::object();
  try {
    return nlohmann::json::parse(in);
  } catch (...) {
    return nlohmann::json::object();
  }
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs a shell command with output to `log`; returns the exit status and the wall time.
struct RunResult {
  int status = -1;
  double seconds = 0.0;
};

RunResult run_logged(const std::string& command, const fs::path& log) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::string full = command + " > " + quote(log.string()) + " 2>&1 < /dev/null";
  const int raw = std::system(full.c_str());
  RunResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
  return r;
}

std::string tail_of(const fs::path& log, std::size_t lines = 15) {
  std::ifstream in(log);
  std::vector<std::string> all;
  std::string line;
  while (std::getline(in, line)) all.push_back(line);
  std::string out;
  for (std::size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i) out += "    " + all[i] + "\n";
  return out;
}

// ---- the result table -----------------------------------------------------------------

struct Row {
  std::string metric;
  std::string colza, yade, difference, tolerance;
  bool pass = true;
  bool info = false;  // informational row, no verdict
};

std::string fmt(double v, const char* f = "%.4g") {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

class Report {
 public:
  void add(Row r) { rows_.push_back(std::move(r)); }
  void check(const std::string& metric, double colza, double yade, double difference, double tolerance,
             const char* f = "%.4g") {
    Row r{metric, fmt(colza, f), fmt(yade, f), fmt(difference, "%.3e"), fmt(tolerance, "%.1e"), false, false};
    r.pass = std::isfinite(difference) && difference <= tolerance;
    add(r);
  }
  void fail(const std::string& metric, const std::string& why) { add(Row{metric, "-", "-", why, "-", false, false}); }
  void info(const std::string& metric, const std::string& colza, const std::string& yade, const std::string& note) {
    add(Row{metric, colza, yade, note, "-", true, true});
  }
  void note(const std::string& text) { notes_.push_back(text); }
  bool all_passed() const {
    return std::all_of(rows_.begin(), rows_.end(), [](const Row& r) { return r.pass; });
  }
  void print() const {
    std::size_t w[5] = {6, 5, 4, 10, 9};
    for (const Row& r : rows_) {
      w[0] = std::max(w[0], r.metric.size());
      w[1] = std::max(w[1], r.colza.size());
      w[2] = std::max(w[2], r.yade.size());
      w[3] = std::max(w[3], r.difference.size());
      w[4] = std::max(w[4], r.tolerance.size());
    }
    auto line = [&](const std::string& a, const std::string& b, const std::string& c, const std::string& d,
                    const std::string& e, const std::string& f) {
      std::printf("%-*s  %*s  %*s  %*s  %*s  %s\n", int(w[0]), a.c_str(), int(w[1]), b.c_str(), int(w[2]), c.c_str(),
                  int(w[3]), d.c_str(), int(w[4]), e.c_str(), f.c_str());
    };
    line("metric", "colza", "YADE", "difference", "tolerance", "result");
    for (const Row& r : rows_) line(r.metric, r.colza, r.yade, r.difference, r.tolerance, r.info ? "info" : (r.pass ? "PASS" : "FAIL"));
    for (const std::string& n : notes_) std::printf("%s\n", n.c_str());
    std::size_t passed = 0, failed = 0;
    for (const Row& r : rows_)
      if (!r.info) (r.pass ? passed : failed)++;
    std::printf("crosscheck: %zu passed, %zu failed\n", passed, failed);
  }

 private:
  std::vector<Row> rows_;
  std::vector<std::string> notes_;
};

// ---- settings --------------------------------------------------------------------------

struct Options {
  std::string what;
  std::string size = "small";
  fs::path colza, source, workdir, tolerances;
  std::string yade = "yade";
  bool reuse = false;
  std::vector<double> loads;  // --loads: overrides [shear.<size>] loads
};

double tol_number(const toml::table& t, const std::string& path, double fallback) {
  const auto v = t.at_path(path).value<double>();
  return v ? *v : fallback;
}

struct Speed {
  double particle_steps = 0.0;
  double colza_rate = 0.0, yade_rate = 0.0, yade_engine_rate = 0.0;
};

// ---- runners --------------------------------------------------------------------------

class Runner {
 public:
  Runner(Options opt, toml::table tol) : opt_(std::move(opt)), tol_(std::move(tol)) {}

  bool run_colza(const std::string& scenario, const fs::path& config, const fs::path& out,
                 const std::vector<std::string>& sets = {}, const std::vector<std::string>& extra = {}) {
    if (reused(out)) return true;
    std::string cmd = quote(opt_.colza.string()) + " run " + scenario + " --config " + quote(config.string()) +
                      " --out " + quote(out.string()) + " --force --quiet --threads 1";  // as YADE -j 1
    for (const auto& s : sets) cmd += " --set " + quote(s);
    for (const auto& e : extra) cmd += " " + quote(e);
    fs::create_directories(out.parent_path());
    const fs::path log = out.string() + ".log";
    const RunResult r = run_logged(cmd, log);
    if (r.status != 0) {
      std::fprintf(stderr, "crosscheck: colza failed (exit %d): %s\n%s", r.status, cmd.c_str(), tail_of(log).c_str());
      return false;
    }
    return true;
  }

  // --reuse: a finished run (summary.json present) stands.
  bool reused(const fs::path& out) const {
    if (!opt_.reuse || !fs::exists(out / "summary.json")) return false;
    std::printf("crosscheck: reusing %s\n", out.string().c_str());
    return true;
  }

  bool run_yade(const std::string& script, const fs::path& config, const fs::path& out,
                const std::vector<std::string>& extra = {}) {
    if (reused(out)) return true;
    const fs::path py = opt_.source / "yade-scripts" / script;
    std::string cmd = quote(opt_.yade) + " -n -j 1 -x " + quote(py.string()) + " " + quote(config.string()) + " " +
                      quote(out.string());
    for (const auto& e : extra) cmd += " " + quote(e);
    fs::create_directories(out.parent_path());
    const fs::path log = out.string() + ".log";
    const RunResult r = run_logged(cmd, log);
    if (r.status != 0) {
      std::fprintf(stderr, "crosscheck: yade failed (exit %d): %s\n%s", r.status, cmd.c_str(), tail_of(log).c_str());
      return false;
    }
    return true;
  }

  // Accumulates each code's particle-steps and time on a loading both ran. The oedometer's
  // step counts are equal; a shear load's differ a little (consolidation ends when the
  // stress holds, a chaotic moment), so each rate is its own particle-steps / seconds.
  void add_speed(const fs::path& colza_out, const fs::path& yade_out, const std::string& what) {
    const auto c = read_json(colza_out / "summary.json");
    const auto y = read_json(yade_out / "summary.json");
    if (!c.contains("particle_steps_per_second") || !y.contains("particle_steps_per_second")) return;
    const double ps_y = y.value("particles", 0.0) * y.value("steps", 0.0);
    const double ps_c = c.value("particles", 0.0) * c.value("steps", 0.0);
    const double c_rate = c["particle_steps_per_second"].get<double>();
    if (ps_y <= 0.0 || ps_c <= 0.0 || c_rate <= 0.0) return;
    speed_.particle_steps += ps_y;
    colza_particle_steps_ += ps_c;
    colza_seconds_ += ps_c / c_rate;
    yade_seconds_ += y.value("wall_seconds", 0.0);
    yade_engine_seconds_ += y.value("wall_seconds", 0.0) - y.value("python_engine_seconds", 0.0);
    if (speed_what_.find(what) == std::string::npos) speed_what_ += (speed_what_.empty() ? "" : ", ") + what;
  }

  void micro(Report& report) {
    const fs::path scenes = opt_.source / "crosscheck" / "scenes";
    const toml::table* list = tol_.at_path("micro.scenes").as_table();
    if (!list || list->empty()) {
      report.fail("micro", "no [micro.scenes] in the tolerances file");
      return;
    }
    const double default_rel = tol_number(tol_, "micro.relative", 1e-6);
    const double contacts_tol = tol_number(tol_, "micro.contacts", 0.0);
    const std::map<std::string, double> floor = {
        {"position", tol_number(tol_, "micro.floor.position", 1e-12)},
        {"velocity", tol_number(tol_, "micro.floor.velocity", 1e-12)},
        {"angular_velocity", tol_number(tol_, "micro.floor.angular_velocity", 1e-9)},
        {"force", tol_number(tol_, "micro.floor.force", 1e-12)},
        {"torque", tol_number(tol_, "micro.floor.torque", 1e-15)}};
    for (const auto& [key, value] : *list) {
      const std::string name(key.str());
      const double rel = value.value<double>().value_or(default_rel);
      const fs::path config = scenes / (name + ".toml");
      const fs::path c_out = opt_.workdir / "colza" / name, y_out = opt_.workdir / "yade" / name;
      if (!run_colza("scene", config, c_out) || !run_yade("run_scene.py", config, y_out)) {
        report.fail(name, "run failed");
        continue;
      }
      try {
        compare_series(report, name, read_csv(c_out / "series.csv"), read_csv(y_out / "series.csv"), rel, contacts_tol,
                       floor);
      } catch (const std::exception& e) {
        report.fail(name, e.what());
      }
    }
  }

  void oedometer(Report& report, const std::string& size) {
    const std::string base = "oedometer." + size;
    const toml::table* t = tol_.at_path(base).as_table();
    if (!t) {
      report.fail("oedometer " + size, "no [" + base + "] in the tolerances file");
      return;
    }
    fs::path config = opt_.source / t->at_path("config").value_or(std::string());
    const fs::path work = opt_.workdir / ("oedometer_" + size);
    fs::create_directories(work);
    if (size == "full") {
      // Generate the paper's packing with colza's defaults, then load it with the loading
      // config (its packing_file is filled in here).
      const fs::path settle = opt_.source / t->at_path("settle_config").value_or(std::string("data/oedometer.toml"));
      const fs::path settled = work / "settle";
      if (!fs::exists(settled / "packing.txt")) {
        std::printf("crosscheck: generating and settling the full-size packing with colza (%s)...\n",
                    settle.string().c_str());
        std::fflush(stdout);
        if (!run_colza("oedometer", settle, settled)) {
          report.fail("oedometer full", "colza could not make the packing");
          return;
        }
      }
      std::ifstream in(config);
      std::stringstream text;
      text << in.rdbuf();
      std::string s = text.str();
      const std::string marker = "@PACKING@";
      const auto at = s.find(marker);
      if (at == std::string::npos) {
        report.fail("oedometer full", config.string() + " has no packing_file = \"@PACKING@\"");
        return;
      }
      s.replace(at, marker.size(), fs::absolute(settled / "packing.txt").string());
      config = work / "oedometer_full.toml";
      std::ofstream(config) << s;
    }
    const fs::path c_out = work / "colza", y_out = work / "yade";
    std::printf("crosscheck: oedometer %s: running colza and YADE...\n", size.c_str());
    std::fflush(stdout);
    if (!run_colza("oedometer", config, c_out) || !run_yade("run_oedometer.py", config, y_out)) {
      report.fail("oedometer " + size, "run failed");
      return;
    }
    add_speed(c_out, y_out, "oedometer " + size);
    try {
      compare_curves(report, "oed " + size, read_csv(c_out / "curve.csv"), read_csv(y_out / "curve.csv"), *t,
                     read_json(c_out / "summary.json"), read_json(y_out / "summary.json"), config);
    } catch (const std::exception& e) {
      report.fail("oedometer " + size, e.what());
    }
  }

  // Shear box: colza makes the sample once (generation + settling + cut, its packing.txt);
  // then, from that packing, (1) a short deterministic run (the stress is not consolidated,
  // shearing starts at once) must coincide in both codes like the micro scenes, and (2)
  // every load of [shear.<size>] runs the full protocol in both codes (servo consolidation,
  // bonds, shearing); the shear strength, the mean normal stress, the shear-stress curve over
  // the strength window and the Mohr-Coulomb C and Phi of the loads are compared.
  void shear(Report& report, const std::string& size) {
    const std::string base = "shear." + size;
    const toml::table* t = tol_.at_path(base).as_table();
    if (!t) {
      report.fail("shear " + size, "no [" + base + "] in the tolerances file");
      return;
    }
    const std::string label = "shear " + size;
    const fs::path scene = opt_.source / t->at_path("config").value_or(std::string());
    const fs::path work = opt_.workdir / ("shear_" + size);
    fs::create_directories(work);
    toml::table doc;
    try {
      doc = toml::parse_file(scene.string());
    } catch (const std::exception& e) {
      report.fail(label, "cannot read " + scene.string() + ": " + e.what());
      return;
    }
    toml::table* box = doc["shear_box"].as_table();
    if (!box) {
      report.fail(label, scene.string() + " has no [shear_box]");
      return;
    }
    std::vector<double> loads = opt_.loads;
    if (!loads.empty()) {
      std::string list;
      for (double l : loads) list += (list.empty() ? "" : ", ") + fmt(1e-3 * l, "%.2f");
      report.note(label + ": the loads given by --loads (" + list + " kPa), not those of [" + base + "]");
    } else if (const auto* a = t->at_path("loads").as_array()) {
      for (const auto& n : *a) loads.push_back(n.value<double>().value_or(0.0));
    }
    if (loads.empty()) {
      report.fail(label, "no loads in [" + base + "]");
      return;
    }
    // 1. The sample, made once by colza (the load of this run is cut short: it only makes
    // packing.txt).
    const fs::path prep = work / "sample";
    if (!fs::exists(prep / "packing.txt")) {
      std::printf("crosscheck: %s: colza makes the sample (generation, settling, cut)...\n", label.c_str());
      std::fflush(stdout);
      if (!run_colza("shear", scene, prep,
                     {"shear_box.consolidation_max_time=1e-9", "shear_box.strength_window_start=0",
                      "shear_box.strength_window_end=1e-9", "shear_box.shear_displacement=1e-9"},
                     {"--normal-stress", fmt(loads[0], "%.17g")})) {
        report.fail(label, "colza could not make the sample");
        return;
      }
    }
    box->insert_or_assign("packing_file", fs::absolute(prep / "packing.txt").string());
    // The tolerances table may shorten the shearing (a YADE load of the full box to 30 mm
    // takes hours): these keys replace the scene's and are printed with the table.
    for (const char* key : {"shear_displacement", "strength_window_start", "strength_window_end"})
      if (const auto v = t->at_path(key).value<double>()) {
        box->insert_or_assign(key, *v);
        std::printf("crosscheck: %s: shear_box.%s = %g (from [%s])\n", label.c_str(), key, *v, base.c_str());
      }
    auto write_config = [&](const toml::table& d, const std::string& name) {
      const fs::path f = work / name;
      std::ofstream o(f);
      o << "# written by crosscheck from " << scene.string() << "\n" << d << "\n";
      return f;
    };
    const fs::path config = write_config(doc, "shear_" + size + ".toml");
    const double dt = doc.at_path("integration.time_step").value_or(0.0);
    const double ws = box->at_path("strength_window_start").value_or(0.020);
    const double we = box->at_path("strength_window_end").value_or(0.030);

    // 2. Deterministic start: no consolidation (the servo runs 4 steps), shearing at once
    // for early_steps; before chaos sets in the two codes must coincide.
    {
      const double speed = box->at_path("shear_speed").value_or(0.005);
      const double early_steps = tol_number(*t, "early_steps", 400);
      const double disp = early_steps * dt * speed;
      toml::table e = doc;
      toml::table& eb = *e["shear_box"].as_table();
      eb.insert_or_assign("consolidation_max_time", 4 * dt);
      eb.insert_or_assign("shear_displacement", disp);
      eb.insert_or_assign("strength_window_start", 0.0);
      eb.insert_or_assign("strength_window_end", disp);
      eb.insert_or_assign("record_interval", 10);
      const fs::path econfig = write_config(e, "shear_" + size + "_early.toml");
      const fs::path c_out = work / "colza_early", y_out = work / "yade_early";
      const std::vector<std::string> sigma = {"--normal-stress", fmt(loads[0], "%.17g")};
      std::printf("crosscheck: %s: deterministic start (%g steps)...\n", label.c_str(), early_steps);
      std::fflush(stdout);
      if (!run_colza("shear", econfig, c_out, {}, sigma) || !run_yade("run_shear.py", econfig, y_out, sigma)) {
        report.fail(label + " deterministic start", "run failed");
      } else {
        try {
          const Csv c = read_csv(c_out / "curve.csv"), y = read_csv(y_out / "curve.csv");
          if (c.rows() != y.rows() || c.rows() == 0) throw std::runtime_error("different numbers of curve rows");
          for (const char* q : {"shear_stress", "normal_stress"}) {
            double num = 0.0, den = 0.0;
            for (std::size_t r = 0; r < c.rows(); ++r) {
              num = std::max(num, std::abs(c.at(q)[r] - y.at(q)[r]));
              den = std::max(den, std::abs(c.at(q)[r]));
            }
            report.check(label + " start, " + q + " (" + std::to_string(c.rows()) + " rows, max |diff| / max)", den,
                         den, den > 0 ? num / den : 0.0, tol_number(*t, "early_relative", 1e-6));
          }
          double dmax = 0.0;
          for (std::size_t r = 0; r < c.rows(); ++r)
            for (const char* q : {"contacts", "bonds"}) dmax = std::max(dmax, std::abs(c.at(q)[r] - y.at(q)[r]));
          report.check(label + " start, contacts and bonds (max |diff|)", c.at("contacts").back(),
                       y.at("contacts").back(), dmax, 0.0, "%.0f");
        } catch (const std::exception& ex) {
          report.fail(label + " deterministic start", ex.what());
        }
      }
    }

    // 3. The loads, full protocol.
    std::vector<double> c_strength, y_strength;
    for (double sigma : loads) {
      const std::string name = "load-" + fmt(sigma, "%.0f") + "Pa";
      const std::string l = label + " " + fmt(1e-3 * sigma, "%.2f") + " kPa";
      const fs::path c_out = work / ("colza_" + name), y_out = work / ("yade_" + name);
      const std::vector<std::string> arg = {"--normal-stress", fmt(sigma, "%.17g")};
      std::printf("crosscheck: %s: running colza and YADE...\n", l.c_str());
      std::fflush(stdout);
      if (!run_colza("shear", config, c_out, {}, arg) || !run_yade("run_shear.py", config, y_out, arg)) {
        report.fail(l, "run failed");
        continue;
      }
      add_speed(c_out, y_out, label);
      try {
        const auto cs = read_json(c_out / "summary.json"), ys = read_json(y_out / "summary.json");
        const Csv c = read_csv(c_out / "curve.csv"), y = read_csv(y_out / "curve.csv");
        report.check(l + " particles", cs.value("particles", 0.0), ys.value("particles", 0.0),
                     std::abs(cs.value("particles", 0.0) - ys.value("particles", 0.0)), 0.0, "%.0f");
        const bool both = cs.value("consolidated", false) && ys.value("consolidated", false);
        report.add(Row{l + " consolidated", cs.value("consolidated", false) ? "yes" : "no",
                       ys.value("consolidated", false) ? "yes" : "no", "-", "both", both, false});
        report.info(l + " consolidation time (s)", fmt(cs.value("consolidation_time", 0.0)),
                    fmt(ys.value("consolidation_time", 0.0)), "chaotic, not compared");
        const double c_tau = cs.value("shear_strength", 0.0), y_tau = ys.value("shear_strength", 0.0);
        report.check(l + " shear strength (kPa)", 1e-3 * c_tau, 1e-3 * y_tau, std::abs(c_tau - y_tau) / std::abs(c_tau),
                     tol_number(*t, "strength_relative", 0.1), "%.3f");
        const double c_sig = cs.value("mean_normal_stress", 0.0), y_sig = ys.value("mean_normal_stress", 0.0);
        report.check(l + " mean normal stress (kPa)", 1e-3 * c_sig, 1e-3 * y_sig, std::abs(c_sig - y_sig) / std::abs(c_sig),
                     tol_number(*t, "normal_stress_relative", 0.01), "%.3f");
        // shear stress over the strength window, YADE interpolated at colza's offsets
        const auto& cx = c.at("shear_displacement");
        const auto& ct = c.at("shear_stress");
        double sq_diff = 0.0, sq = 0.0, sq_y = 0.0;
        std::size_t n = 0;
        for (std::size_t r = 0; r < c.rows(); ++r) {
          if (cx[r] < ws || cx[r] > we) continue;
          const double ty = interpolate(y.at("shear_displacement"), y.at("shear_stress"), cx[r]);
          if (!std::isfinite(ty)) continue;
          sq_diff += (ct[r] - ty) * (ct[r] - ty);
          sq += ct[r] * ct[r];
          sq_y += ty * ty;
          ++n;
        }
        report.check(l + " shear stress rms difference / rms (" + std::to_string(n) + " rows, " + fmt(1e3 * ws, "%.2f") +
                         "-" + fmt(1e3 * we, "%.2f") + " mm, kPa)",
                     1e-3 * std::sqrt(sq / std::max<std::size_t>(n, 1)),
                     1e-3 * std::sqrt(sq_y / std::max<std::size_t>(n, 1)),
                     n > 0 && sq > 0 ? std::sqrt(sq_diff / sq) : std::numeric_limits<double>::quiet_NaN(),
                     tol_number(*t, "curve_rms_relative", 0.2));
        const double c_out_n = cs.value("particles_outside", 0.0), y_out_n = ys.value("particles_outside", 0.0);
        report.add(Row{l + " particles outside the box", fmt(c_out_n, "%.0f"), fmt(y_out_n, "%.0f"), "-", "0",
                       c_out_n == 0.0 && y_out_n == 0.0, false});
        c_strength.push_back(c_tau);
        y_strength.push_back(y_tau);
      } catch (const std::exception& e) {
        report.fail(l, e.what());
      }
    }
    // 4. Mohr-Coulomb line through (nominal load, strength), as colza's shear-series.
    if (c_strength.size() == loads.size() && loads.size() >= 2) {
      const auto [cc, cphi] = mohr_coulomb(loads, c_strength);
      const auto [yc, yphi] = mohr_coulomb(loads, y_strength);
      report.check(label + " cohesion C (kPa)", 1e-3 * cc, 1e-3 * yc, 1e-3 * std::abs(cc - yc),
                   tol_number(*t, "cohesion_absolute_kpa", 5.0), "%.3f");
      report.check(label + " friction angle Phi (deg)", cphi, yphi, std::abs(cphi - yphi),
                   tol_number(*t, "friction_angle_absolute_deg", 5.0), "%.2f");
    }
  }

  void print_speed() const {
    if (speed_.particle_steps <= 0.0) {
      std::printf("\nspeed: measured on the oedometer and shear runs (the micro scenes are too small to time)\n");
      return;
    }
    const double c = colza_particle_steps_ / colza_seconds_;
    const double y = speed_.particle_steps / yade_seconds_;
    const double ye = yade_engine_seconds_ > 0 ? speed_.particle_steps / yade_engine_seconds_ : 0.0;
    std::printf("\nspeed on the same loadings (%s; colza %.3g, YADE %.3g particle-steps; single thread, from each "
                "run's wall time):\n",
                speed_what_.c_str(), colza_particle_steps_, speed_.particle_steps);
    std::printf("  colza                                   %10.3g particle-steps/s\n", c);
    std::printf("  YADE (whole loop incl. Python runners)  %10.3g particle-steps/s   colza/YADE = %.1f\n", y, c / y);
    if (ye > 0)
      std::printf("  YADE (C++ engines only)                 %10.3g particle-steps/s   colza/YADE = %.1f\n", ye, c / ye);
  }

 private:
  // Micro: per particle and quantity (and per wall force), max |diff| / max(max |colza|, floor).
  void compare_series(Report& report, const std::string& scene, const Csv& c, const Csv& y, double rel,
                      double contacts_tol, const std::map<std::string, double>& floor) {
    if (c.names != y.names) throw std::runtime_error("the two series.csv have different columns");
    if (c.rows() != y.rows() || c.rows() == 0) throw std::runtime_error("different or no rows");
    if (c.at("step") != y.at("step")) throw std::runtime_error("rows are not at the same steps");
    struct Quantity {
      const char* prefix;
      const char* kind;
    };
    const Quantity quantities[] = {{"", "position"}, {"v", "velocity"}, {"w", "angular_velocity"},
                                   {"f", "force"},   {"t", "torque"}};
    // worst metric per quantity kind, over the particles
    std::map<std::string, std::tuple<double, double, double, std::string>> worst;  // kind -> (metric, cmax, ymax, who)
    auto consider = [&](const std::string& kind, const std::string& who, const std::string& stem, bool displacement,
                        double fl) {
      double num = 0.0, cmax = 0.0, ymax = 0.0;
      for (const char* a : {"x", "y", "z"}) {
        const auto& cc = c.at(stem + a);
        const auto& yc = y.at(stem + a);
        const double c0 = displacement ? cc[0] : 0.0, y0 = displacement ? yc[0] : 0.0;
        for (std::size_t r = 0; r < cc.size(); ++r) {
          num = std::max(num, std::abs(cc[r] - yc[r]));
          cmax = std::max(cmax, std::abs(cc[r] - c0));
          ymax = std::max(ymax, std::abs(yc[r] - y0));
        }
      }
      const double metric = num / std::max(cmax, fl);
      auto& w = worst[kind];
      if (std::get<3>(w).empty() || metric > std::get<0>(w) || (metric == std::get<0>(w) && cmax > std::get<1>(w)))
        w = {metric, cmax, ymax, who};
    };
    for (std::size_t k = 0; k < 100; ++k) {
      const std::string p = "p" + std::to_string(k) + "_";
      bool any = false;
      for (const std::string& n : c.names)
        if (n.rfind(p, 0) == 0) any = true;
      if (!any) continue;
      for (const Quantity& q : quantities)
        consider(q.kind, "p" + std::to_string(k), p + q.prefix, std::string(q.kind) == "position", floor.at(q.kind));
    }
    for (std::size_t w = 0; w < 100; ++w) {
      const std::string p = "w" + std::to_string(w) + "_f";
      if (!c.column(p + "x")) break;
      consider("wall_force", "w" + std::to_string(w), p, false, floor.at("force"));
    }
    const char* order[] = {"position", "velocity", "angular_velocity", "force", "torque", "wall_force"};
    for (const char* kind : order) {
      auto it = worst.find(kind);
      if (it == worst.end()) continue;
      const auto& [metric, cmax, ymax, who] = it->second;
      report.check(scene + " " + kind + " (" + who + ")", cmax, ymax, metric, rel);
    }
    const auto& cc = c.at("contacts");
    const auto& yc = y.at("contacts");
    double dmax = 0.0, cm = 0.0, ym = 0.0;
    for (std::size_t r = 0; r < cc.size(); ++r) {
      dmax = std::max(dmax, std::abs(cc[r] - yc[r]));
      cm = std::max(cm, cc[r]);
      ym = std::max(ym, yc[r]);
    }
    report.check(scene + " contacts (max count, max |diff|)", cm, ym, dmax, contacts_tol, "%.0f");
  }

  static double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    if (xs.empty() || x < xs.front() || x > xs.back()) return std::numeric_limits<double>::quiet_NaN();
    const auto it = std::lower_bound(xs.begin(), xs.end(), x);
    const std::size_t i = static_cast<std::size_t>(it - xs.begin());
    if (i == 0) return ys[0];
    const double t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
    return ys[i - 1] + t * (ys[i] - ys[i - 1]);
  }

  void compare_curves(Report& report, const std::string& label, const Csv& c, const Csv& y, const toml::table& t,
                      const nlohmann::json& cs, const nlohmann::json& ys, const fs::path& config) {
    const auto& cs_ = c.at("piston_displacement");
    const auto& cf = c.at("piston_force");
    const auto& ysd = y.at("piston_displacement");
    const auto& yf = y.at("piston_force");
    // The same start: identical particle count and contact count at step 0.
    report.check(label + " particles", cs.value("particles", 0.0), ys.value("particles", 0.0),
                 std::abs(cs.value("particles", 0.0) - ys.value("particles", 0.0)), 0.0, "%.0f");
    report.check(label + " contacts at the start", c.at("contacts")[0], y.at("contacts")[0],
                 std::abs(c.at("contacts")[0] - y.at("contacts")[0]), 0.0, "%.0f");
    // Early rows: before chaos amplifies rounding, the curves must coincide.
    const std::size_t early = static_cast<std::size_t>(t.at_path("early_rows").value_or(10));
    double num = 0.0, den = 0.0;
    for (std::size_t r = 0; r < std::min({early, c.rows(), y.rows()}); ++r) {
      num = std::max(num, std::abs(cf[r] - yf[r]));
      den = std::max(den, std::abs(cf[r]));
    }
    report.check(label + " force, first " + std::to_string(early) + " rows (max |diff| / max F)", den,
                 std::max(0.0, den), den > 0 ? num / den : 0.0, tol_number(t, "early_relative", 1e-5));
    // Logged range: from the fit's lower force on, up to the smaller final travel.
    const double f_min = fit_force_min(config);
    double s_lo = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t r = 0; r < c.rows(); ++r)
      if (cf[r] >= f_min) {
        s_lo = cs_[r];
        break;
      }
    const double s_hi = std::min(cs_.back(), ysd.back());
    double sq_diff = 0.0, sq = 0.0, sq_y = 0.0;
    std::size_t n = 0;
    for (std::size_t r = 0; r < c.rows(); ++r) {
      if (!(cs_[r] >= s_lo) || cs_[r] > s_hi) continue;
      const double fy = interpolate(ysd, yf, cs_[r]);
      if (!std::isfinite(fy)) continue;
      sq_diff += (cf[r] - fy) * (cf[r] - fy);
      sq += cf[r] * cf[r];
      sq_y += fy * fy;
      ++n;
    }
    const double rms = (n > 0 && sq > 0) ? std::sqrt(sq_diff / sq) : std::numeric_limits<double>::quiet_NaN();
    report.check(label + " force rms difference / rms force (" + std::to_string(n) + " rows, travel " +
                     fmt(1e3 * s_lo, "%.2f") + "-" + fmt(1e3 * s_hi, "%.2f") + " mm)",
                 std::sqrt(sq / std::max<std::size_t>(n, 1)), std::sqrt(sq_y / std::max<std::size_t>(n, 1)), rms,
                 tol_number(t, "rms_relative", 0.05));
    if (const auto* travels = t.at_path("travels").as_array()) {
      for (const auto& node : *travels) {
        const double s = node.value<double>().value_or(0.0);
        const double fc = interpolate(cs_, cf, s), fy = interpolate(ysd, yf, s);
        report.check(label + " force at " + fmt(1e3 * s, "%.1f") + " mm travel (N)", fc, fy,
                     std::abs(fc - fy) / std::abs(fc), tol_number(t, "force_at_relative", 0.1), "%.1f");
      }
    }
    report.info(label + " travel at stop (mm)", fmt(1e3 * cs_.back(), "%.3f"), fmt(1e3 * ysd.back(), "%.3f"),
                cs.value("stop_reason", std::string("?")) + " / " + ys.value("stop_reason", std::string("?")));
    if (ys.value("foreign_patch_contacts", 0) != 0)
      report.fail(label + " YADE cylinder patches", "a patch touched a sphere other than its own");
  }

  // Least-squares line tau = C + sigma tan(Phi); returns (C in Pa, Phi in degrees).
  static std::pair<double, double> mohr_coulomb(const std::vector<double>& sigma, const std::vector<double>& tau) {
    const double n = static_cast<double>(sigma.size());
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (std::size_t k = 0; k < sigma.size(); ++k) {
      sx += sigma[k];
      sy += tau[k];
      sxx += sigma[k] * sigma[k];
      sxy += sigma[k] * tau[k];
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    return {(sy - slope * sx) / n, std::atan(slope) * 180.0 / std::numbers::pi};
  }

  static double fit_force_min(const fs::path& config) {
    try {
      const toml::table t = toml::parse_file(config.string());
      return t.at_path("oedometer.fit_force_min").value_or(150.0);
    } catch (...) {
      return 150.0;
    }
  }

  Options opt_;
  toml::table tol_;
  Speed speed_;
  double colza_seconds_ = 0.0, yade_seconds_ = 0.0, yade_engine_seconds_ = 0.0, colza_particle_steps_ = 0.0;
  std::string speed_what_;
};

bool yade_available(const std::string& yade) {
  const std::string cmd = "command -v " + quote(yade) + " > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "crosscheck: %s\n", msg);
  std::fprintf(stderr,
               "usage: crosscheck micro|oedometer|shear|all [--size small|full] [--colza PATH] [--yade PATH]\n"
               "                  [--workdir DIR] [--source DIR] [--tolerances FILE] [--reuse] [--loads PA,PA,..]\n");
  return kExitUsage;
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
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--size") opt.size = value();
      else if (a == "--colza") opt.colza = value();
      else if (a == "--yade") opt.yade = value();
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
          opt.loads.push_back(v);
        }
        if (opt.loads.empty()) throw std::invalid_argument("--loads needs at least one normal stress (Pa)");
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
  if (opt.size != "small" && opt.size != "full") return usage("--size must be small or full");
  if (opt.source.empty() || !fs::exists(opt.source / "yade-scripts" / "run_scene.py"))
    return usage("cannot find the colza source tree (yade-scripts/); give --source");
  if (opt.colza.empty() || !fs::exists(opt.colza)) return usage("cannot find the colza executable; give --colza");
  if (opt.tolerances.empty()) opt.tolerances = opt.source / "data" / "crosscheck-tolerances.toml";
  if (opt.workdir.empty()) opt.workdir = fs::current_path() / "crosscheck-work";
  opt.colza = fs::absolute(opt.colza);
  opt.source = fs::absolute(opt.source);
  opt.workdir = fs::absolute(opt.workdir);

  if (!yade_available(opt.yade)) {
    std::printf("crosscheck: SKIPPED: YADE is not installed ('%s' is not on PATH); install the Debian package yade\n",
                opt.yade.c_str());
    return kExitSkip;
  }
  toml::table tol;
  try {
    tol = toml::parse_file(opt.tolerances.string());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crosscheck: cannot read %s: %s\n", opt.tolerances.string().c_str(), e.what());
    return kExitUsage;
  }
  fs::create_directories(opt.workdir);
  std::printf("crosscheck %s (--size %s): colza %s, YADE '%s', work in %s\n", opt.what.c_str(), opt.size.c_str(),
              opt.colza.string().c_str(), opt.yade.c_str(), opt.workdir.string().c_str());
  std::fflush(stdout);

  Runner runner(opt, tol);
  Report report;
  if (opt.what == "micro" || opt.what == "all") runner.micro(report);
  if (opt.what == "oedometer") runner.oedometer(report, opt.size);
  if (opt.what == "all") {
    runner.oedometer(report, "small");
    if (opt.size == "full") runner.oedometer(report, "full");
  }
  if (opt.what == "shear") runner.shear(report, opt.size);
  if (opt.what == "all") {
    runner.shear(report, "small");
    if (opt.size == "full") runner.shear(report, "full");
  }
  std::printf("\n");
  report.print();
  runner.print_speed();
  return report.all_passed() ? 0 : kExitFail;
}
