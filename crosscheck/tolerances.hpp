// The tolerances file (data/crosscheck-tolerances.toml) read and checked before anything
// runs: a misspelt key, a value of the wrong type or out of range, or a section the command
// needs that is missing would otherwise fall back to a built-in value or fail after YADE had
// run for minutes. The checks then read it with tol_number and at_path, as before.
#pragma once
#include <filesystem>
#include <stdexcept>
#include <string>
#include <toml++/toml.h>
#include <vector>

namespace crosscheck {

// Bad tolerances: what() names the file, the key and the reason.
class ToleranceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A normal stress (Pa) rounded to the pascal, as a shear load's run folder is named
// (load_run_name, shear_setting.hpp): "25750".
std::string whole_pascals(double sigma);

// "" if no two of `loads` (Pa) round to the same pascal, else what is wrong with which two:
// such loads would share a run folder and their runs.
std::string loads_sharing_a_run(const std::vector<double>& loads);

// Why a shear box normal stress (Pa) is refused, or "": below 100 Pa it is taken for kPa, as
// colza calibrate refuses a measured load below its kLeastLabNormalStress (the paper's loads
// are 25750..78750 Pa; a walk-through's "--loads 25.75,78.75" ran loads of 0.03 kPa).
std::string load_in_kpa(double load);

// Parses `file` and checks every key against the schema below; `command` (micro, oedometer,
// shear, all) and `size` (small, full) say which sections must be there, and the files the
// command's sections name (config, settle_config, crosscheck/scenes/<scene>.toml) must be
// in the source tree `source`. Throws ToleranceError.
//   [micro]            relative, contacts (numbers >= 0); [micro.floor] position, velocity,
//                      angular_velocity, force, torque (>= 0); [micro.scenes] name = relative
//                      tolerance (>= 0), at least one
//   [oedometer.SIZE]   config (required), settle_config (strings); early_rows (integer >= 1);
//                      early_relative, rms_relative, force_at_relative (>= 0); travels
//                      (numbers > 0; required with ensemble_realisations >= 2); ensemble keys
//   [shear.SIZE]       config, loads (required; numbers > 0, no two the same to the pascal);
//                      shear_displacement,
//                      strength_window_end (> 0), strength_window_start (>= 0); early_steps, and the
//                      relative and absolute tolerances (>= 0); ensemble keys
//   ensemble keys      ensemble_realisations (integer >= 1), ensemble_perturbation (>= 0),
//                      ensemble_alpha (in (0, 1))
toml::table read_tolerances(const std::filesystem::path& file, const std::string& command, const std::string& size,
                            const std::filesystem::path& source);

}  // namespace crosscheck
