// What the parts of `crosscheck shear` share: one size of the check ([shear.<size>] of the
// tolerance table, its scene and work folder), the configs they write for both codes and the
// names of their run folders.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <toml++/toml.h>
#include <vector>
#include "checks.hpp"
#include "report.hpp"
#include "tolerances.hpp"

namespace crosscheck {

struct ShearSetting {
  std::string size;   // "small" or "full"
  std::string base;   // "shear.<size>"
  std::string label;  // "shear <size>"
  const toml::table& t;
  fs::path scene, work;
  ToleranceSection tolerances() const { return {t, base}; }
};

// `doc` written as `name` into the work folder, for both codes (throws if it cannot be).
inline fs::path write_config(const ShearSetting& s, const toml::table& doc, const std::string& name) {
  return write_run_config(s.work / name, doc, s.scene);
}

// --normal-stress sigma, at full precision.
inline std::vector<std::string> normal_stress_argument(double sigma) {
  return {"--normal-stress", fmt(sigma, "%.17g")};
}

// A load's run folder name without the code's prefix: "load-25750Pa" for realisation 0 (the
// sample as colza made it), "load-25750Pa-r3" for realisation 3 of the ensemble.
inline std::string load_run_name(double sigma, std::size_t realisation) {
  std::string name = "load-" + whole_pascals(sigma) + "Pa";
  if (realisation > 0) name += "-r" + std::to_string(realisation);
  return name;
}

// The run folder of one code ("colza" or "yade") for that load and realisation.
inline fs::path load_run_folder(const ShearSetting& s, const std::string& code, double sigma, std::size_t realisation) {
  return s.work / (code + "_" + load_run_name(sigma, realisation));
}

// The ensemble comparison of the loads (shear_ensemble.cpp): realisations 1..N-1 of every
// load in both codes from perturbed copies of the sample (realisation 0 is the load run of
// compare_load), then the mean strengths, their mean relative difference, C and Phi judged by
// Welch's t test.
// `doc` is the scene with the sample's packing_file set. Nothing when the tolerance table
// asks for fewer than two realisations.
void compare_shear_ensemble(const CheckContext& ctx, const ShearSetting& s, Report& report, const toml::table& doc,
                            const std::vector<double>& loads);

}  // namespace crosscheck
