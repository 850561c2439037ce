// The DEM as a calibration forward model: parameters -> targets. A point x becomes the spec's
// overrides plus one "key=value" per parameter (and, for shear, the spec's loads as
// shear_box.normal_stresses), run by the run cache (run_cache.hpp: fingerprints, reuse,
// shared packings and samples) and turned into targets by name from the run's features
// (run_features.hpp): density: bulk density; compression: c1, c2 of F = c0 + c1 s + c2 s^2;
// shear: C and tan(Phi) of the Mohr-Coulomb line through the window strengths, or through
// the peak strengths of the run's kept load curves (measured.strength = "peak").
// Realisation k >= 1 of a point (realisation scatter, calibrate.hpp) is the same run with
// seed = config seed + k: its own sample (shear), its own shared packing (compression).
// Thread-safe.
#pragma once
#include <Eigen/Dense>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calibration/run_cache.hpp"
#include "calibration/spec.hpp"

namespace colza::calibration {

// A design run as the calibration sees it: the point, the targets read from it, and the run
// cache's record of it (its id, realisation, reuse, wall time, revision, outputs).
struct DemRunRecord {
  Eigen::VectorXd x, y;
  RunRecord run;
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
  RunRequest request_for(const Eigen::VectorXd& x, int replicate) const;
  Eigen::VectorXd targets_from(const RunRecord& run);
  void print_run(const Eigen::VectorXd& x, const RunRecord& run, const Eigen::VectorXd& y) const;

  const Spec& spec_;
  RunCache cache_;
  bool verbose_;
  mutable std::mutex mutex_;           // records_
  std::vector<DemRunRecord> records_;
  mutable std::mutex note_mutex_;      // packing_note_, warnings_
  std::string packing_note_;
  std::vector<std::string> warnings_;
};

}  // namespace colza::calibration
