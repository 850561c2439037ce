// The typed run configuration: one struct per config table, defaults = the paper's
// Table 1 (compression start, physics.md section 5). data/oedometer.toml states the
// same values with their provenance; a unit test keeps the two equal.
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "config/config_reader.hpp"
#include "config/oedometer_cycle_spec.hpp"
#include "config/repose_spec.hpp"
#include "engine/world.hpp"

namespace colza {

struct ParticleSpec {                 // [particle]
  double density = 1250.0;            // rho_p (kg/m^3)
  double normal_stiffness = 437e3;    // kn of the particle entity (N/m)
  double shear_stiffness = 100e3;     // ks (N/m)
  double friction = 0.20;             // mu_pp (-)
  double diameter_min = 6e-3;         // m; diameters uniform on [min, max]
  double diameter_max = 7e-3;         // m
  double young_modulus = 0.0;         // E (Pa), read when given; the Hertz-Mindlin slots need it
  double poisson_ratio = 0.0;         // nu (-), read with young_modulus
};

struct WallSpec {                     // [wall]
  double normal_stiffness = 4000e3;   // kn_w (N/m)
  double shear_stiffness = 1000e3;    // ks_w (N/m)
  double friction = 0.23;             // mu_pw (-)
  double young_modulus = 0.0;         // E (Pa), read when given; the Hertz-Mindlin slots need it
  double poisson_ratio = 0.0;         // nu (-), read with young_modulus
};

struct IntegrationSpec {              // [integration]
  double damping = 0.7;               // local damping alpha (-)
  DampingForm damping_form = DampingForm::kPfc;
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);
  bool automatic_time_step = true;    // time_step = "auto" or a number (s)
  double time_step = 0.0;
  double safety_factor = 0.8;
  std::int64_t recompute_interval = 100;
  double verlet_skin = 0.5e-3;        // m
};

struct SampleSpec {                   // [sample]
  std::int64_t count = 2600;          // spheres generated before settling (the oedometer's)
  // The shear box's default count, data/shear.toml's for the paper's 200 x 200 mm box (2600
  // would settle not a layer above its shear plane: config/sample_depth.hpp).
  static constexpr std::int64_t kShearBoxCount = 12800;
  double settle_unbalanced_force = 1e-4;  // N, mean over particles (paper: 1e-4 oedometer)
  double settle_max_time = 5.0;       // s of simulated time before settling gives up
  std::int64_t settle_check_interval = 200;  // steps between checks
  std::int64_t max_placement_attempts = 1000000;
};

struct OedometerSpec {                // [oedometer]
  double cylinder_diameter = 0.100;   // m (paper: 100 mm)
  double cylinder_height = 0.080;     // m, the rim: particles whose top is above it are discarded
  double generation_height = 0.200;   // m, particles are generated in diameter x this height
  double piston_speed = 0.5 / 60.0;   // m/s (500 mm/min)
  double stop_force = 30e3;           // N, loading ends when the piston force reaches this
  double max_piston_travel = 0.040;   // m, loading also ends here
  std::int64_t record_interval = 50;  // steps between curve samples
  double fit_force_min = 150.0;       // N, displacement zeroed here; fit range start
  double fit_force_max = 29.3e3;      // N, fit range end (paper logs 150 N - 29.3 kN)
  // Optional settled packing ("x y z r" per line, e.g. a previous run's packing.txt): when
  // given, generation and settling are skipped and loading starts from it at rest. This is
  // how colza and YADE start from the identical sample in the cross-check.
  std::string packing_file;
  // oedometer.cycles (config/oedometer_cycle_spec.hpp): load-unload targets; empty = one loading.
  OedometerCycleSpec cycles;
};

// How the shear box's plates touch a sphere where two of them meet (walls/wall.hpp, RectangleEdges).
// kPerWall: every plate is a wall of its own, edges included, so a sphere at the seam of an
// upper and a lower side wall, or at the corner of a rim and its side wall, can get a
// contact from each (PFC3D 4's walls and YADE's boxes do the same: the paper's model and the
// cross-check's). kPerSurface: one contact per surface there (the plates' shared edges restricted).
enum class BoxEdgeContacts { kPerWall, kPerSurface };
const char* to_string(BoxEdgeContacts e);

