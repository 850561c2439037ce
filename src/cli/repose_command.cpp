#include "cli/repose_command.hpp"

#include <cmath>
#include <cstdio>

#include "analysis/inertial_number.hpp"
#include "cli/command_common.hpp"
#include "io/format_number.hpp"
#include "io/lab_features_json.hpp"
#include "io/packing_file.hpp"
#include "io/scenario_inertial_numbers.hpp"
#include "io/summary.hpp"
#include "scenario/repose.hpp"

namespace colza {

namespace {

nlohmann::json rest_json(const SettleResult& s) {
  return {{"converged", s.converged},
          {"steps", s.steps},
          {"simulated_time", s.simulated_time},
          {"mean_unbalanced_force", s.mean_unbalanced_force},
          {"share_touching_nothing", s.share_touching_nothing}};
}

}  // namespace

void run_repose_scenario(const RunConfig& c, const RunOptions& opt, OutputStaging& out) {
  Progress progress(!opt.quiet);
  const ReposeResult r = run_repose(c, progress, c.output.snapshot_interval);
  const ReposeSpec& rs = c.repose;
  nlohmann::json s = common_summary(c, "repose", opt.threads);
  s["particles_generated"] = r.particles_generated;
  s["particles"] = r.particles;
  s["column_height"] = r.column_height;
  s["column_bulk_density"] = r.column_bulk_density;
  s["settling"] = settling_json(c, r.settling);
  s["lift_time"] = r.lift_time;
  s["rest"] = rest_json(r.rest);
  s["base_friction"] = rs.base_friction;
  s["base"] = {{"kind", repose_base_name(rs.base)},
               {"glued_spheres", r.glued_layer.size()},
               {"glued_layer_diameter", rs.base == ReposeBase::kPlate ? 0.0 : rs.glued_layer_diameter},
               {"base_height", r.base_height}};
  const HeapAngle& h = r.heap;
  s["angle_of_repose"] = {{"valid", h.valid},
                          {"angle_deg", h.angle_deg},
                          {"angle_error_deg", h.angle_error_deg},
                          {"heap_height", h.height},
                          {"heap_radius", h.radius},
                          {"cone_apex_height", h.intercept},
                          {"fit_rho_range", {h.fit_rho_min, h.fit_rho_max}},
                          {"points", h.points},
                          {"surface_spheres", h.surface_spheres},
                          {"r2", h.r2},
                          {"sectors", rs.sectors}};
  s["spheres_beyond_heap"] = r.spheres_beyond_heap;
  double inertial = 0.0;
  s["inertial_number"] =
      inertial_number_json(repose_inertial_inputs(c, r.column_height, r.column_bulk_density), inertial);
  std::vector<std::string> warnings = settings_warnings(c, Scenario::kRepose, /*series=*/false);
  if (!r.settling.converged) warnings.push_back(settling_warning(c, r.settling));
  if (!r.rest.converged)
    warnings.push_back("the heap did not come to rest within repose.rest_max_time = " +
                       format_shortest(rs.rest_max_time) + " s (mean unbalanced force " +
                       format_significant(r.rest.mean_unbalanced_force, 3) + " N against " +
                       format_shortest(rs.rest_unbalanced_force) + " N): its angle may still change");
  if (!h.valid)
    warnings.push_back("no cone could be fitted: fewer than 3 surface spheres between repose.fit_inner and fit_outer "
                       "of the heap's radius (" + format_significant(1e3 * h.radius, 3) +
                       " mm; a heap less than two diameters high has none): fill more spheres");
  if (inertial > kQuasiStaticInertialNumber)
    warnings.push_back("the inertial number of the lift is " + format_significant(inertial, 3) + ", above " +
                       format_shortest(kQuasiStaticInertialNumber) +
                       ": the lift is not quasi-static and the heap depends on repose.lift_speed");
  s["warnings"] = warnings;
  s["dt"] = r.dt;
  s["steps"] = r.steps;
  add_snapshots_summary(s, r.snapshots);
  add_timing(s, r.stages);

  const Table profile = heap_profile_table(r.final_state, r.base_height, r.heap);
  write_csv(out.path("heap_profile.csv"), profile);
  write_packing(out.path("packing.txt"), r.column);
  write_packing(out.path("heap.txt"), r.final_state);
  write_result_h5(out, "repose", c, s, "heap_profile", profile,
                  {{"particles/column", &r.column}, {"particles/final", &r.final_state}, {"particles/glued_layer", &r.glued_layer}}, &r.snapshots);
  write_json(out.path("summary.json"), s);

  std::printf("repose: %zu particles (%zu generated), column %.1f mm high, bulk density %.1f kg/m^3\n", r.particles,
              r.particles_generated, 1e3 * r.column_height, r.column_bulk_density);
  if (r.glued_layer.size() > 0)
    std::printf("  base: %zu spheres glued over a %.0f mm disc, its top at %.1f mm\n", r.glued_layer.size(),
                1e3 * rs.glued_layer_diameter, 1e3 * r.base_height);
  if (h.valid)
    std::printf("  angle of repose %.2f +/- %.2f deg (cone fit to %zu surface spheres at %.1f..%.1f mm), heap %.1f mm "
                "high, radius %.1f mm\n",
                h.angle_deg, h.angle_error_deg, h.points, 1e3 * h.fit_rho_min, 1e3 * h.fit_rho_max, 1e3 * h.height,
                1e3 * h.radius);
  std::printf("  lift %.3f s, rest %s after %.3f s; %zu spheres beyond the heap; inertial number %.3g\n", r.lift_time,
              r.rest.converged ? "reached" : "NOT reached", r.rest.simulated_time, r.spheres_beyond_heap, inertial);
  for (const std::string& w : warnings) std::printf("  WARNING: %s\n", w.c_str());
}

}  // namespace colza
