// DEM cases of `colza diagnose` on small samples: "measured" data made by colza with one
// mechanism switched on (or none, or an effect outside the candidate list), at seeds the
// diagnosis's runs never use (realisations 1000 and up; the diagnosis uses 0..R), averaged
// over three samples as a lab reports them, handed to `colza diagnose` as plain numbers in a
// spec that does not say which. Shared by the default
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
// tests/data/small_shear.toml without bonds, preconsolidated at its higher load (78.75 kPa)
// before each load is sheared, as a yield-locus test consolidates (ASTM D6128): a cohesion
// that grows with the stress a bulk has carried shows at the lower load. Friction is
// calibrated (0.1..0.5); the normal stiffness stays at the configs' 437 kN/m, as a lab takes it
// from single-seed compression tests: a bulk test alone cannot tell a stiffer linear contact
// from an elasto-plastic one (both shorten the rebound; the loading branch that would separate
// them is rearrangement, which scatters by half between packings of 170 spheres).
// Its features and a lab's repeatability as their measurement uncertainty, well under the
// realisation scatter measured on six seeds (sd: bulk density 15 kg/m^3, rebound strain
// 4.2e-4, unloading modulus 1.1 MPa, K 0.063, C 1.7 kPa, tan(Phi) 0.024). A lab set may add
// an angle of repose test, the test that tells rolling resistance from friction (physics.md
// section 8), with the same particles on a layer of spheres glued to the plate
// (repose.base = "glued_layer"):
// - the wide heap, tests/data/repose_wide.toml: a 100 mm cylinder, ~2600 spheres, viscous
//   contact damping instead of local damping (which also damps the spin, a rolling resistance
//   of its own). Its fit error is ~0.5 deg; without rolling resistance the angle saturates
//   near 18.7 deg above friction 0.4, so no friction stands in for rolling resistance: at
//   friction 0.2 14.8 deg, with mu_r = 0.09 21.4, with 0.18 25.3 (seed 1). About a minute a run
//   on one core.
// - the small heap, tests/data/small_repose.toml generated up to 180 mm (900 spheres do not
//   all fit below 150 mm on every seed), under local damping 0.2 (under the paper's 0.7 a heap
//   creeps for seconds): ~550 spheres, ~6 diameters wide, each fit's own error ~3.3 deg. At
//   friction 0.2, seeds 1-4: without rolling resistance 23.2, 11.2, 19.7, 19.5 deg; with
//   mu_r = 0.09 31.2, 25.0, 29.3, 31.6; with mu_r = 0.18 31.8, 34.4, 30.3, 31.9. Too noisy to
//   cut the ridge where a higher friction stands in for rolling resistance (on data seed 2 of
//   the rolling case the diagnosis finds no significant discrepancy).
struct SmallFeature {
  const char* test;
  const char* name;
  double uncertainty;
};
// Which angle of repose test the small set has, if any.
enum class ReposeHeap { none, small, wide };
struct SmallLab {
  ReposeHeap repose = ReposeHeap::none;
};
inline std::vector<SmallFeature> small_features(SmallLab lab = {}) {
  std::vector<SmallFeature> f = {{"oedometer", "bulk_density", 2.0},
                                 {"oedometer", "cycle1/rebound_strain", 1e-4},
                                 {"oedometer", "branch2/modulus@20000Pa", 3e5},
                                 {"oedometer", "branch1/lateral_ratio_end", 0.01},
                                 {"shear", "cohesion", 300.0},
                                 {"shear", "tan_phi", 0.01}};
  if (lab.repose != ReposeHeap::none) f.push_back({"repose", "angle_of_repose_deg", 1.0});
  return f;
}

// A lab reports each test's values as the mean of three samples (its `samples` in the spec).
constexpr int kLabSamples = 3;

