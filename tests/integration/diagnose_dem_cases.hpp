// DEM cases of `colza diagnose` on small samples: "measured" data made by colza with one
// mechanism switched on (or none, or an effect outside the candidate list), at seeds the
// diagnosis's runs never use (realisation 1000 + data seed, i.e. seed + 1000 + s), handed to
// `colza diagnose` as plain numbers in a spec that does not say which. Shared by the default
// run's cases (tests/integration/test_diagnose_dem.cpp) and the seed study (label full).
#pragma once
#include <Eigen/Dense>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "calibration/run_cache.hpp"
#include "cli_runner.hpp"
#include "diagnose/dem_forward.hpp"
#include "diagnose/diagnosis_spec.hpp"
#include "io/format_number.hpp"

namespace colza::testing {

// The small model: tests/data/small_oedometer.toml with a load-unload cycle to 40 kPa and
// tests/data/small_shear.toml without bonds; friction and normal stiffness calibrated.
// Its features and a lab's repeatability as their measurement uncertainty, well under the
// realisation scatter measured on six seeds (sd: bulk density 15 kg/m^3, rebound strain
// 4.2e-4, unloading modulus 1.1 MPa, K 0.063, C 1.7 kPa, tan(Phi) 0.024).
struct SmallFeature {
  const char* test;
  const char* name;
  double uncertainty;
};
inline const std::vector<SmallFeature>& small_features() {
  static const std::vector<SmallFeature> f = {{"oedometer", "bulk_density", 2.0},
                                              {"oedometer", "cycle1/rebound_strain", 1e-4},
                                              {"oedometer", "branch2/modulus@20000Pa", 3e5},
                                              {"oedometer", "branch1/lateral_ratio_end", 0.01},
                                              {"shear", "cohesion", 300.0},
                                              {"shear", "tan_phi", 0.01}};
  return f;
}

// The spec, each feature's measured value from `value(k)` (k: index in small_features()).
inline std::string small_spec(int replicates, const std::function<double(std::size_t)>& value) {
  const std::string data = std::string(COLZA_SOURCE_DIR) + "/tests/data/";
  std::ostringstream s;
  s << "title = \"small samples\"\n"
    << "[settings]\nreplicates = " << replicates << "\nsignature_seeds = 3\ncalibration_runs = 8\nextend_at_most = 2\n"
    << "[[parameters]]\nname = \"mu_pp\"\nkey = \"particle.friction\"\nlower = 0.1\nupper = 0.5\n"
    << "[[parameters]]\nname = \"kn_p\"\nkey = \"particle.normal_stiffness\"\nunit = \"N/m\"\nlower = 250e3\nupper = 650e3\n"
    << "[[candidates]]\nname = \"rolling_resistance\"\n"
    << "[[candidates]]\nname = \"elasto_plastic\"\n"
    << "[[candidates]]\nname = \"load_induced_cohesion\"\n";
  const auto features_of = [&](const std::string& test) {
    for (std::size_t k = 0; k < small_features().size(); ++k)
      if (small_features()[k].test == test)
        s << "[[tests.features]]\nname = \"" << small_features()[k].name << "\"\nvalue = "
          << format_significant(value(k), 17) << "\nuncertainty = " << small_features()[k].uncertainty << "\n";
  };
  s << "[[tests]]\nname = \"oedometer\"\nscenario = \"oedometer\"\nconfig = \"" << data << "small_oedometer.toml\"\n"
    << "set = [\"oedometer.cycles=[40e3, 0.0]\", \"oedometer.record_interval=5\"]\n";
  features_of("oedometer");
  s << "[[tests]]\nname = \"shear\"\nscenario = \"shear\"\nconfig = \"" << data << "small_shear.toml\"\n"
    << "set = [\"contact.bond=none\", \"contact.bond_install=never\"]\n";
  features_of("shear");
  return s.str();
}

// What hides in the data.
struct HiddenEffect {
  std::string candidate;                    // a candidate of the spec, or "" for none
  double strength = 0.0;
  std::vector<std::string> other_settings;  // an effect outside the candidates (another wall friction, ...)
};

// The features of the truth (friction 0.2, kn 437 kN/m: the configs' own) with the hidden
// effect, realisation 1000 + data_seed, run in `data_runs`, apart from the diagnosis's runs.
inline Eigen::VectorXd small_truth_features(const HiddenEffect& hidden, int data_seed,
                                            const std::filesystem::path& data_runs) {
  std::filesystem::create_directories(data_runs);
  const std::filesystem::path spec_file = data_runs / "truth-spec.toml";
  write_file(spec_file, small_spec(3, [](std::size_t) { return 0.0; }));
  diagnose::DiagnosisSpec spec = diagnose::read_diagnosis_spec(spec_file.string());
  for (auto& t : spec.tests) t.set.insert(t.set.end(), hidden.other_settings.begin(), hidden.other_settings.end());
  diagnose::ModelPoint truth{Eigen::Vector2d(0.2, 437e3)};
  for (std::size_t k = 0; k < spec.candidates.size(); ++k)
    if (spec.candidates[k].candidate.name == hidden.candidate) {
      truth.candidate = static_cast<int>(k);
      truth.strength = hidden.strength;
    }
  calibration::RunCache cache(data_runs, false);
  diagnose::DemForward dem(spec, cache, false);
  return dem(truth, 1000 + data_seed);
}

// Makes the data, writes the spec into `dir`, runs `colza diagnose` there (--jobs 2) and
// returns its summary.json.
inline nlohmann::json diagnose_small(const HiddenEffect& hidden, int data_seed, const std::filesystem::path& dir,
                                     int replicates = 6) {
  const Eigen::VectorXd m = small_truth_features(hidden, data_seed, dir / "data-runs");
  const std::filesystem::path spec = dir / "spec.toml";
  write_file(spec, small_spec(replicates, [&](std::size_t k) { return m[static_cast<Eigen::Index>(k)]; }));
  const CliResult r = run_colza("diagnose --spec " + spec.string() + " --out " + (dir / "out").string() +
                                " --runs " + (dir / "runs").string() + " --jobs 2 --threads 1 --quiet --force");
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  return nlohmann::json::parse(read_file(dir / "out" / "summary.json"));
}

}  // namespace colza::testing
