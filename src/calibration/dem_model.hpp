// The DEM as a calibration forward model: parameters -> targets by running colza's
// oedometer (density: bulk density; compression: c1, c2 of F = c0 + c1 s + c2 s^2) or a
// shear series over the spec's loads (shear: C and tan(Phi) of the Mohr-Coulomb line).
// Every run is kept in <runs>/<fingerprint>/summary.json (with the curve: curve.csv, or
// load-<sigma>Pa.csv per shear load), the fingerprint being FNV-1a 64
// of the run's full configuration as used (model config + spec overrides + parameters +
// shared packing); a calibration started again reuses finished runs. Thread-safe.
// Realisation k >= 1 of a point (realisation scatter, calibrate.hpp) is the same run with
// seed = config seed + k: its own sample (shear), its own shared packing (compression).
#pragma once
#include <Eigen/Dense>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calibration/spec.hpp"
#include "io/table.hpp"
#include "core/concurrent.hpp"
#include "scenario/shear_box.hpp"

namespace colza::calibration {

struct DemRunRecord {
  std::string id;           // fingerprint = directory name under runs/
  Eigen::VectorXd x, y;
  int replicate = 0;        // realisation: seed = config seed + replicate
  bool reused = false;
  double wall_seconds = 0;  // of the original run
  std::string made_by;      // git revision of the colza that ran it ("unknown" for runs older than the field)
  nlohmann::json outputs;
};

class DemModel {
 public:
  DemModel(const Spec& spec, std::filesystem::path runs_dir, bool verbose);
  Eigen::VectorXd operator()(const Eigen::VectorXd& x) { return run(x, 0); }
  Eigen::VectorXd run(const Eigen::VectorXd& x, int replicate);
  std::vector<DemRunRecord> records() const;
  const DemRunRecord* find(const Eigen::VectorXd& x, int replicate) const;
  std::string shared_packing_note() const {
    std::lock_guard<std::mutex> lock(note_mutex_);
    return packing_note_;
  }
  std::vector<std::string> warnings() const {  // about runs (a peak at the end of a curve)
    std::lock_guard<std::mutex> lock(note_mutex_);
    return warnings_;
  }

 private:
  RunConfig config_for(const Eigen::VectorXd& x, int replicate, std::string& fingerprint);
  std::vector<std::string> seed_override(int replicate) const;
  nlohmann::json run_oedometer_outputs(const RunConfig& c, const std::filesystem::path& dir, double& wall);
  nlohmann::json run_shear_outputs(const RunConfig& c, double& wall, std::vector<Table>& curves);
  std::shared_ptr<const ShearSample> shear_sample(const RunConfig& c);
  std::pair<std::string, std::string> shared_packing(int replicate);  // (path, fingerprint)
  Eigen::VectorXd targets_from(const nlohmann::json& outputs, const std::string& id) const;
  Eigen::VectorXd peak_targets(const std::filesystem::path& run_dir, const std::string& id);  // shear, strength = "peak"
  bool has_load_curves(const std::filesystem::path& run_dir) const;

  const Spec& spec_;
  std::filesystem::path runs_;
  bool verbose_;
  mutable std::mutex mutex_;           // records_
  std::vector<DemRunRecord> records_;
  OncePerKey<std::string, std::shared_ptr<const ShearSample>> samples_;  // by sample fingerprint
  OncePerKey<int, std::pair<std::string, std::string>> packings_;       // replicate -> (path, fingerprint)
  mutable std::mutex note_mutex_;      // packing_note_, warnings_
  std::string packing_note_;
  std::vector<std::string> warnings_;
  // The contents of the packing file every run loads (spec.fixed_packing_file), read once:
  // part of every run's and sample's fingerprint, so that a file replaced under the same
  // path is not answered with the old file's runs.
  const std::string fixed_packing_line_;
};

}  // namespace colza::calibration
