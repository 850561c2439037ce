#include "calibration/spec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "analysis/mohr_coulomb.hpp"
#include "analysis/polyfit.hpp"
#include "config/config_error.hpp"
#include "config/config_reader.hpp"
#include "config/plausibility.hpp"
#include "io/format_number.hpp"
#include "io/input_file.hpp"
#include "io/load_label.hpp"

namespace colza::calibration {

namespace fs = std::filesystem;

const char* to_string(Stage s) {
  switch (s) {
    case Stage::kDensity: return "density";
    case Stage::kCompression: return "compression";
    case Stage::kShear: return "shear";
  }
  return "?";
}

namespace {

std::string fmt(double v) { return format_significant(v, 6); }

// "(350000, 0.3)": a design point as the user wrote it.
std::string point_text(const Eigen::VectorXd& x) {
  std::string t = "(";
  for (Eigen::Index j = 0; j < x.size(); ++j) t += (j ? ", " : "") + format_shortest(x[j]);
  return t + ")";
}

// Small typed access to one table of the spec, with unknown-key rejection.
struct Node {
  const std::string& file;
  const toml::table* table;
  std::string path;
  mutable std::set<std::string> used;

  std::string full(const std::string& k) const { return path.empty() ? k : path + "." + k; }
  [[noreturn]] void fail(const std::string& k, const std::string& why) const { throw ConfigError(file, full(k), why); }
  const toml::node* get(const std::string& k) const {
    used.insert(k);
    return table ? table->get(k) : nullptr;
  }
  bool has(const std::string& k) const { return table && table->contains(k); }
  double number(const std::string& k) const {
    const toml::node* n = get(k);
    if (!n) fail(k, "missing (a number is required)" + misspelt_key_hint(table, k));
    if (auto v = n->value<double>()) {
      if (!std::isfinite(*v)) fail(k, "must be a finite number");
      return *v;
    }
    fail(k, "must be a number");
  }
  double number(const std::string& k, double fallback) const { return has(k) ? number(k) : (get(k), fallback); }
  long long integer(const std::string& k, long long fallback, long long lo, long long hi) const {
    const toml::node* n = get(k);
    if (!n) return fallback;
    if (!n->is_integer()) fail(k, "must be a whole number");
    const long long v = n->as_integer()->get();
    if (v < lo || v > hi) fail(k, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " + std::to_string(v));
    return v;
  }
  double positive(const std::string& k) const {
    const double v = number(k);
    if (!(v > 0.0)) fail(k, "must be > 0, got " + fmt(v));
    return v;
  }
  std::string string(const std::string& k, const std::string& fallback, bool required = false) const {
    const toml::node* n = get(k);
    if (!n) {
      if (required) fail(k, "missing (a string is required)" + misspelt_key_hint(table, k));
      return fallback;
    }
    if (auto v = n->value<std::string>()) return *v;
    fail(k, "must be a string");
  }
  std::vector<double> numbers(const std::string& k) const {
    const toml::node* n = get(k);
    if (!n) return {};
    const toml::array* a = n->as_array();
    if (!a) fail(k, "must be an array of numbers");
    std::vector<double> out;
    for (const auto& e : *a) {
      auto v = e.value<double>();
      if (!v || !std::isfinite(*v)) fail(k, "must be an array of finite numbers");
      out.push_back(*v);
    }
    return out;
  }
  std::vector<std::string> strings(const std::string& k) const {
    const toml::node* n = get(k);
    if (!n) return {};
    const toml::array* a = n->as_array();
    if (!a) fail(k, "must be an array of strings");
    std::vector<std::string> out;
    for (const auto& e : *a) {
      auto v = e.value<std::string>();
      if (!v) fail(k, "must be an array of strings");
      out.push_back(*v);
    }
    return out;
  }
  Node child(const std::string& k) const {
    const toml::node* n = get(k);
    if (n && !n->is_table()) fail(k, "must be a table");
    return Node{file, n ? n->as_table() : nullptr, full(k), {}};
  }
  void reject_unknown() const {
    if (!table) return;
    for (const auto& [key, value] : *table)
      if (!used.count(std::string(key.str())))
        throw ConfigError(file, full(std::string(key.str())), "unknown key (misspelt? it does not belong in this table)");
  }
};

std::string resolve(const std::string& spec_file, const std::string& value) {
  fs::path p(value);
  if (p.is_relative()) p = fs::path(spec_file).parent_path() / p;
  return p.lexically_normal().string();
}

// Measured values below or above these are taken for a unit slip (exit 2 before any run,
// where a slip used to surface as "outside what the design can reach" after the design runs):
// a seed bulk's density (kg/m^3; oilseeds ~350..800, the paper's rapeseed 651; g/cm^3 gives
// ~0.65), the oedometer's initial stiffness c1 (N/m; the paper's cylinder ~1e6, the 40 mm
// test cylinder ~1e5; kN/m gives ~1e2..1e3), the cohesion's uncertainty (Pa; a shear box
// resolves ~100 Pa, the paper's C is 11.41 kPa; kPa gives ~0.5) and tan(Phi)'s (-; tan(Phi)
// itself is ~0.5; an angle's uncertainty in degrees gives ~1..3).
constexpr double kLeastBulkDensity = 100.0, kMostBulkDensity = 2000.0;
constexpr double kLeastInitialStiffness = 1e3;
constexpr double kLeastCohesionUncertainty = 10.0;
constexpr double kMostTanPhiUncertainty = 1.0;
// Least tau / sigma at failure of a granular bulk: tan(1 deg).
constexpr double kLeastStrengthRatio = 0.017;

// Why a normal stress `sigma` (Pa) read from the spec or its data is taken for kPa, or "".
std::string normal_stress_in_kpa(double sigma) {
  if (sigma >= kLeastLabNormalStress) return "";
  return "a normal stress of " + fmt(sigma) + " Pa, below " + fmt(kLeastLabNormalStress) +
         " Pa: colza reads Pa (25.75 kPa is 25750); are these kPa?";
}

// "" when the model config loads with `key` = `value` added to the spec's overrides (and the
// configuration read into `accepted`, when given), else why not ("the model does not accept
// particle.density = -1200: must be positive, ...").
std::string model_rejects(const Spec& s, Scenario scenario, const std::string& key, double value,
                          RunConfig* accepted = nullptr) {
  // The value exactly as a run would be given it: rounded to 6 digits, a bound just past a
  // model limit (0.9990001 for a limit of 0.999) would pass here and be refused mid-calibration.
  std::vector<std::string> set = s.model_set;
  set.push_back(key + "=" + format_shortest(value));
  try {
    RunConfig model = load_run_config(scenario, s.model_config, set);
    if (accepted) *accepted = std::move(model);
  } catch (const ConfigError& e) {
    // The key that objected, when another than the parameter's (a limit between two keys).
    const std::string other = e.key().empty() || e.key() == key ? "" : "key '" + e.key() + "': ";
    return "the model does not accept " + key + " = " + format_shortest(value) + ": " + other + e.reason();
  }
  return "";
}

// A parameter's bound that no seed has, most likely a unit slip (config/plausibility.hpp: a
// friction design in degrees, diameters in mm), and the model's own such settings: warned
// of, not refused (the runs can run them). The shear box's loads are checked with the
// measured data.
// A setting flagged at the bound but not in the model alone (s.base) is the parameter's
// doing, even under another key (kn_p in kN/m makes particle.shear_stiffness 285 times it).
// `at_lower`, `at_upper`: the model as read with the parameter at each bound.
void warn_of_implausible_bounds(Spec& s, Scenario scenario, const Node& n, const Parameter& par,
                                const RunConfig& at_lower, const RunConfig& at_upper) {
  std::set<std::string> models_own;
  for (const ImplausibleSetting& found : implausible_settings(s.base, scenario)) models_own.insert(found.key);
  for (const std::string bound : {"lower", "upper"}) {
    const double value = bound == "lower" ? par.lower : par.upper;
    for (const ImplausibleSetting& found : implausible_settings(bound == "lower" ? at_lower : at_upper, scenario)) {
      std::string w = found.text();
      if (found.key == par.key || !models_own.count(found.key))
        w = n.file + ": key '" + n.full(bound) + "': " + par.name + " = " + format_shortest(value) + " (" + par.key +
            "): " + (found.key == par.key ? "" : "with it, " + found.key + " ") + found.reason;
      else if (found.origin.rfind("--set", 0) == 0)  // the spec's [model] set, not a command line
        w = s.file + ": key 'model.set' (" + found.key + "): " + found.reason;
      if (std::find(s.warnings.begin(), s.warnings.end(), w) == s.warnings.end()) s.warnings.push_back(w);
    }
  }
}

}  // namespace

Spec read_spec(const std::string& path) {
  Spec s;
  s.file = path;
  if (const std::string why = unreadable_file_reason(path); !why.empty())
    throw ConfigError(path, "", "the calibration spec " + why);
  toml::table doc;
  try {
    doc = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    std::ostringstream m;
    m << "TOML syntax error: " << e.description() << " (line " << e.source().begin.line << ")";
    throw ConfigError(path, "", m.str());
  }
  const Node root{path, &doc, "", {}};
  // The top level first: a misspelt [modle] would otherwise read as a missing model.config.
  static const std::set<std::string> kTopLevel = {"stage", "title",      "provenance", "model",   "parameters",
                                                  "fit",   "sequential", "scatter",    "measured"};
  for (const auto& [key, value] : doc)
    if (!kTopLevel.count(std::string(key.str())))
      root.fail(std::string(key.str()), "unknown key or table (misspelt?): a spec has stage, title, provenance, "
                                        "[model], [[parameters]], [fit], [sequential], [scatter] and [measured]");
  const std::string stage = root.string("stage", "", true);
  if (stage == "density") s.stage = Stage::kDensity;
  else if (stage == "compression") s.stage = Stage::kCompression;
  else if (stage == "shear") s.stage = Stage::kShear;
  else root.fail("stage", "must be \"density\", \"compression\" or \"shear\", got \"" + stage + "\"");
  s.title = root.string("title", "");
  root.string("provenance", "");

  // --- the DEM model --------------------------------------------------------------
  const Node model = root.child("model");
  s.model_config = resolve(path, model.string("config", "", true));
  if (!fs::exists(s.model_config)) model.fail("config", "the model config " + s.model_config + " does not exist");
  s.model_set = model.strings("set");
  const std::string packing = model.string("packing", "per_run");
  if (packing != "per_run" && packing != "shared") model.fail("packing", "must be \"per_run\" or \"shared\"");
  s.shared_packing = packing == "shared";
  if (s.shared_packing && s.stage == Stage::kDensity)
    model.fail("packing", "the density stage measures the settled packing: every run must settle (\"per_run\")");
  model.reject_unknown();
  const Scenario scenario = s.stage == Stage::kShear ? Scenario::kShear : Scenario::kOedometer;
  try {
    s.base = load_run_config(scenario, s.model_config, s.model_set);
  } catch (const ConfigError& e) {
    throw ConfigError(path, "model", std::string("the model config does not load: ") + e.what());
  }
  s.fixed_packing_file = s.stage == Stage::kShear ? s.base.shear_box.packing_file : s.base.oedometer.packing_file;

  // --- parameters and design ---------------------------------------------------------
  Problem& p = s.problem;
  const toml::node* params = root.get("parameters");
  const toml::array* pa = params ? params->as_array() : nullptr;
  if (!pa || pa->empty()) root.fail("parameters", "missing: give one [[parameters]] table per calibrated parameter");
  std::vector<std::vector<double>> columns;
  for (std::size_t j = 0; j < pa->size(); ++j) {
    const toml::table* t = (*pa)[j].as_table();
    if (!t) root.fail("parameters", "must be an array of tables ([[parameters]])");
    const Node n{path, t, "parameters[" + std::to_string(j) + "]", {}};
    Parameter par;
    par.key = n.string("key", "", true);
    for (std::size_t i = 0; i < p.parameters.size(); ++i)
      if (p.parameters[i].key == par.key)
        n.fail("key", "repeats parameters[" + std::to_string(i) + "]'s key " + par.key +
                          ": a run sets a key once, so one of the two parameters would do nothing");
    par.name = n.string("name", par.key);
    par.unit = n.string("unit", "");
    std::vector<double> d = n.numbers("design");
    if (d.empty()) n.fail("design", "missing: the parameter's value at each design point");
    par.lower = n.number("lower", *std::min_element(d.begin(), d.end()));
    par.upper = n.number("upper", *std::max_element(d.begin(), d.end()));
    if (!(par.upper > par.lower))
      n.fail("design", "the design does not vary " + par.name + " (range [" + fmt(par.lower) + ", " + fmt(par.upper) +
                           "]): a surface cannot be fitted");
    for (double v : d)
      if (v < par.lower || v > par.upper) n.fail("design", "design value " + fmt(v) + " is outside [lower, upper]");
    // Every value a run can be given must be one the model config accepts: the design
    // values and the bounds (the solver and the sequential refinement stay within them; the
    // model's own limits are ranges, so the bounds stand for the values between them).
    // A key the model refuses at every value (misspelt, or not a number) is the key's fault.
    std::set<double> values(d.begin(), d.end());
    values.insert(par.lower);
    values.insert(par.upper);
    std::string first_reason, first_key;
    std::size_t refused = 0;
    RunConfig at_lower, at_upper;  // the model with the parameter at its bounds
    for (double v : values)
      if (const std::string why = model_rejects(s, scenario, par.key, v,
                                                v == par.lower ? &at_lower : v == par.upper ? &at_upper : nullptr);
          !why.empty()) {
        ++refused;
        if (first_reason.empty()) {
          first_reason = why;
          const bool in_design = std::find(d.begin(), d.end(), v) != d.end();
          first_key = in_design ? "design" : (v == par.lower ? "lower" : "upper");
        }
      }
    if (refused == values.size()) n.fail("key", first_reason);
    if (refused > 0) n.fail(first_key, first_reason);
    warn_of_implausible_bounds(s, scenario, n, par, at_lower, at_upper);
    // The fit and the sequential refinement give a parameter any value between its bounds,
    // so the model must take one that is not a whole number too: a key of whole numbers
    // (sample.count) passed the checks above and failed after the design runs. The value is
    // the range's golden section, a whole number for no practical bounds.
    const double between = par.lower + (par.upper - par.lower) * 0.3819660112501051;
    if (const std::string why = model_rejects(s, scenario, par.key, between); !why.empty())
      n.fail("key", why + "; a calibrated parameter takes any value in [" + fmt(par.lower) + ", " + fmt(par.upper) +
                        "] (the fit's solution, the sequential refinement), so " + par.key +
                        " cannot be one");
    if (!columns.empty() && d.size() != columns[0].size())
      n.fail("design", "has " + std::to_string(d.size()) + " values, parameters[0].design has " +
                           std::to_string(columns[0].size()) + ": every parameter needs one value per design point");
    columns.push_back(d);
    p.parameters.push_back(par);
    n.reject_unknown();
  }
  const std::size_t np = p.parameters.size();
  for (std::size_t k = 0; k < columns[0].size(); ++k) {
    Eigen::VectorXd x(np);
    for (std::size_t j = 0; j < np; ++j) x[j] = columns[j][k];
    p.design.push_back(x);
  }
  for (std::size_t k = 0; k < p.design.size(); ++k)
    for (std::size_t l = 0; l < k; ++l)
      if (p.design[k] == p.design[l])
        root.fail("parameters", "design point " + std::to_string(k + 1) + " " + point_text(p.design[k]) +
                                    " repeats design point " + std::to_string(l + 1) +
                                    ": a run at the same point and seed is the same run, so it would count twice in "
                                    "the fit; to measure the scatter between realisations, use [scatter] replicates");
  if (p.design.size() < np + 1)
    root.fail("parameters", "too few design points for the surrogate: " + std::to_string(p.design.size()) +
                                " given, a plane in " + std::to_string(np) + " parameter(s) needs at least " +
                                std::to_string(np + 1) + " (the paper used 7 for compression, 5 for shear)");

  // --- surrogate and sequential settings -------------------------------------------
  const Node fit = root.child("fit");
  try {
    p.surface = surface_kind_from_string(fit.string("surface", "auto"));
  } catch (const std::invalid_argument& e) {
    fit.fail("surface", e.what());
  }
  fit.reject_unknown();
  const Node seq = root.child("sequential");
  p.max_runs = static_cast<int>(seq.integer("max_runs", 12, 1, 100000));
  if (p.max_runs < static_cast<int>(np) + 2)
    seq.fail("max_runs", "must allow the " + std::to_string(np + 1) + " start points and one refinement run (>= " +
                             std::to_string(np + 2) + ")");
  if (const toml::node* st = seq.get("start")) {
    // The shape expected, shown with this spec's own first design points: one array per
    // point, one value per parameter (with one parameter, [[350000], [450000]]).
    std::string example;
    for (std::size_t k = 0; k <= np && k < p.design.size(); ++k) {
      std::string point;
      for (std::size_t j = 0; j < np; ++j) point += (j ? ", " : "") + format_shortest(p.design[k][j]);
      example += (k ? ", [" : "[") + point + "]";
    }
    const std::string shape = "an array of " + std::to_string(np + 1) + " or more points, each an array of " +
                              std::to_string(np) + " value(s) in the order of [[parameters]], e.g. [" + example + "]";
    const toml::array* a = st->as_array();
    if (!a) seq.fail("start", "must be " + shape);
    for (const auto& row : *a) {
      const toml::array* r = row.as_array();
      if (!r || r->size() != np) seq.fail("start", "must be " + shape);
      Eigen::VectorXd x(np);
      for (std::size_t j = 0; j < np; ++j) {
        auto v = (*r)[j].value<double>();
        if (!v) seq.fail("start", "points must be numbers");
        x[j] = *v;
        const Parameter& par = p.parameters[j];
        const std::string point = "point " + std::to_string(p.sequential_start.size() + 1);
        if (const std::string why = model_rejects(s, scenario, par.key, x[j]); !why.empty())
          seq.fail("start", point + ": " + why);
        if (x[j] < par.lower || x[j] > par.upper)
          seq.fail("start", point + ": " + par.name + " = " + format_shortest(x[j]) + " is outside [" +
                                fmt(par.lower) + ", " + fmt(par.upper) + "], the bounds the refinement keeps to");
      }
      for (std::size_t l = 0; l < p.sequential_start.size(); ++l)
        if (p.sequential_start[l] == x)
          seq.fail("start", "point " + std::to_string(p.sequential_start.size() + 1) + " repeats point " +
                                std::to_string(l + 1) + ": the start points must span " +
                                (np == 1 ? std::string("a line") : "a plane"));
      p.sequential_start.push_back(x);
    }
    if (p.sequential_start.size() < np + 1)
      seq.fail("start", "needs at least " + std::to_string(np + 1) + " points to determine " +
                            (np == 1 ? std::string("a line") : "a plane") + ", got " +
                            std::to_string(p.sequential_start.size()));
  }
  seq.reject_unknown();
  // Realisation scatter: the same point with other seeds (calibrate.hpp).
  const Node scatter = root.child("scatter");
  p.replicates = static_cast<int>(scatter.integer("replicates", 0, 0, 50));
  if (p.replicates == 1)
    scatter.fail("replicates", "must be 0 (off) or at least 2: one extra realisation gives a scatter with a single "
                               "degree of freedom, too unreliable to widen a tolerance with");
  if (p.replicates > 0 && !s.fixed_packing_file.empty())
    scatter.fail("replicates", "every run loads the packing file " + s.fixed_packing_file +
                                   ", so another seed gives the same run and the scatter would read zero: remove the "
                                   "packing_file (each run then settles its own sample" +
                                   std::string(s.stage == Stage::kShear ? "" : ", or one per seed with [model] packing = \"shared\"") +
                                   "), or set replicates = 0");
  scatter.reject_unknown();

  // --- measured data -> targets ------------------------------------------------------
  const Node m = root.child("measured");
  if (!m.table) root.fail("measured", "missing: the [measured] table names the measured data and their uncertainties");
  if (s.stage == Stage::kDensity) {
    const double bulk = m.positive("bulk_density");
    if (bulk < kLeastBulkDensity || bulk > kMostBulkDensity)
      m.fail("bulk_density", fmt(bulk) + " kg/m^3 is outside the " + fmt(kLeastBulkDensity) + ".." +
                                 fmt(kMostBulkDensity) + " kg/m^3 of a seed bulk: colza reads kg/m^3 (0.651 g/cm^3 "
                                 "is 651, the paper's rapeseed); is it in g/cm^3?");
    p.targets.push_back({"bulk_density", "kg/m^3", bulk, m.positive("bulk_density_uncertainty")});
  } else if (s.stage == Stage::kCompression) {
    const double u1 = m.positive("c1_uncertainty"), u2 = m.positive("c2_uncertainty");
    if (m.has("curve")) {
      if (m.has("c1") || m.has("c2")) m.fail("curve", "give either the curve or c1 and c2, not both");
      s.measured_file = resolve(path, m.string("curve", ""));
      if (!fs::exists(s.measured_file)) m.fail("curve", "the measured curve " + s.measured_file + " does not exist");
      const std::string dcol = m.string("displacement_column", "displacement");
      const std::string fcol = m.string("force_column", "force");
      std::vector<std::size_t> lines;
      const auto cols = read_csv_columns(s.measured_file, {dcol, fcol}, path, "measured.curve", lines);
      require_increasing(cols[0], lines, dcol, s.measured_file, path, "measured.curve");
      const double fmin = s.base.oedometer.fit_force_min, fmax = s.base.oedometer.fit_force_max;
      // Units (colza reads m and N): a piston cannot travel further than the sample is high,
      // and a curve whose largest force is under 1 % of the fit range's top is in kN or a
      // lever's units, not one to shorten the fit range for.
      const double cylinder_height = s.base.oedometer.cylinder_height;
      if (cols[0].back() > cylinder_height)
        m.fail("curve", s.measured_file + ": the displacement reaches " + fmt(cols[0].back()) + ", more than the "
                            "sample's height oedometer.cylinder_height = " + fmt(cylinder_height) +
                            " m: colza reads " + dcol + " in m (mm / 1000)");
      const double peak = *std::max_element(cols[1].begin(), cols[1].end());
      if (!(peak > 0.0))
        m.fail("curve", s.measured_file + ": the curve has no positive force (" + fcol + " in N, compression "
                            "positive)");
      if (peak < 0.01 * fmax)
        m.fail("curve", s.measured_file + ": its largest force is " + fmt(peak) + " N, under 1 % of "
                            "oedometer.fit_force_max = " + fmt(fmax) + " N: colza reads " + fcol +
                            " in N (kN x 1000); is it in kN?");
      if (peak < fmax)
        m.fail("curve", s.measured_file + ": the curve never reaches its fit range: its largest force is " + fmt(peak) +
                            " N, the fit runs to oedometer.fit_force_max = " + fmt(fmax) +
                            " N; lower it in [model] set (e.g. \"oedometer.fit_force_max=" + fmt(0.95 * peak) +
                            "\") or supply the whole curve");
      const CompressionFit cf = fit_compression_curve(cols[0], cols[1], fmin, fmax);
      if (!cf.valid || cf.fit.points < 10)
        m.fail("curve", s.measured_file + ": too few points between " + fmt(fmin) + " and " + fmt(fmax) +
                            " N to fit F = c0 + c1 s + c2 s^2 (need >= 10)");
      p.targets.push_back({"c1", "N/m", cf.fit.coefficients[1], u1});
      p.targets.push_back({"c2", "N/m^2", cf.fit.coefficients[2], u2});
      s.measured_c0 = cf.fit.coefficients[0];
      s.measured_fit_r2 = cf.fit.r2;
      if (cf.fit.r2 < 0.95)
        s.warnings.push_back("the measured curve is poorly described by a quadratic (R^2 = " + fmt(cf.fit.r2) +
                             " < 0.95, the paper's simulated curves reach > 0.95): check the curve's units and range");
    } else {
      const double c1 = m.number("c1");
      if (c1 < kLeastInitialStiffness)
        m.fail("c1", fmt(c1) + " N/m is below " + fmt(kLeastInitialStiffness) + " N/m: colza reads N/m (a bulk in "
                                   "the paper's cylinder starts near 1e6 N/m); is it in kN/m?");
      p.targets.push_back({"c1", "N/m", c1, u1});
      p.targets.push_back({"c2", "N/m^2", m.number("c2"), u2});
    }
    // c1 and c2 come from one quadratic over the same range, so their errors are seldom
    // independent: from sample to sample a stiffer start (c1) goes with a flatter rise (c2).
    // [measured] correlation gives it (e.g. from repeated tests); not set: independent.
    s.correlation_given = m.has("correlation");
    if (s.correlation_given) {
      const double rho = m.number("correlation");
      if (!(rho > -1.0 && rho < 1.0)) m.fail("correlation", "must lie strictly between -1 and 1, got " + fmt(rho));
      p.target_correlation = (Eigen::Matrix2d() << 1.0, rho, rho, 1.0).finished();
    }
  } else {
    const double uc = m.positive("cohesion_uncertainty"), ut = m.positive("tan_phi_uncertainty");
    if (uc < kLeastCohesionUncertainty)
      m.fail("cohesion_uncertainty", fmt(uc) + " Pa is below " + fmt(kLeastCohesionUncertainty) +
                                         " Pa, finer than a shear box resolves: colza reads Pa (0.5 kPa is 500); is "
                                         "it in kPa?");
    if (ut >= kMostTanPhiUncertainty)
      m.fail("tan_phi_uncertainty", fmt(ut) + " is the uncertainty of tan(Phi), which is itself ~0.5 for seeds (the "
                                        "paper's tan 28.1 deg = 0.534): is it an angle in degrees? (2 deg at 28 deg "
                                        "is +/- 0.045 in tan(Phi): sec^2 Phi d Phi)");
    const bool has_results = m.has("results"), has_curves = m.has("curves");
    if (has_results && has_curves)
      m.fail("curves", "give either the shear strengths (results) or one curve per normal load (curves), not both");
    if (!has_results && !has_curves)
      m.fail("results", "missing: name the measured shear strengths (results = \"file.csv\", columns normal_stress, "
                        "shear_strength) or one curve per normal load ([[measured.curves]] with normal_stress and file)");
    const std::string source_key = has_results ? "results" : "curves";
    // Which strength: the paper's mean over the stationary window, or the peak.
    s.strength.window = {s.base.shear_box.strength_window_start, s.base.shear_box.strength_window_end};
    const std::string kind = m.string("strength", "window");
    if (kind == "peak")
      s.strength.peak = true;
    else if (kind != "window")
      m.fail("strength", "must be \"window\" (the mean over shear_box.strength_window_start .. _end, the paper's) or "
                         "\"peak\" (the largest mean over measured.peak_width), got \"" + kind + "\"");
    if (m.has("peak_width")) {
      if (!s.strength.peak) m.fail("peak_width", "only with strength = \"peak\"");
      s.strength.peak_width = m.positive("peak_width");
    }
    if (s.strength.peak && !(s.strength.peak_width < s.base.shear_box.shear_displacement))
      m.fail("peak_width", "the peak width " + fmt(s.strength.peak_width) + " m must be shorter than the simulated "
                           "shear displacement (shear_box.shear_displacement = " +
                           fmt(s.base.shear_box.shear_displacement) + " m)");
    std::vector<double> sigma, tau;
    if (has_results) {
      s.measured_file = resolve(path, m.string("results", "", true));
      if (!fs::exists(s.measured_file))
        m.fail("results", "the measured shear results " + s.measured_file + " do not exist");
      const auto cols = read_csv_columns(s.measured_file, {"normal_stress", "shear_strength"}, path, "measured.results");
      sigma = cols[0], tau = cols[1];
      for (std::size_t k = 0; k < sigma.size(); ++k)
        if (!(sigma[k] > 0.0) || !(tau[k] > 0.0))
          m.fail("results", s.measured_file + ": normal stress and shear strength must be > 0 (Pa)");
    } else {
      // One measured curve per normal load; its strength is derived over the model's strength window.
      const toml::array* curves = m.get("curves")->as_array();
      if (!curves || curves->empty())
        m.fail("curves", "must be a non-empty array of tables ([[measured.curves]] with normal_stress and file)");
      for (std::size_t k = 0; k < curves->size(); ++k) {
        const toml::table* t = (*curves)[k].as_table();
        if (!t) m.fail("curves", "must be an array of tables ([[measured.curves]])");
        const Node c{path, t, "measured.curves[" + std::to_string(k) + "]", {}};
        const double normal_stress = c.positive("normal_stress");
        const std::string file = resolve(path, c.string("file", "", true));
        const MeasuredShearCurve curve =
            read_measured_shear_curve(file, normal_stress, s.strength, path, c.full("file"), s.warnings,
                                      s.base.shear_box.length);
        if (!(curve.shear_strength > 0.0))
          c.fail("file", file + ": the shear strength (" + s.strength.describe() + ") is " + fmt(curve.shear_strength) +
                             " Pa; a shear strength must be > 0 (check the sign and units of shear_stress, Pa)");
        c.reject_unknown();
        sigma.push_back(normal_stress);
        tau.push_back(curve.shear_strength);
        s.measured_curves.push_back(curve);
      }
    }
    // Units (colza reads Pa): a lab direct shear load is kilopascals, not tens of pascals, and
    // at failure tau / sigma of a granular bulk is tan(Phi) plus cohesion over sigma, never
    // below tan(1 deg) = 0.017. A column in kPa beside one in Pa breaks one or the other;
    // refused here, before any design run is spent on loads of 26 Pa.
    for (std::size_t k = 0; k < sigma.size(); ++k) {
      if (const std::string why = normal_stress_in_kpa(sigma[k]); !why.empty()) m.fail(source_key, why);
      if (tau[k] / sigma[k] < kLeastStrengthRatio)
        m.fail(source_key, "a shear strength of " + fmt(tau[k]) + " Pa at a normal stress of " + fmt(sigma[k]) +
                               " Pa, tau / sigma = " + fmt(tau[k] / sigma[k]) + " < " + fmt(kLeastStrengthRatio) +
                               ": colza reads both in Pa; is the shear stress in kPa?");
    }
    std::set<double> distinct(sigma.begin(), sigma.end());
    if (distinct.size() < 2)
      m.fail(source_key, "needs shear strengths at two or more distinct normal stresses for the Mohr-Coulomb line, "
                         "got " + std::to_string(distinct.size()));
    for (std::size_t k = 0; k < sigma.size(); ++k) s.measured_points.push_back({sigma[k], tau[k]});
    const MohrCoulombFit mc = fit_mohr_coulomb(sigma, tau);
    s.measured_fit_r2 = mc.r2;
    p.targets.push_back({"cohesion", "Pa", mc.cohesion, uc});
    p.targets.push_back({"tan_phi", "-", mc.slope, ut});
    s.loads = m.numbers("loads");
    if (s.loads.empty()) s.loads = {*distinct.begin(), *distinct.rbegin()};  // the paper: lowest and highest
    if (std::set<double>(s.loads.begin(), s.loads.end()).size() < 2)
      m.fail("loads", "needs two or more distinct normal stresses (Pa)");
    for (double l : s.loads) {
      if (!(l > 0.0)) m.fail("loads", "normal stresses must be > 0 (Pa)");
      if (const std::string why = normal_stress_in_kpa(l); !why.empty()) m.fail("loads", why);
    }
    if (const std::string clash = loads_sharing_a_label(s.loads); !clash.empty()) m.fail("loads", clash);
    // The measured C and tan(Phi) come from one line through the measured strengths: unless
    // the spec gives the correlation of their errors ([measured] correlation), it is that of
    // the line's intercept and slope for strengths of equal, independent uncertainty at the
    // measured loads (line_fit_correlation).
    double rho = line_fit_correlation(sigma)(0, 1);
    s.correlation_given = m.has("correlation");
    if (s.correlation_given) {
      rho = m.number("correlation");
      if (!(rho > -1.0 && rho < 1.0)) m.fail("correlation", "must lie strictly between -1 and 1, got " + fmt(rho));
    } else if (1.0 - rho * rho < 1e-6) {
      m.fail(source_key, "the measured normal stresses are too close together for a Mohr-Coulomb line (C and "
                         "tan(Phi) correlate at " + fmt(rho) + ")");
    }
    p.target_correlation = (Eigen::Matrix2d() << 1.0, rho, rho, 1.0).finished();
    if (mc.cohesion < 0.0)
      s.warnings.push_back("the measured line has a negative cohesion (" + fmt(mc.cohesion) + " Pa): check the data");
  }
  if (s.stage == Stage::kDensity && m.has("correlation"))
    m.fail("correlation", "correlates two targets from one fit (compression: c1 and c2; shear: C and tan(Phi)); a "
                          "density spec has one target, bulk_density");
  m.reject_unknown();
  return s;
}

}  // namespace colza::calibration
