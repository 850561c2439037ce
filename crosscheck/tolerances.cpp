#include "tolerances.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "report.hpp"

namespace crosscheck {

namespace fs = std::filesystem;

namespace {

enum class Kind { kNonNegative, kPositive, kCount, kProbability, kString, kPositiveList };

struct Checker {
  std::string file;

  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    throw ToleranceError(file + ": key '" + key + "': " + why);
  }

  void value(const std::string& key, const toml::node& n, Kind kind) const {
    if (kind == Kind::kString) {
      if (!n.is_string()) fail(key, "must be a string (a path in the source tree)");
      return;
    }
    if (kind == Kind::kPositiveList) {
      const toml::array* a = n.as_array();
      if (!a || a->empty()) fail(key, "must be a list of numbers > 0");
      for (const auto& item : *a) {
        const auto v = item.value<double>();
        if (!v || !(*v > 0.0) || !std::isfinite(*v)) fail(key, "must be a list of numbers > 0");
      }
      return;
    }
    if (kind == Kind::kCount) {
      const auto v = n.value_exact<std::int64_t>();
      if (!v || *v < 1) fail(key, "must be a whole number >= 1");
      return;
    }
    const auto v = n.value<double>();
    if (!v || !std::isfinite(*v)) fail(key, "must be a number");
    if (kind == Kind::kNonNegative && *v < 0.0) fail(key, "must be >= 0");
    if (kind == Kind::kPositive && !(*v > 0.0)) fail(key, "must be > 0");
    if (kind == Kind::kProbability && !(*v > 0.0 && *v < 1.0)) fail(key, "must be between 0 and 1");
  }

  // Every key of `t` must be in `schema`; the `required` ones must be there.
  void table(const std::string& base, const toml::table& t, const std::map<std::string, Kind>& schema,
             const std::set<std::string>& required = {}) const {
    for (const auto& [k, n] : t) {
      const std::string key = base + "." + std::string(k.str());
      const auto it = schema.find(std::string(k.str()));
      if (it == schema.end()) fail(key, "unknown key (misspelt?)");
      value(key, n, it->second);
    }
    for (const std::string& r : required)
      if (!t.contains(r)) fail(base + "." + r, "missing");
  }

  // A path key (relative to the source tree) must name a file that is there: a misspelt
  // path would otherwise be a FAIL row after the other runs, not bad usage.
  void existing_file(const std::string& key, const fs::path& source, const std::string& relative) const {
    std::error_code ec;
    if (!fs::is_regular_file(source / relative, ec))
      fail(key, "names " + (source / relative).string() + ", which is not a file");
  }

  const toml::table& section(const toml::table& doc, const std::string& path, bool required) const {
    static const toml::table kEmpty;
    const toml::node_view<const toml::node> n = doc.at_path(path);
    if (!n) {
      if (required) fail(path, "missing: the [" + path + "] section is needed by this command");
      return kEmpty;
    }
    if (!n.is_table()) fail(path, "must be a table ([" + path + "])");
    return *n.as_table();
  }
};

const std::map<std::string, Kind>& ensemble_keys() {
  static const std::map<std::string, Kind> keys = {{"ensemble_realisations", Kind::kCount},
                                                   {"ensemble_perturbation", Kind::kNonNegative},
                                                   {"ensemble_alpha", Kind::kProbability}};
  return keys;
}

std::map<std::string, Kind> with_ensemble(std::map<std::string, Kind> keys) {
  keys.insert(ensemble_keys().begin(), ensemble_keys().end());
  return keys;
}

}  // namespace

std::string whole_pascals(double sigma) {
  char text[64];
  std::snprintf(text, sizeof text, "%.0f", sigma);
  return text;
}

std::string load_in_kpa(double load) {
  if (!(load < 100.0)) return "";
  return fmt(load, "%.15g") + " Pa is below a lab shear box's least normal stress (100 Pa): loads are in Pa (the "
         "paper's 25.75 kPa is 25750)";
}

std::string loads_sharing_a_run(const std::vector<double>& loads) {
  for (std::size_t a = 0; a < loads.size(); ++a)
    for (std::size_t b = a + 1; b < loads.size(); ++b)
      if (whole_pascals(loads[a]) == whole_pascals(loads[b])) {
        char text[160];
        std::snprintf(text, sizeof text, "loads %.15g and %.15g Pa are the same to the pascal (they would share runs)",
                      loads[a], loads[b]);
        return text;
      }
  return "";
}

