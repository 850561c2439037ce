#include "cli/command_common.hpp"

#include "config/plausibility.hpp"
#include "contact/slot_registry.hpp"
#include "core/cpu_model.hpp"
#include "core/version.hpp"
#include "core/kernel_isa.hpp"
#include "io/format_number.hpp"
#include "io/hdf5_writer.hpp"
#include "io/summary.hpp"
#include "io/xdmf_writer.hpp"

namespace colza {

nlohmann::json common_summary(const RunConfig& c, const std::string& scenario, int threads) {
  return {{"scenario", scenario},
          {"colza_version", kVersion},
          {"git_revision", git_revision()},
          {"config", c.source},
          {"overrides", c.overrides},
          {"seed", c.seed},
          {"threads", threads},
          {"stiffness_rule", to_string(c.stiffness_rule)},
          {"wall_friction", to_string(c.wall_friction)},
          {"contact_model", describe(c.contact)},
          {"contact", contact_summary(c.contact)},
          {"damping", c.integration.damping},
          {"damping_form", to_string(c.integration.damping_form)},
          {"time_step_mode", c.integration.automatic_time_step ? "auto" : "fixed"},
          // The copy of the force loops that ran and what it was built for (core/kernel_isa.hpp),
          // and the CPU: the speed depends on them, the results do not.
          {"kernel_isa", to_string(active_kernel_isa())},
          {"kernel_isa_built_for", kernel_isa_built_for(active_kernel_isa())},
          {"kernel_isa_report", kernel_isa_report()},
          {"cpu_model", cpu_model()}};
}

double total_wall_seconds(const std::vector<StageTiming>& stages) {
  double t = 0.0;
  for (const auto& s : stages) t += s.wall_seconds;
  return t;
}

double overall_rate(const std::vector<StageTiming>& stages) {
  double ps = 0.0;
  for (const auto& s : stages) ps += s.particle_steps;
  const double t = total_wall_seconds(stages);
  return t > 0.0 ? ps / t : 0.0;
}

void add_timing(nlohmann::json& summary, const std::vector<StageTiming>& stages) {
  summary["wall_seconds"] = total_wall_seconds(stages);
  double cpu = 0.0;
  for (const auto& s : stages) cpu += s.cpu_seconds;
  summary["cpu_seconds"] = cpu;
  summary["particle_steps_per_second"] = overall_rate(stages);
  summary["stages"] = stages_json(stages);
}

namespace {

// The keys add_timing sets that measure the machine, not the simulation (also per stage).
constexpr const char* kTimingKeys[] = {"wall_seconds", "cpu_seconds", "particle_steps_per_second"};

nlohmann::json without_timing(const nlohmann::json& summary) {
  nlohmann::json s = summary;
  for (const char* key : kTimingKeys) s.erase(key);
  if (s.contains("stages"))
    for (auto& stage : s["stages"])
      for (const char* key : kTimingKeys) stage.erase(key);
  return s;
}

}  // namespace

void write_result_h5(OutputStaging& out, const std::string& scenario, const RunConfig& c,
                     const nlohmann::json& summary, const std::string& table_group, const Table& table,
                     std::initializer_list<NamedState> states, const SnapshotSeries* snapshots) {
  Hdf5Writer h5(out.path("result.h5"), /*many_chunked=*/snapshots && !snapshots->empty());
  write_provenance(h5, scenario, c.seed, c.resolved_toml);
  h5.attribute("summary_json", without_timing(summary).dump());
  h5.write_table(table_group, table);
  for (const NamedState& st : states) h5.write_particles(st.group, *st.particles);
  if (snapshots) h5.write_snapshots(*snapshots);
  h5.close();
  if (snapshots && !snapshots->empty()) write_xdmf(out.path("result.xmf"), *snapshots, "result.h5");
}

void add_snapshots_summary(nlohmann::json& summary, const SnapshotSeries& snapshots) {
  if (snapshots.empty()) return;
  summary["snapshots"] = {{"interval", snapshots.interval}, {"count", snapshots.snapshots.size()}};
}

std::string settling_warning(const RunConfig& c, const SettleResult& settling) {
  // Below the criterion, but too many spheres still touching nothing (settle()).
  const bool still_falling = settling.mean_unbalanced_force < c.sample.settle_unbalanced_force;
  const std::string state =
      still_falling ? format_significant(100.0 * settling.share_touching_nothing, 3) +
                          " % of the spheres touched nothing, against at most " +
                          format_shortest(100.0 * kMaxShareTouchingNothing) + " % at rest"
                    : "mean unbalanced force " + format_significant(settling.mean_unbalanced_force, 3) +
                          " N against " + format_shortest(c.sample.settle_unbalanced_force) + " N";
  return "settling did not converge within sample.settle_max_time = " + format_shortest(c.sample.settle_max_time) +
         " s (" + state + "): the sample was not at rest when its test began; raise sample.settle_max_time";
}

nlohmann::json settling_json(const RunConfig& c, const SettleResult& settling) {
  return {{"converged", settling.converged},
          {"steps", settling.steps},
          {"simulated_time", settling.simulated_time},
          {"mean_unbalanced_force", settling.mean_unbalanced_force},
          {"share_touching_nothing", settling.share_touching_nothing},
          {"threshold", c.sample.settle_unbalanced_force}};
}

std::vector<std::string> settings_warnings(const RunConfig& c, Scenario scenario, bool series,
                                           const std::vector<double>& stresses) {
  const std::string stress_origin =
      series ? c.origin_of("shear_box.normal_stresses") + ": key 'shear_box.normal_stresses'" : "--normal-stress";
  std::vector<std::string> w;
  for (const ImplausibleSetting& found : implausible_settings(c, scenario, stresses, stress_origin))
    w.push_back(found.text());
  return w;
}

}  // namespace colza
