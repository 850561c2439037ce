#include "calibration/spec_design.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "calibration/lab_tests.hpp"
#include "calibration/spec_fields.hpp"
#include "calibration/spec_model.hpp"
#include "config/plausibility.hpp"
#include "io/format_number.hpp"

namespace colza::calibration {

namespace {

std::string fmt(double v) { return spec_number_text(v); }

// "(350000, 0.3)": a design point as the user wrote it.
std::string point_text(const Eigen::VectorXd& x) {
  std::string t = "(";
  for (Eigen::Index j = 0; j < x.size(); ++j) t += (j ? ", " : "") + format_shortest(x[j]);
  return t + ")";
}

// A parameter's bound that no seed has, most likely a unit slip (config/plausibility.hpp: a
// friction design in degrees, diameters in mm), and the model's own such settings: warned
// of, not refused (the runs can run them). The shear box's loads are checked with the
// measured data.
// A setting flagged at the bound but not in the model alone (s.base) is the parameter's
// doing, even under another key (kn_p in kN/m makes particle.shear_stiffness 285 times it).
// `at_lower`, `at_upper`: the model as read with the parameter at each bound.
void warn_of_implausible_bounds(Spec& s, const ConfigNode& n, const Parameter& par, const RunConfig& at_lower,
                                const RunConfig& at_upper) {
  const Scenario scenario = scenario_of(s.stage);
  std::set<std::string> models_own;
  for (const ImplausibleSetting& found : implausible_settings(s.base, scenario)) models_own.insert(found.key);
  for (const std::string bound : {"lower", "upper"}) {
    const double value = bound == "lower" ? par.lower : par.upper;
    for (const ImplausibleSetting& found : implausible_settings(bound == "lower" ? at_lower : at_upper, scenario)) {
      std::string w = found.text();
      if (found.key == par.key || !models_own.count(found.key))
        w = s.file + ": key '" + n.full(bound) + "': " + par.name + " = " + format_shortest(value) + " (" + par.key +
            "): " + (found.key == par.key ? "" : "with it, " + found.key + " ") + found.reason;
      else if (found.origin.rfind("--set", 0) == 0)  // the spec's [model] set, not a command line
        w = s.file + ": key 'model.set' (" + found.key + "): " + found.reason;
      if (std::find(s.warnings.begin(), s.warnings.end(), w) == s.warnings.end()) s.warnings.push_back(w);
    }
  }
}

// Every value a run can be given must be one the model config accepts: the design values
// and the bounds (the solver and the sequential refinement stay within them; the model's
// own limits are ranges, so the bounds stand for the values between them). A key the model
// refuses at every value (misspelt, or not a number) is the key's fault.
void check_model_accepts(Spec& s, const ConfigNode& n, const Parameter& par, const std::vector<double>& d) {
  std::set<double> values(d.begin(), d.end());
  values.insert(par.lower);
  values.insert(par.upper);
  std::string first_reason, first_key;
  std::size_t refused = 0;
  RunConfig at_lower, at_upper;  // the model with the parameter at its bounds
  for (double v : values)
    if (const std::string why =
            model_rejects(s, par.key, v, v == par.lower ? &at_lower : v == par.upper ? &at_upper : nullptr);
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
  warn_of_implausible_bounds(s, n, par, at_lower, at_upper);
  // The fit and the sequential refinement give a parameter any value between its bounds,
  // so the model must take one that is not a whole number too: a key of whole numbers
  // (sample.count) passed the checks above and failed after the design runs. The value is
  // the range's golden section, a whole number for no practical bounds.
  const double between = par.lower + (par.upper - par.lower) * 0.3819660112501051;
  if (const std::string why = model_rejects(s, par.key, between); !why.empty())
    n.fail("key", why + "; a calibrated parameter takes any value in [" + fmt(par.lower) + ", " + fmt(par.upper) +
                      "] (the fit's solution, the sequential refinement), so " + par.key + " cannot be one");
}

// One [[parameters]] table; its design values into `design`.
Parameter read_parameter(const ConfigNode& n, Spec& s, std::vector<double>& d) {
  const Problem& p = s.problem;
  Parameter par;
  par.key = required_string(n, "key");
  for (std::size_t i = 0; i < p.parameters.size(); ++i)
    if (p.parameters[i].key == par.key)
      n.fail("key", "repeats parameters[" + std::to_string(i) + "]'s key " + par.key +
                        ": a run sets a key once, so one of the two parameters would do nothing");
  par.name = string_or(n, "name", par.key);
  par.unit = string_or(n, "unit", "");
  d = number_array(n, "design");
  if (d.empty()) n.fail("design", "missing: the parameter's value at each design point");
  par.lower = number_or(n, "lower", *std::min_element(d.begin(), d.end()));
  par.upper = number_or(n, "upper", *std::max_element(d.begin(), d.end()));
  if (!(par.upper > par.lower))
    n.fail("design", "the design does not vary " + par.name + " (range [" + fmt(par.lower) + ", " + fmt(par.upper) +
                         "]): a surface cannot be fitted");
  for (double v : d)
    if (v < par.lower || v > par.upper) n.fail("design", "design value " + fmt(v) + " is outside [lower, upper]");
  check_model_accepts(s, n, par, d);
  return par;
}

}  // namespace

void read_spec_parameters(const ConfigNode& root, Spec& s) {
  Problem& p = s.problem;
  const toml::node* params = root.get("parameters");
  const toml::array* pa = params ? params->as_array() : nullptr;
  if (!pa || pa->empty()) root.fail("parameters", "missing: give one [[parameters]] table per calibrated parameter");
  for (const auto& t : *pa)
    if (!t.is_table()) root.fail("parameters", "must be an array of tables ([[parameters]])");
  std::vector<std::vector<double>> columns;
  for (const ConfigNode& n : root.table_array("parameters")) {
    std::vector<double> d;
    const Parameter par = read_parameter(n, s, d);
    if (!columns.empty() && d.size() != columns[0].size())
      n.fail("design", "has " + std::to_string(d.size()) + " values, parameters[0].design has " +
                           std::to_string(columns[0].size()) + ": every parameter needs one value per design point");
    columns.push_back(d);
    p.parameters.push_back(par);
    reject_unknown_spec_keys(n);
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
}

void read_spec_fit(const ConfigNode& fit, Problem& p) {
  try {
    p.surface = surface_kind_from_string(string_or(fit, "surface", "auto"));
  } catch (const std::invalid_argument& e) {
    fit.fail("surface", e.what());
  }
  reject_unknown_spec_keys(fit);
}

void read_spec_sequential(const ConfigNode& seq, Spec& s) {
  Problem& p = s.problem;
  const std::size_t np = p.parameters.size();
  p.max_runs = static_cast<int>(whole_number_or(seq, "max_runs", 12, 1, 100000));
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
        if (const std::string why = model_rejects(s, par.key, x[j]); !why.empty())
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
  reject_unknown_spec_keys(seq);
}

void read_spec_scatter(const ConfigNode& scatter, Spec& s) {
  Problem& p = s.problem;
  p.replicates = static_cast<int>(whole_number_or(scatter, "replicates", 0, 0, 50));
  if (p.replicates == 1)
    scatter.fail("replicates", "must be 0 (off) or at least 2: one extra realisation gives a scatter with a single "
                               "degree of freedom, too unreliable to widen a tolerance with");
  if (p.replicates > 0 && !s.fixed_packing_file.empty())
    scatter.fail("replicates", "every run loads the packing file " + s.fixed_packing_file +
                                   ", so another seed gives the same run and the scatter would read zero: remove the "
                                   "packing_file (each run then settles its own sample" +
                                   std::string(s.stage == Stage::kShear ? "" : ", or one per seed with [model] packing = \"shared\"") +
                                   "), or set replicates = 0");
  reject_unknown_spec_keys(scatter);
}

}  // namespace colza::calibration
