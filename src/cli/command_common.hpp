// Pieces shared by the `colza run` commands.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include "cli/run_commands.hpp"
#include "config/run_config.hpp"
#include "core/stage_timing.hpp"
#include "io/output_dir.hpp"
#include "io/snapshot.hpp"
#include "io/table.hpp"
#include "scenario/settling.hpp"

namespace colza {

// Model choices and provenance every summary.json carries.
nlohmann::json common_summary(const RunConfig& c, const std::string& scenario, int threads);
double total_wall_seconds(const std::vector<StageTiming>& stages);
double overall_rate(const std::vector<StageTiming>& stages);  // particle-steps per second
// Sets wall_seconds, cpu_seconds, particle_steps_per_second and stages of a summary.
void add_timing(nlohmann::json& summary, const std::vector<StageTiming>& stages);

struct NamedState {
  const char* group;  // e.g. "particles/final"
  const ParticleArrays* particles;
};
// result.h5: provenance, the summary without the timings add_timing set (so that the same
// config and seed at the same thread count give the same result.h5, byte for byte;
// summary.json keeps them) as an attribute, the recorded table and particle states, and the
// snapshots if there are any (then result.xmf too, beside it: io/xdmf_writer.hpp).
void write_result_h5(OutputStaging& out, const std::string& scenario, const RunConfig& c,
                     const nlohmann::json& summary, const std::string& table_group, const Table& table,
                     std::initializer_list<NamedState> states, const SnapshotSeries* snapshots = nullptr);

// summary.json's "snapshots" {interval (s), count}, set only when the run took any.
void add_snapshots_summary(nlohmann::json& summary, const SnapshotSeries& snapshots);

// The warning a run's summary carries when its sample's settling did not converge (the
// oedometer's and the shear box's "warnings"), naming the key to raise.
std::string settling_warning(const RunConfig& c, const SettleResult& settling);

// summary.json's "settling": how the sample's settling ended, against its criterion.
nlohmann::json settling_json(const RunConfig& c, const SettleResult& settling);

// The settings a user should look at twice, most likely unit slips (config/plausibility.hpp):
// printed before a run starts and kept in its summary.json's "warnings". `stresses` are the
// shear box's normal stresses in question (Pa): --normal-stress, or a series' loads from
// shear_box.normal_stresses.
std::vector<std::string> settings_warnings(const RunConfig& c, Scenario scenario, bool series,
                                           const std::vector<double>& stresses = {});

}  // namespace colza
