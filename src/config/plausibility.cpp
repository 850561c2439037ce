#include "config/plausibility.hpp"

#include <algorithm>
#include <cmath>

#include "core/materials.hpp"
#include "io/format_number.hpp"

namespace colza {

namespace {

// The bands are wide: they take every oilseed and the scaled-up seeds DEM models use (rape
// ~2 mm, soybean ~7 mm, sunflower ~10 mm long; the paper's model 6-7 mm), so a value outside
// is far more likely a unit slip than a seed.
constexpr double kMaxFriction = 1.5;            // mu (-): atan 1.5 = 56 deg; seeds 0.2..0.6
constexpr double kMinDiameter = 0.5e-3;         // m
constexpr double kMaxDiameter = 30e-3;          // m
constexpr double kMinDensity = 500.0;           // kg/m^3; seeds' own density ~900..1300, the paper 1230..1250
constexpr double kMaxDensity = 2000.0;          // kg/m^3
constexpr double kMaxNormalStress = 10e6;       // Pa; its oedometer reaches 3.8 MPa
constexpr double kMinStopStress = 10e3;         // Pa: the oedometer's stop force over the piston; the
constexpr double kMaxStopStress = 100e6;        //   paper's 30 kN is 3.8 MPa, the density stage's 200 N 25 kPa
// m/s. The paper's 500 mm/min = 0.0083 m/s and 300 mm/min = 0.005 m/s; the tests' small
// samples run at 0.05 m/s. A speed in m/min (0.5, 0.3) is above it; a faster test is no
// longer quasi-static (0.3 m/s moved the small box's strength by 26 %, session 27's review).
constexpr double kMaxSpeed = 0.1;
constexpr double kMinGravity = 9.7;             // m/s^2; Earth's surface 9.78..9.83
constexpr double kMaxGravity = 9.9;
constexpr double kMaxMeanOverlapShare = 0.25;   // of the mean diameter, see mean_overlap_share
// ks / kn of an entity: the paper's 0.23 (particles, Table 1), 0.26 (Table 2), 0.25 (walls);
// elastic spheres (Mindlin) 2 (1 - nu) / (2 - nu) = 0.67..1 for nu = 0..0.5.
constexpr double kMinShearToNormal = 0.05;
constexpr double kMaxShearToNormal = 1.5;
// Wall kn over particle kn: the paper's walls are 9.2 (Table 1) and 10.4 (Table 2) times
// stiffer; walls ten times softer than the seeds are a wall stiffness in kN/m.
constexpr double kMinWallToParticle = 0.1;

// Least output.snapshot_interval (s) that keeps a test's snapshots to a few thousand: the
// paper's tests last 2.4 s (oedometer loading) to ~7 s (a shear load), and a snapshot holds
// ~125 bytes a sphere (io/snapshot.hpp: 14 four-byte values, and 29 bytes for each of its
// ~2.4 contacts in the paper's oedometer), all kept in memory until the result is written.
// Below it, likely milliseconds taken for seconds.
constexpr double kMinSnapshotInterval = 1e-3;

using Found = std::vector<ImplausibleSetting>;

void add(Found& w, const RunConfig& c, const std::string& key, const std::string& reason) {
  w.push_back({c.origin_of(key), key, reason});
}

std::string degrees_of(double mu) { return format_significant(std::atan(mu) * 180.0 / M_PI, 3) + " deg"; }

// `paper`: the paper's values of this coefficient.
void check_friction(const RunConfig& c, const std::string& key, double mu, const std::string& paper, Found& w) {
  if (mu <= kMaxFriction) return;
  std::string reason = format_shortest(mu) + " is a friction coefficient mu = tan(phi), here phi = " + degrees_of(mu) +
                       "; seeds have 0.2..0.6 (the paper " + paper + ")";
  if (mu >= 5.0 && mu <= 60.0)  // a plausible angle of friction in degrees
    reason += ". Was an angle in degrees meant? (" + format_shortest(mu) + " deg is mu = " +
              format_significant(std::tan(mu * M_PI / 180.0), 3) + ")";
  add(w, c, key, reason);
}

void check_diameter(const RunConfig& c, const std::string& key, double d, Found& w) {
  if (d >= kMinDiameter && d <= kMaxDiameter) return;
  add(w, c, key, format_shortest(d) + " m is outside the " + format_shortest(kMinDiameter * 1e3) + ".." +
              format_shortest(kMaxDiameter * 1e3) + " mm of seeds: lengths are in metres (the paper's 6 mm is 0.006)");
}

// `paper`: the paper's speed for this test, in mm/min and m/s.
void check_speed(const RunConfig& c, const std::string& key, double v, const std::string& paper, Found& w) {
  if (v <= kMaxSpeed) return;
  add(w, c, key, format_shortest(v) + " m/s is faster than " + format_shortest(kMaxSpeed) +
              " m/s, too fast for a quasi-static test: speeds are in m/s (the paper's " + paper + ")");
}

// An entity's ks / kn (`what`: "particle" or "wall").
void check_stiffness_ratio(const RunConfig& c, const std::string& what, double kn, double ks, Found& w) {
  const double ratio = ks / kn;
  if (ratio >= kMinShearToNormal && ratio <= kMaxShearToNormal) return;
  add(w, c, what + ".shear_stiffness",
      format_shortest(ks) + " N/m is " + format_significant(ratio, 3) + " times " + what + ".normal_stiffness " +
          format_shortest(kn) + " N/m, outside " + format_shortest(kMinShearToNormal) + ".." +
          format_shortest(kMaxShearToNormal) + " (the paper 0.23..0.26; elastic spheres 0.67..1): stiffnesses are "
          "in N/m (the paper's 100 kN/m is 100e3)");
}

// The mean contact's overlap as a share of the mean diameter d under a stress sigma, for a
// packing of solid fraction phi and coordination number Z. The mean stress of the contact
// forces (Love-Weber, equal spheres, branch length d), p = phi Z <F> / (pi d^2), gives
// <F> = pi d^2 p / (phi Z), so un / d = pi / (phi Z) p d / Kn. With phi = 0.6, Z = 6 and p =
// sigma: 0.87 sigma d / Kn. An estimate, good to a factor ~1.5: the paper's bulk is looser
// (651 / 1230 = 0.53, Z ~ 5: 1.19 in place of 0.87), the oedometer's mean stress is below its
// vertical stress and the shear box's at failure ~1.3 sigma_n above. The paper's oedometer at
// 30 kN (3.82 MPa, d = 6.5 mm, Kn = 218.5 kN/m) gives 0.099 (0.13 with 1.19), its shear box
// at 78.75 kPa 0.0023. The limit, 0.25, is for slips by orders of magnitude: a spring in
// kN/m for N/m gives a thousand times the share.
double mean_overlap_share(double sigma, double d, double kn) {
  constexpr double kSolidFraction = 0.6, kCoordination = 6.0;
  return M_PI / (kSolidFraction * kCoordination) * sigma * d / kn;
}

void check_spring(const RunConfig& c, double sigma, const std::string& stress_named, Found& w) {
  const double d = 0.5 * (c.particle.diameter_min + c.particle.diameter_max);
  const double kn = combine_stiffness(c.particle.normal_stiffness, c.particle.normal_stiffness, c.stiffness_rule);
  const double share = mean_overlap_share(sigma, d, kn);
  if (!(share > kMaxMeanOverlapShare)) return;
  add(w, c, "particle.normal_stiffness", format_shortest(c.particle.normal_stiffness) +
              " N/m gives a contact stiffness of " + format_significant(kn, 4) + " N/m, so soft that at " +
              stress_named + " the mean contact would overlap ~" + format_shortest(std::round(100.0 * share)) +
              " % of a diameter (0.87 sigma d / Kn), where the paper's oedometer reaches ~10 % at 30 kN: "
              "stiffnesses are in N/m (the paper's 437 kN/m is 437e3)");
}

void check_gravity(const RunConfig& c, Found& w) {
  const Vec3& g = c.integration.gravity;
  const bool down = g.x() == 0.0 && g.y() == 0.0 && -g.z() >= kMinGravity && -g.z() <= kMaxGravity;
  if (down) return;
  std::string vector = "[";  // built in steps: gcc 12 warns falsely (-Wrestrict) of "[" + std::string
  vector += format_shortest(g.x()) + ", " + format_shortest(g.y()) + ", " + format_shortest(g.z()) + "]";
  add(w, c, "integration.gravity",
      vector + " m/s^2: the sample settles and is loaded along -z under Earth's gravity, [0, 0, -9.81]");
}

}  // namespace

std::vector<ImplausibleSetting> implausible_settings(const RunConfig& c, Scenario scenario,
                                                     const std::vector<double>& normal_stresses,
                                                     const std::string& stress_origin) {
  Found w;
  if (scenario == Scenario::kScene) return w;
  check_friction(c, "particle.friction", c.particle.friction, "0.2..0.5", w);
  check_friction(c, "wall.friction", c.wall.friction, "0.23", w);
  check_stiffness_ratio(c, "particle", c.particle.normal_stiffness, c.particle.shear_stiffness, w);
  check_stiffness_ratio(c, "wall", c.wall.normal_stiffness, c.wall.shear_stiffness, w);
  if (c.wall.normal_stiffness < kMinWallToParticle * c.particle.normal_stiffness)
    add(w, c, "wall.normal_stiffness",
        format_shortest(c.wall.normal_stiffness) + " N/m is " +
            format_significant(c.wall.normal_stiffness / c.particle.normal_stiffness, 3) + " times particle.normal_stiffness " +
            format_shortest(c.particle.normal_stiffness) + " N/m; the paper's walls are 9-10 times stiffer than its "
            "seeds: stiffnesses are in N/m (the paper's 4000 kN/m is 4000e3)");
  check_diameter(c, "particle.diameter_min", c.particle.diameter_min, w);
  if (c.particle.diameter_max != c.particle.diameter_min)
    check_diameter(c, "particle.diameter_max", c.particle.diameter_max, w);
  if (c.particle.density < kMinDensity || c.particle.density > kMaxDensity)
    add(w, c, "particle.density", format_shortest(c.particle.density) + " kg/m^3 is outside the " +
                format_shortest(kMinDensity) + ".." + format_shortest(kMaxDensity) +
                " kg/m^3 of seeds: densities are in kg/m^3 (1.25 g/cm^3 is 1250). A deliberate mass scaling "
                "is fine if the test stays quasi-static");
  check_gravity(c, w);
  if (c.output.snapshot_interval > 0.0 && c.output.snapshot_interval < kMinSnapshotInterval)
    add(w, c, "output.snapshot_interval",
        format_shortest(c.output.snapshot_interval) + " s gives more than " +
            format_shortest(1.0 / kMinSnapshotInterval) + " snapshots per simulated second, each held in memory "
            "until the run ends (~125 bytes a sphere): intervals are in seconds of simulated time (the default is " +
            format_shortest(default_snapshot_interval(scenario)) + " s)");
  if (scenario == Scenario::kRepose) {
    check_speed(c, "repose.lift_speed", c.repose.lift_speed, "5 mm/s is 0.005", w);
    return w;
  }
  if (scenario == Scenario::kOedometer) {
    check_speed(c, "oedometer.piston_speed", c.oedometer.piston_speed, "500 mm/min is 0.00833", w);
    const double area = M_PI / 4.0 * c.oedometer.cylinder_diameter * c.oedometer.cylinder_diameter;
    const double sigma = c.oedometer.stop_force / area;
    if (sigma < kMinStopStress || sigma > kMaxStopStress)
      add(w, c, "oedometer.stop_force",
          format_shortest(c.oedometer.stop_force) + " N is " + format_significant(sigma * 1e-3, 3) + " kPa on the piston, outside " +
              format_shortest(kMinStopStress * 1e-3) + " kPa .. " + format_shortest(kMaxStopStress * 1e-6) +
              " MPa: forces are in N (the paper's 30 kN is 30e3, 3.8 MPa)");
    check_spring(c, sigma, "oedometer.stop_force's " + format_significant(sigma * 1e-6, 3) + " MPa", w);
    return w;
  }
  check_speed(c, "shear_box.shear_speed", c.shear_box.shear_speed, "300 mm/min is 0.005", w);
  for (double sigma : normal_stresses)
    if (sigma < kLeastLabNormalStress || sigma > kMaxNormalStress)
      w.push_back({stress_origin, "",
                   "normal stress " + format_shortest(sigma) + " Pa is outside " + format_shortest(kLeastLabNormalStress) +
                       " Pa .. " + format_shortest(kMaxNormalStress * 1e-6) +
                       " MPa: stresses are in Pa (the paper's 25.75 kPa is 25750)"});
  if (!normal_stresses.empty()) {
    const double sigma = *std::max_element(normal_stresses.begin(), normal_stresses.end());
    check_spring(c, sigma, "the normal stress " + format_shortest(sigma) + " Pa", w);
  }
  return w;
}

}  // namespace colza