toml::table read_tolerances(const fs::path& file, const std::string& command, const std::string& size,
                            const fs::path& source) {
  const Checker c{file.string()};
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (status.type() == fs::file_type::not_found) throw ToleranceError(file.string() + ": does not exist");
  if (ec) throw ToleranceError(file.string() + ": cannot be read: " + ec.message());
  if (fs::is_directory(status)) throw ToleranceError(file.string() + ": is a directory, not a tolerances file");
  if (!std::ifstream(file)) throw ToleranceError(file.string() + ": cannot be read");
  toml::table doc;
  try {
    doc = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    throw ToleranceError(file.string() + ": TOML syntax error (line " + std::to_string(e.source().begin.line) +
                         "): " + std::string(e.description()));
  }
  for (const auto& [k, n] : doc) {
    const std::string key(k.str());
    if (key != "micro" && key != "oedometer" && key != "shear") c.fail(key, "unknown section (micro, oedometer, shear)");
    if (!n.is_table()) c.fail(key, "must be a table");
  }
  const bool all = command == "all";
  // The oedometer has a third size, small_rolling: the small one with rolling resistance.
  const auto sizes_of = [&](const std::string& setup, const std::set<std::string>& sizes, const char* names) {
    for (const auto& [k, n] : c.section(doc, setup, false)) {
      const std::string s(k.str());
      if (!sizes.count(s)) c.fail(setup + "." + s, std::string("unknown size (") + names + ")");
      if (!n.is_table()) c.fail(setup + "." + s, "must be a table");
    }
  };
  sizes_of("oedometer", {"small", "full", "small_rolling"}, "small, full, small_rolling");
  sizes_of("shear", {"small", "full"}, "small, full");

  // [micro]
  const toml::table& micro = c.section(doc, "micro", command == "micro" || all);
  for (const auto& [k, n] : micro) {
    const std::string key = "micro." + std::string(k.str());
    if (k.str() == "relative" || k.str() == "contacts") c.value(key, n, Kind::kNonNegative);
    else if (k.str() == "floor") {
      if (!n.is_table()) c.fail(key, "must be a table");
      c.table(key, *n.as_table(),
              {{"position", Kind::kNonNegative}, {"velocity", Kind::kNonNegative},
               {"angular_velocity", Kind::kNonNegative}, {"force", Kind::kNonNegative},
               {"torque", Kind::kNonNegative}});
    } else if (k.str() == "scenes") {
      if (!n.is_table()) c.fail(key, "must be a table");
      for (const auto& [scene, v] : *n.as_table()) c.value(key + "." + std::string(scene.str()), v, Kind::kNonNegative);
    } else {
      c.fail(key, "unknown key (misspelt?)");
    }
  }
  if (command == "micro" || all) {
    const toml::table& scenes = c.section(doc, "micro.scenes", true);
    if (scenes.empty()) c.fail("micro.scenes", "names no scene");
    for (const auto& [scene, v] : scenes)
      c.existing_file("micro.scenes." + std::string(scene.str()), source,
                      "crosscheck/scenes/" + std::string(scene.str()) + ".toml");
  }

  // [oedometer.SIZE], [shear.SIZE]
  const std::map<std::string, Kind> oedometer = with_ensemble({{"config", Kind::kString},
                                                               {"settle_config", Kind::kString},
                                                               {"early_rows", Kind::kCount},
                                                               {"early_relative", Kind::kNonNegative},
                                                               {"rms_relative", Kind::kNonNegative},
                                                               {"force_at_relative", Kind::kNonNegative},
                                                               {"travels", Kind::kPositiveList}});
  const std::map<std::string, Kind> shear = with_ensemble({{"config", Kind::kString},
                                                           {"loads", Kind::kPositiveList},
                                                           {"shear_displacement", Kind::kPositive},
                                                           {"strength_window_start", Kind::kNonNegative},
                                                           {"strength_window_end", Kind::kPositive},
                                                           {"early_steps", Kind::kNonNegative},
                                                           {"early_relative", Kind::kNonNegative},
                                                           {"strength_relative", Kind::kNonNegative},
                                                           {"curve_rms_relative", Kind::kNonNegative},
                                                           {"normal_stress_relative", Kind::kNonNegative},
                                                           {"cohesion_absolute_kpa", Kind::kNonNegative},
                                                           {"friction_angle_absolute_deg", Kind::kNonNegative}});
  const auto check_oedometer_size = [&](const std::string& s, bool wanted_oedometer) {
    const std::string o = "oedometer." + s;
    const toml::table& oedometer_size = c.section(doc, o, wanted_oedometer);
    c.table(o, oedometer_size, oedometer, wanted_oedometer ? std::set<std::string>{"config"} : std::set<std::string>{});
    // The oedometer's ensemble judges the mean forces at `travels` and nothing else: without
    // them its extra runs would judge no row and pass. (An empty list fails above.)
    const std::int64_t realisations = oedometer_size["ensemble_realisations"].value_or(std::int64_t{1});
    if (realisations >= 2 && !oedometer_size.contains("travels"))
      c.fail(o + ".travels", "missing: with ensemble_realisations = " + std::to_string(realisations) +
                                 " the ensemble compares the mean forces at these travels, and without them it "
                                 "would judge nothing");
    // Travels in mm and a strength window out of order or past the shear's end passed this
    // check and failed every row after the whole ensemble had run (a walk-through: travels =
    // [5, 6, 7] ran 16 runs; a window 3 .. 1.5 mm ran 22 YADE runs for colza's refusals).
    if (const toml::array* travels = oedometer_size["travels"].as_array())
      for (const auto& n : *travels)
        if (n.value<double>().value_or(0.0) > 0.05)
          c.fail(o + ".travels", "a travel of " + fmt(n.value<double>().value_or(0.0), "%g") +
                                     " m is more than the oedometer's sample compresses: travels are in m (5 mm is "
                                     "0.005)");
    for (const auto& [wanted, key] : {std::pair{wanted_oedometer, "config"},
                                      std::pair{wanted_oedometer && s == "full", "settle_config"}})
      if (const auto path = oedometer_size[key].value<std::string>(); wanted && path)
        c.existing_file(o + "." + key, source, *path);
  };
  check_oedometer_size("small_rolling", command == "oedometer" && size == "small_rolling");
  for (const std::string s : {"small", "full"}) {
    // `all` runs the small setups, and the full ones too with --size full.
    const bool wanted_oedometer = (command == "oedometer" && size == s) || (all && (s == "small" || size == "full"));
    const bool wanted_shear = (command == "shear" && size == s) || (all && (s == "small" || size == "full"));
    check_oedometer_size(s, wanted_oedometer);
    const std::string h = "shear." + s;
    const toml::table& shear_size = c.section(doc, h, wanted_shear);
    const auto window_start = shear_size["strength_window_start"].value<double>();
    const auto window_end = shear_size["strength_window_end"].value<double>();
    const auto sheared = shear_size["shear_displacement"].value<double>();
    if (window_start && window_end && !(*window_start < *window_end))
      c.fail(h + ".strength_window_end", "must be above strength_window_start (" + fmt(*window_start, "%g") + " m), got " +
                                             fmt(*window_end, "%g") + " m");
    if (window_end && sheared && *window_end > *sheared)
      c.fail(h + ".strength_window_end", "must be at most shear_displacement (" + fmt(*sheared, "%g") + " m), got " +
                                             fmt(*window_end, "%g") + " m");
    c.table(h, shear_size, shear, wanted_shear ? std::set<std::string>{"config", "loads"} : std::set<std::string>{});
    if (const toml::array* loads = shear_size["loads"].as_array()) {
      std::vector<double> values;
      for (const auto& n : *loads) values.push_back(n.value<double>().value_or(0.0));
      if (const std::string why = loads_sharing_a_run(values); !why.empty()) c.fail(h + ".loads", why);
      for (double v : values)
        if (const std::string why = load_in_kpa(v); !why.empty()) c.fail(h + ".loads", why);
    }
    if (const auto path = shear_size["config"].value<std::string>(); wanted_shear && path)
      c.existing_file(h + ".config", source, *path);
  }
  return doc;
}

}  // namespace crosscheck
