// DEM runs kept by what they were run from. A run is asked for by scenario, model config,
// overrides ("key=value") and realisation; it is kept in <runs>/<fingerprint>/ with its
// summary.json (written last: a folder with one is a finished run) and its curves
// (oedometer: curve.csv; shear series: load-<sigma>Pa.csv per load; angle of repose:
// heap_profile.csv). The fingerprint is FNV-1a 64 (io/fingerprint.hpp) of the run's full
// configuration as used, the contents of the packing file it names and, when it loads a
// shared packing, that packing's fingerprint: a request whose fingerprint has a finished run
// is answered from it.
//
// Realisation k >= 1 is the same run with seed = the configuration's seed + k.
// Shared packings (oedometer): one packing settled per packing configuration and seed, kept
// in <runs>/packing-<fp>/packing.txt, loaded by every run that asks for it.
// Shear samples: one settled sample per sample fingerprint (the configuration without the
// keys that act only after settling: bond strengths, loads, the shearing stage), kept in
// <runs>/sample-<fp>/packing.txt; every shear run starts from that file.
//
// Nothing half-written is left: a run is computed in a scratch or staging folder and moved
// into place whole (io/output_dir.hpp). Calibrations sharing one runs folder may compute the
// same run at once; the last rename wins with identical content. Thread-safe.
#pragma once
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "config/run_config.hpp"
#include "core/concurrent.hpp"
#include "scenario/shear_box.hpp"

namespace colza::calibration {

struct RunRequest {
  // kOedometer, kShear (a series over shear_box.normal_stresses) or kRepose.
  Scenario scenario = Scenario::kOedometer;
  std::string config_path;                   // the model config
  std::vector<std::string> overrides;        // "key=value", applied in order
  int replicate = 0;                         // realisation: seed = the configuration's seed + replicate
  // Oedometer: load the packing settled once from the model config with these overrides (and
  // this realisation's seed) instead of settling one per run; none: each run settles its own.
  std::optional<std::vector<std::string>> shared_packing_overrides;
  // Shear: reuse a finished run only if it kept every load's curve (a caller reading them).
  bool needs_load_curves = false;
  // Written into summary.json beside the outputs (what the run is to the caller).
  nlohmann::json annotations = nlohmann::json::object();
  // Names the run in the error of a run that blew up, e.g. "kn_p = 450000, mu_pp = 0.3".
  std::string label;
};

struct RunRecord {
  std::string id;                  // fingerprint = the folder name under the runs folder
  std::filesystem::path dir;       // <runs>/<id>
  int replicate = 0;
  std::uint64_t seed = 0;          // the seed the run was made with
  std::string shared_packing_file; // the packing it loaded, when shared ("" otherwise)
  bool reused = false;             // answered from a finished run
  double wall_seconds = 0.0;       // of the original run
  std::string made_by;             // git revision of the colza that ran it ("unknown" for runs older than the field)
  nlohmann::json outputs;          // summary.json "outputs"
};

// A shear run's curve at normal stress sigma (Pa): load-<sigma>Pa.csv in its folder.
std::string shear_curve_file_name(double sigma);

// The settled sample's fingerprint: the resolved configuration without the keys that act
// only after settling (bond strengths, loads, the shearing stage) plus `packing_line`
// (file_contents_line of the packing file the configuration names).
std::string sample_fingerprint(const RunConfig& config, const std::string& packing_line);

// One warning about the reused runs another revision of colza made: a run's fingerprint holds
// its configuration, not the code, so they stand only if the physics did not change in
// between. `reused`: (run id, the revision that made it) of each reused run, repeats allowed.
// Revisions compare as strings ("unknown" for runs older than the field; a "-dirty" build
// equals another). "" when this revision made every one.
std::string runs_by_another_revision_warning(const std::vector<std::pair<std::string, std::string>>& reused,
                                             const std::filesystem::path& runs_dir);

class RunCache {
 public:
  // `verbose`: one line per shared packing and shear sample settled.
  RunCache(std::filesystem::path runs_dir, bool verbose);

  // The run's record: reused when finished, otherwise run now (UnstableMotion names the run
  // and request.label).
  RunRecord run(const RunRequest& request);

  // The configuration a request runs with (its realisation's seed, the shared packing in
  // place) and its fingerprint; settles the shared packing if it is not there yet.
  RunConfig config_for(const RunRequest& request, std::string& fingerprint, std::string& shared_packing_file);

  const std::filesystem::path& runs_dir() const { return runs_; }

 private:
  std::string packing_line(const std::string& packing_file);
  std::pair<std::string, std::string> shared_packing(const RunRequest& request);  // (path, fingerprint)
  std::shared_ptr<const ShearSample> shear_sample(const RunConfig& config, const std::string& packing_line);
  bool reusable(const std::filesystem::path& dir, const std::string& fingerprint, const RunConfig& config,
                bool needs_load_curves, RunRecord& record) const;

  std::filesystem::path runs_;
  bool verbose_;
  OncePerKey<std::string, std::shared_ptr<const ShearSample>> samples_;  // by sample fingerprint
  OncePerKey<std::string, std::pair<std::string, std::string>> packings_;  // by packing fingerprint
  // The contents line of each packing file a configuration names, read once per path: part
  // of every run's and sample's fingerprint, so a file replaced under the same path is not
  // answered with the old file's runs.
  OncePerKey<std::string, std::string> packing_lines_;
};

}  // namespace colza::calibration
