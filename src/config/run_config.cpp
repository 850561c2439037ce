#include "config/run_config.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <sstream>

#include "config/sample_depth.hpp"
#include "contact/slot_registry.hpp"
#include "io/format_number.hpp"
#include "io/load_label.hpp"
#include "io/packing_check.hpp"
#include "io/packing_file.hpp"

namespace colza {

const char* to_string(Scenario s) {
  switch (s) {
    case Scenario::kOedometer: return "oedometer";
    case Scenario::kShear: return "shear";
    case Scenario::kScene: return "scene";
    case Scenario::kRepose: return "repose";
  }
  return "?";
}

double default_snapshot_interval(Scenario s) {
  switch (s) {
    case Scenario::kOedometer: return 0.05;
    case Scenario::kShear: return 0.2;
    case Scenario::kRepose: return 0.5;
    case Scenario::kScene: return 0.0;
  }
  return 0.0;
}

const char* to_string(BoxEdgeContacts e) {
  return e == BoxEdgeContacts::kPerWall ? "per_wall" : "per_surface";
}

namespace {

// E (Pa) and nu (-) of a material table, read only when the table gives E (a model without
// the Hertz-Mindlin slots does not use them, and its stored config does not state them).
void read_hertz_moduli(const ConfigNode& t, double& young, double& poisson) {
  if (!t.has("young_modulus") && !t.has("poisson_ratio")) return;
  young = t.positive("young_modulus", young);
  poisson = t.number_in("poisson_ratio", 0.3, 0.0, 0.5);
}

// The Hertz-Mindlin slots need E and nu of the particles and the walls.
void require_hertz_moduli(const ConfigNode& root, const RunConfig& c) {
  if (!needs_hertz_moduli(c.contact)) return;
  const char* why = "is required by contact.normal = \"hertz\" or contact.tangential = \"mindlin\" (Pa)";
  if (!(c.particle.young_modulus > 0.0)) root.table("particle").fail("young_modulus", why);
  if (!(c.wall.young_modulus > 0.0)) root.table("wall").fail("young_modulus", why);
}

ParticleSpec read_particle(const ConfigNode& t) {
  ParticleSpec p;
  p.density = t.positive("density", p.density);
  p.normal_stiffness = t.positive("normal_stiffness", p.normal_stiffness);
  p.shear_stiffness = t.positive("shear_stiffness", p.shear_stiffness);
  p.friction = t.non_negative("friction", p.friction);
  p.diameter_min = t.positive("diameter_min", p.diameter_min);
  p.diameter_max = t.positive("diameter_max", p.diameter_max);
  if (p.diameter_min > p.diameter_max)
    t.fail("diameter_min", "must not exceed particle.diameter_max (" + std::to_string(p.diameter_max) + ")");
  read_hertz_moduli(t, p.young_modulus, p.poisson_ratio);
  return p;
}

WallSpec read_wall(const ConfigNode& t) {
  WallSpec w;
  w.normal_stiffness = t.positive("normal_stiffness", w.normal_stiffness);
  w.shear_stiffness = t.positive("shear_stiffness", w.shear_stiffness);
  w.friction = t.non_negative("friction", w.friction);
  read_hertz_moduli(t, w.young_modulus, w.poisson_ratio);
  return w;
}

IntegrationSpec read_integration(const ConfigNode& t) {
  IntegrationSpec s;
  s.damping = t.number_in("damping", s.damping, 0.0, 0.999);
  s.damping_form = t.choice("damping_form", "pfc", {"pfc", "yade"}) == "pfc" ? DampingForm::kPfc : DampingForm::kYade;
  s.gravity = t.vec3("gravity", s.gravity);
  if (t.has("time_step") && !t.is_string("time_step")) {
    s.automatic_time_step = false;
    s.time_step = t.positive("time_step", 0.0);
  } else {
    t.choice("time_step", "auto", {"auto"});  // absent: "auto", recorded as used
    s.automatic_time_step = true;
  }
  s.safety_factor = t.number_in("safety_factor", s.safety_factor, 1e-3, 1.0);
  s.recompute_interval = t.integer("recompute_interval", s.recompute_interval, 1);
  s.verlet_skin = t.positive("verlet_skin", s.verlet_skin);
  return s;
}

SampleSpec read_sample(const ConfigNode& t, Scenario scenario) {
  SampleSpec s;
  if (scenario == Scenario::kShear) s.count = SampleSpec::kShearBoxCount;
  s.count = t.integer("count", s.count, 1);
  s.settle_unbalanced_force = t.positive("settle_unbalanced_force", s.settle_unbalanced_force);
  s.settle_max_time = t.positive("settle_max_time", s.settle_max_time);
  s.settle_check_interval = t.integer("settle_check_interval", s.settle_check_interval, 1);
  s.max_placement_attempts = t.integer("max_placement_attempts", s.max_placement_attempts, 1);
  return s;
}

OedometerSpec read_oedometer(const ConfigNode& t, const ParticleSpec& particle) {
  OedometerSpec o;
  o.cylinder_diameter = t.positive("cylinder_diameter", o.cylinder_diameter);
  o.cylinder_height = t.positive("cylinder_height", o.cylinder_height);
  o.generation_height = t.positive("generation_height", o.generation_height);
  o.piston_speed = t.positive("piston_speed", o.piston_speed);
  o.stop_force = t.positive("stop_force", o.stop_force);
  o.max_piston_travel = t.positive("max_piston_travel", o.max_piston_travel);
  o.record_interval = t.integer("record_interval", o.record_interval, 1);
  o.fit_force_min = t.non_negative("fit_force_min", o.fit_force_min);
  o.fit_force_max = t.positive("fit_force_max", o.fit_force_max);
  if (o.fit_force_min >= o.fit_force_max) t.fail("fit_force_min", "must be below oedometer.fit_force_max");
  if (o.cylinder_diameter <= particle.diameter_max)
    t.fail("cylinder_diameter", format_shortest(o.cylinder_diameter) + " m must exceed particle.diameter_max, " +
                                    format_shortest(particle.diameter_max) + " m (lengths are in metres)");
  if (o.generation_height < o.cylinder_height) t.fail("generation_height", "must be at least oedometer.cylinder_height");
  o.packing_file = t.string("packing_file", "");
  o.cycles = read_oedometer_cycles(t, kPi * 0.25 * o.cylinder_diameter * o.cylinder_diameter, o.stop_force);
  return o;
}

ShearBoxSpec read_shear_box(const ConfigNode& t, const ParticleSpec& particle) {
  ShearBoxSpec b;
  b.length = t.positive("length", b.length);
  b.width = t.positive("width", b.width);
  b.height = t.positive("height", b.height);
  b.shear_plane = t.positive("shear_plane", b.shear_plane);
  b.rim_length = t.positive("rim_length", b.rim_length);
  b.generation_height = t.positive("generation_height", b.generation_height);
  b.normal_stresses = t.number_list("normal_stresses", b.normal_stresses);
  for (double v : b.normal_stresses)
    if (!(v > 0.0)) t.fail("normal_stresses", "every normal stress must be positive (Pa)");
  if (b.normal_stresses.empty()) t.fail("normal_stresses", "needs at least one normal stress (Pa)");
  if (const std::string clash = loads_sharing_a_label(b.normal_stresses); !clash.empty())
    t.fail("normal_stresses", clash);
  b.shear_speed = t.positive("shear_speed", b.shear_speed);
  b.shear_displacement = t.positive("shear_displacement", b.shear_displacement);
  b.strength_window_start = t.non_negative("strength_window_start", b.strength_window_start);
  b.strength_window_end = t.positive("strength_window_end", b.strength_window_end);
  b.servo_relaxation = t.number_in("servo_relaxation", b.servo_relaxation, 1e-3, 1.0);
  b.servo_max_speed = t.positive("servo_max_speed", b.servo_max_speed);
  b.consolidation_tolerance = t.positive("consolidation_tolerance", b.consolidation_tolerance);
  b.consolidation_window = t.positive("consolidation_window", b.consolidation_window);
  b.consolidation_plate_speed = t.positive("consolidation_plate_speed", b.consolidation_plate_speed);
  b.consolidation_max_time = t.positive("consolidation_max_time", b.consolidation_max_time);
  b.preconsolidation_stress = t.non_negative("preconsolidation_stress", b.preconsolidation_stress);
  for (double v : b.normal_stresses)
    if (b.preconsolidation_stress > 0.0 && b.preconsolidation_stress < v)
      t.fail("preconsolidation_stress", format_shortest(b.preconsolidation_stress) + " Pa is below the normal stress " +
                                            format_shortest(v) + " Pa of shear_box.normal_stresses: a sample is "
                                            "preconsolidated at a stress above every load it is sheared at (0 = none)");
  b.record_interval = t.integer("record_interval", b.record_interval, 1);
  b.packing_file = t.string("packing_file", "");
  b.edge_contacts = t.choice("edge_contacts", "per_wall", {"per_wall", "per_surface"}) == "per_wall"
                        ? BoxEdgeContacts::kPerWall
                        : BoxEdgeContacts::kPerSurface;
  const auto m = [](double v) { return format_shortest(v) + " m"; };
  if (b.shear_plane >= b.height)
    t.fail("shear_plane", m(b.shear_plane) + " must lie below shear_box.height, " + m(b.height));
  if (b.generation_height < b.height)
    t.fail("generation_height", m(b.generation_height) + " must be at least shear_box.height, " + m(b.height));
  // The halves part by the shear displacement: past the box's length nothing of the sample is
  // sheared any more (a walk-through's 30, mm for m, would have run ~1e8 steps, hours).
  if (b.shear_displacement >= b.length)
    t.fail("shear_displacement", m(b.shear_displacement) + " must be below shear_box.length, " + m(b.length) +
                                     " (lengths are in metres)");
  if (b.strength_window_start >= b.strength_window_end)
    t.fail("strength_window_start", m(b.strength_window_start) + " must be below shear_box.strength_window_end, " +
                                        m(b.strength_window_end));
  if (b.strength_window_end > b.shear_displacement)
    t.fail("strength_window_end", m(b.strength_window_end) + " must not exceed shear_box.shear_displacement, " +
                                      m(b.shear_displacement) + " (the window is where the strength is averaged: "
                                      "shorten it with the shear)");
  if (std::min(b.length, b.width) <= particle.diameter_max) {
    const bool length = b.length <= b.width;
    t.fail(length ? "length" : "width", m(length ? b.length : b.width) + " must exceed particle.diameter_max, " +
                                            m(particle.diameter_max) + ": the box must be wider than a particle "
                                            "(lengths are in metres)");
  }
  return b;
}

// Settling stops when the mean unbalanced force per sphere falls below
// sample.settle_unbalanced_force (N; physics.md section 4, the paper's "unbalance force").
// A sample still falling has a mean unbalanced force of the mean sphere weight, m g with
// m = rho (pi / 6) E[d^3] and E[d^3] = (dmax^4 - dmin^4) / (4 (dmax - dmin)) for diameters
// uniform on [dmin, dmax]: a criterion at or above that weight is met before the spheres
// land (found with 4.5-5.5 mm seeds at the shear box's 1e-3 N, and with a density given in
// g/cm^3), so it is refused. The paper's criteria are 5.7 % (oedometer, 1e-4 N) and 57 %
// (shear box, 1e-3 N) of the weight of its 6-7 mm seeds.
void require_a_criterion_below_the_weight(const RunConfig& c, const ConfigNode& sample) {
  const double dmin = c.particle.diameter_min, dmax = c.particle.diameter_max;
  const double weight = c.particle.density * mean_sphere_volume(c.particle) * c.integration.gravity.norm();
  const double criterion = c.sample.settle_unbalanced_force;
  if (criterion < weight) return;
  sample.fail("settle_unbalanced_force",
              format_significant(criterion, 6) + " N is not below the weight of a sphere of the mean size, " +
                  format_significant(weight, 3) + " N (particle.density " + format_shortest(c.particle.density) +
                  " kg/m^3, diameters " + format_shortest(dmin) + " .. " + format_shortest(dmax) +
                  " m, |integration.gravity| " + format_shortest(c.integration.gravity.norm()) +
                  " m/s^2): a sample still falling meets it, so settling would stop before the spheres land. "
                  "Lower it well below that weight (the paper's oedometer uses 1e-4 N, 6 % of the weight of its "
                  "6-7 mm seeds), or check the units: densities in kg/m^3, lengths in metres");
}

// A relative path in the config file is relative to the file's folder; one given with
// --set is relative to the working directory.
std::string resolve_input_path(const ConfigReader& reader, const std::string& full_key, const std::string& value) {
  std::filesystem::path file(value);
  if (file.is_relative() && reader.origin_of(full_key).rfind("--set", 0) != 0)
    file = std::filesystem::path(reader.source_name()).parent_path() / file;
  return file.string();
}

Wall read_scene_wall(const ConfigNode& t) {
  const std::string shape = t.choice("shape", "plane", {"plane", "cylinder", "rectangle"});
  const std::string name = t.string("name", shape);
  Wall w;
  if (shape == "plane") {
    const Vec3 n = t.vec3("normal", Vec3::UnitZ());
    if (n.norm() == 0.0) t.fail("normal", "must not be zero");
    w = Wall::plane(name, t.vec3("point", Vec3::Zero()), n);
  } else if (shape == "cylinder") {
    const Vec3 axis = t.vec3("axis", Vec3::UnitZ());
    if (axis.norm() == 0.0) t.fail("axis", "must not be zero");
    const double lo = t.number("axial_min", -1e300), hi = t.number("axial_max", 1e300);
    if (lo >= hi) t.fail("axial_min", "must be below axial_max");
    w = Wall::cylinder(name, t.vec3("point", Vec3::Zero()), axis, t.positive("radius", 0.0), lo, hi);
  } else {
    const Vec3 n = t.vec3("normal", Vec3::UnitZ());
    const Vec3 u = t.vec3("axis_u", Vec3::UnitX());
    if (n.norm() == 0.0) t.fail("normal", "must not be zero");
    if (n.normalized().cross(u).norm() < 1e-9) t.fail("axis_u", "must not be parallel to the normal");
    w = Wall::rectangle(name, t.vec3("center", Vec3::Zero()), n, u, t.positive("half_u", 0.0),
                        t.positive("half_v", 0.0));
  }
  w.velocity = t.vec3("velocity", Vec3::Zero());
  return w;
}

// A settled packing named by `key`: its path resolved against the config file's folder, and
// the file checked before the run starts (missing, malformed, outside its container as
// `in_container` tells, or not settled: a ConfigError naming the file and the key). The
// scenario reads the spheres again when it starts (scenario/oedometer.cpp, shear_box.cpp).
template <class InContainer>
std::string checked_packing_file(const ConfigReader& reader, const std::string& key, const std::string& file,
                                 InContainer&& in_container) {
  const std::string path = resolve_input_path(reader, key, file);
  const std::vector<PackedSphere> spheres = read_packing(path, key);
  in_container(spheres, path, key);
  check_packing_overlaps(spheres, path, key);
  return path;
}

// Two spheres of a scene at one centre have no contact normal (the law divides by their
// distance): refused, naming both: [[particles]] entries by index, the packing file's spheres
// (the last packing_lines.size() particles) by their line in `packing_path`. Sorted by
// position, O(n log n).
void refuse_shared_centres(const ConfigNode& t, const std::vector<SceneParticle>& particles,
                           const std::vector<int>& packing_lines, const std::string& packing_path) {
  std::vector<std::size_t> order(particles.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto key = [&](std::size_t i) {
    const Vec3& x = particles[i].position;
    return std::array<double, 4>{x[0], x[1], x[2], static_cast<double>(i)};
  };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  const std::size_t first_from_packing = particles.size() - packing_lines.size();
  const auto name = [&](std::size_t n) {
    return n < first_from_packing ? "particles[" + std::to_string(n) + "]"
                                  : "line " + std::to_string(packing_lines[n - first_from_packing]) + " of " +
                                        packing_path;
  };
  for (std::size_t k = 1; k < order.size(); ++k) {
    const std::size_t i = order[k - 1], j = order[k];
    if (particles[i].position != particles[j].position) continue;
    t.fail(j < first_from_packing ? "particles" : "packing_file",
           name(i) + " and " + name(j) + " have the same centre: their contact has no normal");
  }
}

SceneSpec read_scene(const ConfigNode& t, const ConfigReader& reader) {
  SceneSpec s;
  s.steps = t.integer("steps", 0, 1);
  t.require("steps", "number of steps to run");
  s.stop_unbalanced_force = t.non_negative("stop_unbalanced_force", 0.0);
  s.record_interval = t.integer("record_interval", 1, 1);
  s.record_particles = t.integer_list("record_particles");
  s.packing_file = t.string("packing_file", "");
  for (const ConfigNode& p : t.table_array("particles")) {
    SceneParticle sp;
    sp.position = p.vec3("position", Vec3::Zero());
    p.require("radius", "the sphere's radius, m");
    sp.radius = p.positive("radius", 0.0);
    sp.velocity = p.vec3("velocity", Vec3::Zero());
    sp.angular_velocity = p.vec3("angular_velocity", Vec3::Zero());
    sp.fixed = p.boolean("fixed", false);
    s.particles.push_back(sp);
  }
  std::vector<int> packing_lines;  // of the spheres read from the packing file
  std::string packing_path;
  if (!s.packing_file.empty()) {
    const std::string key = t.path() + ".packing_file";
    packing_path = resolve_input_path(reader, key, s.packing_file);
    for (const PackedSphere& ps : read_packing(packing_path, key)) {
      packing_lines.push_back(ps.line);
      SceneParticle sp;
      sp.position = ps.position;
      sp.radius = ps.radius;
      s.particles.push_back(sp);
    }
  }
  refuse_shared_centres(t, s.particles, packing_lines, packing_path);
  for (const ConfigNode& w : t.table_array("walls")) s.walls.push_back(read_scene_wall(w));
  for (std::int64_t i : s.record_particles)
    if (i < 0 || i >= static_cast<std::int64_t>(s.particles.size()))
      t.fail("record_particles", "index " + std::to_string(i) + " is not a particle of the scene (" +
                                     std::to_string(s.particles.size()) + " particles)");
  return s;
}

// [output]. A key left out takes the scenario's default without being recorded in the
// resolved config (OutputSpec): the run's fingerprint stays that of its physics.
OutputSpec read_output(const ConfigNode& t, Scenario scenario) {
  OutputSpec o;
  o.snapshot_interval = t.has("snapshot_interval") ? t.non_negative("snapshot_interval", 0.0)
                                                   : default_snapshot_interval(scenario);
  if (t.has("plots")) o.plots = t.boolean("plots", true);
  return o;
}

}  // namespace

RunConfig read_run_config(Scenario scenario, const ConfigReader& reader) {
  const ConfigNode root = reader.root();
  RunConfig c;
  c.source = reader.source_name();
  const std::string declared = root.string("scenario", to_string(scenario));
  if (declared != to_string(scenario))
    root.fail("scenario", std::string("this file is for scenario \"") + declared + "\", not \"" + to_string(scenario) + "\"");
  root.string("title", "");
  root.string("provenance", "");
  c.seed = static_cast<std::uint64_t>(root.integer("seed", 1, 0));
  c.particle = read_particle(root.table("particle"));
  c.wall = read_wall(root.table("wall"));
  const ConfigNode contact = root.table("contact");
  c.stiffness_rule = contact.choice("stiffness_rule", "series", {"series", "contact"}) == "series"
                         ? StiffnessRule::kSeries : StiffnessRule::kContact;
  c.wall_friction = contact.choice("wall_friction", "own", {"own", "min"}) == "own" ? WallFrictionRule::kOwn
                                                                                    : WallFrictionRule::kMinimum;
  c.contact = read_contact_model(contact);
  require_hertz_moduli(root, c);
  c.integration = read_integration(root.table("integration"));
  // Bonds join the candidate pairs within bond_gap, and only pairs closer than the Verlet skin
  // are candidates (scenario/bonds.hpp install_bonds).
  if (installs_bonds_at_a_moment(c.contact.bond_install) && c.contact.bond_gap >= c.integration.verlet_skin) {
    // Both values in the message: either may come from the file or from --set. 15 digits,
    // so that a gap a hair above the skin does not print as the same number.
    std::ostringstream why;
    why.precision(15);
    why << c.contact.bond_gap << " m must be below integration.verlet_skin = " << c.integration.verlet_skin
        << " m: bonds are put on candidate pairs, and only pairs closer than the skin are sure to be candidates";
    contact.fail("bond_gap", why.str());
  }
  if (scenario == Scenario::kOedometer) {
    c.sample = read_sample(root.table("sample"), scenario);
    c.oedometer = read_oedometer(root.table("oedometer"), c.particle);
    if (!c.oedometer.packing_file.empty())
      c.oedometer.packing_file = checked_packing_file(
          reader, "oedometer.packing_file", c.oedometer.packing_file,
          [&](const std::vector<PackedSphere>& spheres, const std::string& path, const std::string& key) {
            check_packing_in_cylinder(spheres, 0.5 * c.oedometer.cylinder_diameter, path, key);
          });
  } else if (scenario == Scenario::kShear) {
    c.sample = read_sample(root.table("sample"), scenario);
    c.shear_box = read_shear_box(root.table("shear_box"), c.particle);
    if (!c.shear_box.packing_file.empty())
      c.shear_box.packing_file = checked_packing_file(
          reader, "shear_box.packing_file", c.shear_box.packing_file,
          [&](const std::vector<PackedSphere>& spheres, const std::string& path, const std::string& key) {
            check_packing_in_box(spheres, c.shear_box.length, c.shear_box.width, path, key);
          });
  } else if (scenario == Scenario::kRepose) {
    c.sample = read_sample(root.table("sample"), scenario);
    c.repose = read_repose(root.table("repose"), c.particle.diameter_max, c.wall.friction);
  } else {
    c.scene = read_scene(root.table("scene"), reader);
    if (c.integration.automatic_time_step && !root.table("integration").has("time_step"))
      root.table("integration").fail("time_step", "a scene needs a fixed time step (s) or \"auto\" stated explicitly");
  }
  c.output = read_output(root.table("output"), scenario);
  reader.reject_unknown_keys();
  const bool settles = (scenario == Scenario::kOedometer && c.oedometer.packing_file.empty()) ||
                       (scenario == Scenario::kShear && c.shear_box.packing_file.empty()) ||
                       scenario == Scenario::kRepose;
  if (settles) {
    require_a_criterion_below_the_weight(c, root.table("sample"));
    require_a_sample_deep_enough(c, scenario, root);
  }
  c.resolved_toml = reader.resolved_text();
  return c;
}

RunConfig load_run_config(Scenario scenario, const std::string& config_path,
                          const std::vector<std::string>& overrides) {
  ConfigReader reader = config_path.empty() ? ConfigReader::empty() : ConfigReader::from_file(config_path);
  for (const auto& o : overrides) reader.apply_override(o);
  RunConfig c = read_run_config(scenario, reader);
  c.overrides = overrides;
  return c;
}

PhysicsSettings make_physics(const RunConfig& c) {
  PhysicsSettings ph;
  ph.particle_materials.push_back({"seed", c.particle.density, c.particle.normal_stiffness,
                                   c.particle.shear_stiffness, c.particle.friction, c.particle.young_modulus,
                                   c.particle.poisson_ratio});
  ph.wall_materials.push_back({"wall", c.wall.normal_stiffness, c.wall.shear_stiffness, c.wall.friction,
                               c.wall.young_modulus, c.wall.poisson_ratio});
  ph.stiffness_rule = c.stiffness_rule;
  ph.wall_friction = c.wall_friction;
  ph.model = c.contact;
  ph.integrator.damping = c.integration.damping;
  ph.integrator.damping_form = c.integration.damping_form;
  ph.integrator.gravity = c.integration.gravity;
  ph.time_step.automatic = c.integration.automatic_time_step;
  ph.time_step.fixed_dt = c.integration.time_step;
  ph.time_step.safety_factor = c.integration.safety_factor;
  ph.time_step.recompute_interval = static_cast<std::uint64_t>(c.integration.recompute_interval);
  ph.skin = c.integration.verlet_skin;
  return ph;
}

}  // namespace colza