struct ShearBoxSpec {                // [shear_box], physics.md section 4
  double length = 0.200;              // m, inner size along x (shear direction)
  double width = 0.200;               // m, inner size along y
  double height = 0.080;              // m, both halves; particles above are discarded
  double shear_plane = 0.040;         // m, height of the lower half
  double rim_length = 0.040;          // m, the rims are length-wise plates of rim_length x width
  double generation_height = 0.200;   // m, particles are generated in the box extended to this height
  std::vector<double> normal_stresses{25.75e3, 43.50e3, 61.00e3, 78.75e3};  // Pa, on length x width
  double shear_speed = 0.3 / 60.0;    // m/s (300 mm/min, the paper's simulation speed; lab: 3 mm/min)
  double shear_displacement = 0.030;  // m, shearing stops here
  double strength_window_start = 0.020;  // m, shear strength = mean stress over [start, end]
  double strength_window_end = 0.030;    // m
  double servo_relaxation = 0.5;      // fraction of the force error corrected per step (-)
  double servo_max_speed = 0.05;      // m/s, plate speed limit
  double consolidation_tolerance = 0.01;  // relative stress error for "held"
  double consolidation_window = 0.02;     // s, stress held and plate still for this long
  double consolidation_plate_speed = 1e-4;  // m/s, "still" means slower than this
  double consolidation_max_time = 2.0;      // s
  // Pa; 0 = none. Overconsolidation (soil mechanics' preconsolidation stress; the consolidation
  // step of Jenike's and Schulze's yield-locus tests, ASTM D6128, without the pre-shear): each
  // load is first consolidated at this stress, then unloaded to its normal stress and sheared.
  // Cohesion that grows with the stress a bulk has carried shows as strength at the lower load.
  double preconsolidation_stress = 0.0;
  std::int64_t record_interval = 100;       // steps between curve samples
  std::string packing_file;           // optional settled packing (skips generation and settling)
  BoxEdgeContacts edge_contacts = BoxEdgeContacts::kPerWall;  // shear_box.edge_contacts
};

struct SceneParticle {
  Vec3 position = Vec3::Zero();
  double radius = 0.0;
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  bool fixed = false;
};

struct SceneSpec {                    // [scene]
  std::int64_t steps = 0;             // the run ends after this many steps at most
  // Optional stop condition: end as soon as the mean unbalanced force per particle (N, as
  // in settling) falls below this; 0 = run all `steps`.
  double stop_unbalanced_force = 0.0;
  std::string packing_file;           // optional "x y z r" per line, full precision
  std::vector<SceneParticle> particles;
  std::vector<Wall> walls;
  std::int64_t record_interval = 1;
  std::vector<std::int64_t> record_particles;  // indices; empty = none
};

// [output]: what a `colza run` writes beside its results. Not part of the physics: a key
// left out is not written into the resolved config (RunConfig::resolved_toml), so the
// run's fingerprint (calibration run reuse) is that of its physics alone.
struct OutputSpec {
  // Simulated seconds between particle snapshots in result.h5 (and result.xmf), counted from
  // the start of the test (the oedometer's loading, the shear box's consolidation of each
  // load, the angle of repose's lift, the scene's first step); 0 = none. Default per
  // scenario: default_snapshot_interval.
  double snapshot_interval = 0.0;
  // output.plots: draw the result's plots into DIR/plots/ after the run (cli/plot_command.hpp).
  bool plots = true;
};
struct RunConfig {
  std::string source;                 // file name (or built-in defaults)
  std::vector<std::string> overrides; // --set key=value (and --seed as seed=N), in order
  // Where a key's value came from, for an error about it found while running: "--set KEY"
  // when an override set it, else the file (as the config reader's errors name it).
  std::string origin_of(const std::string& key) const {
    for (const std::string& o : overrides)
      if (o.rfind(key + "=", 0) == 0) return "--set " + key;
    return source;
  }
  std::string resolved_toml;          // the configuration as used, overrides applied
  std::uint64_t seed = 1;
  ParticleSpec particle;
  WallSpec wall;
  ContactModel contact;
  StiffnessRule stiffness_rule = StiffnessRule::kSeries;
  WallFrictionRule wall_friction = WallFrictionRule::kOwn;  // contact.wall_friction
  IntegrationSpec integration;
  SampleSpec sample;
  OedometerSpec oedometer;
  ShearBoxSpec shear_box;
  ReposeSpec repose;
  SceneSpec scene;
  OutputSpec output;
};

enum class Scenario { kOedometer, kShear, kScene, kRepose };
const char* to_string(Scenario s);

// Defaults of output.snapshot_interval (s): a few dozen snapshots of each test (the
// oedometer loads for ~1-2 s, the shear box consolidates and shears for ~6-7 s, the angle of
// repose's cylinder is lifted for ~11 s); none for a scene (set it to have them).
double default_snapshot_interval(Scenario s);

// Reads and validates everything the scenario needs, then rejects unknown keys.
// `config_path` empty = built-in defaults. Throws ConfigError.
RunConfig load_run_config(Scenario scenario, const std::string& config_path,
                          const std::vector<std::string>& overrides);
RunConfig read_run_config(Scenario scenario, const ConfigReader& reader);

// Materials, contact model and integration settings for the Stepper.
PhysicsSettings make_physics(const RunConfig& config);

}  // namespace colza
