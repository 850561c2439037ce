// crosscheck micro: the deterministic 2-3 body scenes of crosscheck/scenes, run by `colza run
// scene` and yade-scripts/run_scene.py, their time series (series.csv) compared.
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include "checks.hpp"
#include "analysis/curve_comparison.hpp"
#include "result_files.hpp"

namespace crosscheck {

void compare_scene_series(Report& report, const std::string& scene, const Csv& c, const Csv& y, const Tolerance& rel,
                          const Tolerance& contacts_tol, const std::map<std::string, double>& floor) {
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
      // max_magnitude, not std::max: a NaN must not be skipped (an all-NaN YADE series passed)
      for (std::size_t r = 0; r < cc.size(); ++r) {
        num = colza::max_magnitude(num, cc[r] - yc[r]);
        cmax = colza::max_magnitude(cmax, cc[r] - c0);
        ymax = colza::max_magnitude(ymax, yc[r] - y0);
      }
    }
    // The floor stands for the signal when colza's is smaller (a zero torque by symmetry); with
    // a zero floor a zero signal agrees only with a zero difference (relative_difference). A NaN
    // cmax (a value not finite) gives +inf whatever the floor.
    const double metric = colza::relative_difference(num, std::isnan(cmax) ? cmax : std::max(cmax, fl));
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
    report.check(scene + " " + kind + " (" + who + ")", cmax, ymax, metric, Measure::kRelative, rel);
  }
  const auto& cc = c.at("contacts");
  const auto& yc = y.at("contacts");
  double dmax = 0.0, cm = 0.0, ym = 0.0;  // counts >= 0; NaN once a count is not finite
  for (std::size_t r = 0; r < cc.size(); ++r) {
    dmax = colza::max_magnitude(dmax, cc[r] - yc[r]);
    cm = colza::max_magnitude(cm, cc[r]);
    ym = colza::max_magnitude(ym, yc[r]);
  }
  report.check(scene + " contacts (max count, max |diff|)", cm, ym, dmax, Measure::kAbsolute, contacts_tol, "%.0f");
}

void check_micro(const CheckContext& ctx, Report& report) {
  const fs::path scenes = ctx.opt.source / "crosscheck" / "scenes";
  const toml::table* list = ctx.tol.at_path("micro.scenes").as_table();
  if (!list || list->empty()) {
    report.fail("micro", "no [micro.scenes] in the tolerances file");
    return;
  }
  const ToleranceSection micro{*ctx.tol["micro"].as_table(), "micro"};
  const Tolerance default_rel = micro.get("relative", 1e-6);
  const Tolerance contacts_tol = micro.get("contacts", 0.0);
  const std::map<std::string, double> floor = {
      {"position", tol_number(ctx.tol, "micro.floor.position", 1e-12)},
      {"velocity", tol_number(ctx.tol, "micro.floor.velocity", 1e-12)},
      {"angular_velocity", tol_number(ctx.tol, "micro.floor.angular_velocity", 1e-9)},
      {"force", tol_number(ctx.tol, "micro.floor.force", 1e-12)},
      {"torque", tol_number(ctx.tol, "micro.floor.torque", 1e-15)}};
  for (const auto& [key, value] : *list) {
    const std::string name(key.str());
    const Tolerance rel = value.value<double>() ? micro.get("scenes." + name, 0.0) : default_rel;
    const fs::path config = scenes / (name + ".toml");
    const fs::path c_out = ctx.opt.workdir / "colza" / name, y_out = ctx.opt.workdir / "yade" / name;
    if (!ctx.runs.run_colza("scene", config, c_out) || !ctx.runs.run_yade("run_scene.py", config, y_out)) {
      report.fail(name, ctx.runs.failure(c_out, y_out));
      continue;
    }
    try {
      compare_scene_series(report, name, read_csv(c_out / "series.csv"), read_csv(y_out / "series.csv"), rel,
                           contacts_tol, floor);
    } catch (const std::exception& e) {
      report.fail(name, e.what());
    }
  }
}

}  // namespace crosscheck