// The spec, each feature's measured value from `value(k)` (k: index in small_features(lab)).
inline std::string small_spec(int replicates, const std::function<double(std::size_t)>& value, SmallLab lab = {}) {
  const std::string data = std::string(COLZA_SOURCE_DIR) + "/tests/data/";
  const std::vector<SmallFeature> features = small_features(lab);
  std::ostringstream s;
  s << "title = \"small samples\"\n"
    << "[settings]\nreplicates = " << replicates << "\nsignature_seeds = 3\ncalibration_runs = 12\nextend_at_most = 2\n"
    << "[[parameters]]\nname = \"mu_pp\"\nkey = \"particle.friction\"\nlower = 0.1\nupper = 0.5\n"
    << "[[candidates]]\nname = \"rolling_resistance\"\n"
    << "[[candidates]]\nname = \"elasto_plastic\"\n"
    << "[[candidates]]\nname = \"load_induced_cohesion\"\n";
  const auto features_of = [&](const std::string& test) {
    for (std::size_t k = 0; k < features.size(); ++k)
      if (features[k].test == test)
        s << "[[tests.features]]\nname = \"" << features[k].name << "\"\nvalue = "
          << format_significant(value(k), 17) << "\nuncertainty = " << features[k].uncertainty << "\n";
  };
  s << "[[tests]]\nname = \"oedometer\"\nscenario = \"oedometer\"\nconfig = \"" << data << "small_oedometer.toml\"\n"
    << "set = [\"oedometer.cycles=[40e3, 0.0]\", \"oedometer.record_interval=5\"]\nsamples = " << kLabSamples << "\n";
  features_of("oedometer");
  s << "[[tests]]\nname = \"shear\"\nscenario = \"shear\"\nconfig = \"" << data << "small_shear.toml\"\n"
    << "set = [\"contact.bond=none\", \"contact.bond_install=never\", \"particle.normal_stiffness=437e3\", "
    << "\"shear_box.preconsolidation_stress=78.75e3\"]\nsamples = " << kLabSamples << "\n";
  features_of("shear");
  if (lab.repose == ReposeHeap::small) {
    s << "[[tests]]\nname = \"repose\"\nscenario = \"repose\"\nconfig = \"" << data << "small_repose.toml\"\n"
      << "set = [\"particle.normal_stiffness=437e3\", \"particle.density=1250\", \"repose.generation_height=0.18\", "
      << "\"repose.base=glued_layer\", \"integration.damping=0.2\", \"repose.rest_max_time=4\"]\nsamples = " << kLabSamples
      << "\n";
    features_of("repose");
  } else if (lab.repose == ReposeHeap::wide) {
    s << "[[tests]]\nname = \"repose\"\nscenario = \"repose\"\nconfig = \"" << data << "repose_wide.toml\"\n"
      << "samples = " << kLabSamples << "\n";
    features_of("repose");
  }
  return s.str();
}

// What hides in the data.
struct HiddenEffect {
  std::string candidate;                    // a candidate of the spec, or "" for none
  double strength = 0.0;
  std::vector<std::string> other_settings;  // an effect outside the candidates (another wall friction, ...)
};

// The features of the truth (friction 0.2, kn 437 kN/m) with the hidden effect: the mean of
// kLabSamples realisations, 1000 + kLabSamples (data_seed - 1) + 1, 2, ..., run in
// `data_runs`, apart from the diagnosis's runs.
inline Eigen::VectorXd small_truth_features(const HiddenEffect& hidden, int data_seed,
                                            const std::filesystem::path& data_runs, SmallLab lab = {}) {
  std::filesystem::create_directories(data_runs);
  const std::filesystem::path spec_file = data_runs / "truth-spec.toml";
  write_file(spec_file, small_spec(3, [](std::size_t) { return 0.0; }, lab));
  diagnose::DiagnosisSpec spec = diagnose::read_diagnosis_spec(spec_file.string());
  for (auto& t : spec.tests) t.set.insert(t.set.end(), hidden.other_settings.begin(), hidden.other_settings.end());
  diagnose::ModelPoint truth{Eigen::VectorXd::Constant(1, 0.2)};
  for (std::size_t k = 0; k < spec.candidates.size(); ++k)
    if (spec.candidates[k].candidate.name == hidden.candidate) {
      truth.candidate = static_cast<int>(k);
      truth.strength = hidden.strength;
    }
  calibration::RunCache cache(data_runs, false);
  diagnose::DemForward dem(spec, cache, false);
  Eigen::VectorXd sum;
  for (int k = 1; k <= kLabSamples; ++k) {
    const Eigen::VectorXd y = dem(truth, 1000 + kLabSamples * (data_seed - 1) + k);
    sum = k == 1 ? y : Eigen::VectorXd(sum + y);
  }
  return sum / kLabSamples;
}

// Makes the data, writes the spec into `dir`, runs `colza diagnose` there (--jobs 2) and
// returns its summary.json.
inline nlohmann::json diagnose_small(const HiddenEffect& hidden, int data_seed, const std::filesystem::path& dir,
                                     int replicates = 6, SmallLab lab = {}) {
  const Eigen::VectorXd m = small_truth_features(hidden, data_seed, dir / "data-runs", lab);
  const std::filesystem::path spec = dir / "spec.toml";
  write_file(spec, small_spec(replicates, [&](std::size_t k) { return m[static_cast<Eigen::Index>(k)]; }, lab));
  const CliResult r = run_colza("diagnose --spec " + spec.string() + " --out " + (dir / "out").string() +
                                " --runs " + (dir / "runs").string() + " --jobs 2 --threads 1 --quiet --force");
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  return nlohmann::json::parse(read_file(dir / "out" / "summary.json"));
}

}  // namespace colza::testing
