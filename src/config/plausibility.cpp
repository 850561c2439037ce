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
constexpr double kMaxFriction = 1.5;            // mu (-): atan 1.5 = 56 deg; seeds 0.2..0.6, the paper 0.20..0.34
constexpr double kMinDiameter = 0.5e-3;         // m
constexpr double kMaxDiameter = 30e-3;          // m
constexpr double kMinDensity = 500.0;           // kg/m^3; seeds' own density ~900..1300, the paper 1230..1250
constexpr double kMaxDensity = 2000.0;          // kg/m^3
constexpr double kMinNormalStress = 100.0;      // Pa; the paper's shear box 25.75..78.75 kPa
constexpr double kMaxNormalStress = 10e6;       // Pa; its oedometer reaches 3.8 MPa
constexpr double kMaxSpeed = 0.5;               // m/s; the paper's 500 mm/min = 0.0083 m/s, 300 mm/min = 0.005 m/s
constexpr double kMinGravity = 9.7;             // m/s^2; Earth's surface 9.78..9.83
constexpr double kMaxGravity = 9.9;
constexpr double kMaxMeanOverlapShare = 0.25;   // of the mean diameter, see mean_overlap_share

// "FILE: key 'K': " as ConfigError starts, so a warning reads like the error it may become.
std::string at(const RunConfig& c, const std::string& key) { return c.origin_of(key) + ": key '" + key + "': "; }

std::string degrees_of(double mu) { return format_significant(std::atan(mu) * 180.0 / M_PI, 3) + " deg"; }

void check_friction(const RunConfig& c, const std::string& key, double mu, std::vector<std::string>& w) {
  if (mu <= kMaxFriction) return;
  w.push_back(at(c, key) + format_shortest(mu) + " is a friction coefficient mu = tan(phi), here phi = " +
              degrees_of(mu) + "; seeds have 0.2..0.6 (the paper 0.20..0.34). Was an angle in degrees meant? (" +
              format_shortest(mu) + " deg is mu = " + format_significant(std::tan(mu * M_PI / 180.0), 3) + ")");
}

void check_diameter(const RunConfig& c, const std::string& key, double d, std::vector<std::string>& w) {
  if (d >= kMinDiameter && d <= kMaxDiameter) return;
  w.push_back(at(c, key) + format_shortest(d) + " m is outside the " + format_shortest(kMinDiameter * 1e3) + ".." +
              format_shortest(kMaxDiameter * 1e3) + " mm of seeds: lengths are in metres (the paper's 6 mm is 0.006)");
}

void check_speed(const RunConfig& c, const std::string& key, double v, std::vector<std::string>& w) {
  if (v <= kMaxSpeed) return;
  w.push_back(at(c, key) + format_shortest(v) + " m/s is faster than " + format_shortest(kMaxSpeed) +
              " m/s: the test is no longer quasi-static. Speeds are in m/s (the paper's 500 mm/min is 0.00833)");
}

// The mean contact's overlap as a share of the mean diameter d under a stress sigma, for a
// packing of solid fraction phi and coordination number Z: the mean stress of the contact
// forces, p = phi Z <F> / (pi d^2) (Cauchy's formula with branch length d, equal spheres),
// gives <F> = pi d^2 p / (phi Z); with phi = 0.6, Z = 6 and p <= sigma (the vertical stress
// bounds the mean), un / d <= 0.87 sigma d / Kn. The paper's oedometer at 30 kN (3.82 MPa,
// d = 6.5 mm, Kn = 218.5 kN/m) gives 0.099; its shear box at 78.75 kPa 0.0023. A spring
// given in kN/m for N/m gives a thousand times that.
double mean_overlap_share(double sigma, double d, double kn) {
  constexpr double kSolidFraction = 0.6, kCoordination = 6.0;
  return M_PI / (kSolidFraction * kCoordination) * sigma * d / kn;
}

void check_spring(const RunConfig& c, double sigma, const std::string& stress_named, std::vector<std::string>& w) {
  const double d = 0.5 * (c.particle.diameter_min + c.particle.diameter_max);
  const double kn = combine_stiffness(c.particle.normal_stiffness, c.particle.normal_stiffness, c.stiffness_rule);
  const double share = mean_overlap_share(sigma, d, kn);
  if (!(share > kMaxMeanOverlapShare)) return;
  w.push_back(at(c, "particle.normal_stiffness") + format_shortest(c.particle.normal_stiffness) +
              " N/m gives a contact stiffness of " + format_significant(kn, 4) + " N/m, so soft that at " +
              stress_named + " the mean contact would overlap ~" + format_shortest(std::round(100.0 * share)) +
              " % of a diameter (0.87 sigma d / Kn): the linear spring is meant for overlaps of a few per cent. "
              "Stiffnesses are in N/m (the paper's 437 kN/m is 437e3)");
}

void check_gravity(const RunConfig& c, std::vector<std::string>& w) {
  const Vec3& g = c.integration.gravity;
  const bool down = g.x() == 0.0 && g.y() == 0.0 && -g.z() >= kMinGravity && -g.z() <= kMaxGravity;
  if (down) return;
  w.push_back(at(c, "integration.gravity") + "[" + format_shortest(g.x()) + ", " + format_shortest(g.y()) + ", " +
              format_shortest(g.z()) + "] m/s^2: the sample settles and is loaded along -z under Earth's gravity, "
              "[0, 0, -9.81]");
}

}  // namespace

std::vector<std::string> implausible_settings(const RunConfig& c, Scenario scenario,
                                              const std::vector<double>& normal_stresses,
                                              const std::string& stress_origin) {
  std::vector<std::string> w;
  if (scenario == Scenario::kScene) return w;
  check_friction(c, "particle.friction", c.particle.friction, w);
  check_friction(c, "wall.friction", c.wall.friction, w);
  check_diameter(c, "particle.diameter_min", c.particle.diameter_min, w);
  if (c.particle.diameter_max != c.particle.diameter_min)
    check_diameter(c, "particle.diameter_max", c.particle.diameter_max, w);
  if (c.particle.density < kMinDensity || c.particle.density > kMaxDensity)
    w.push_back(at(c, "particle.density") + format_shortest(c.particle.density) + " kg/m^3 is outside the " +
                format_shortest(kMinDensity) + ".." + format_shortest(kMaxDensity) +
                " kg/m^3 of seeds: densities are in kg/m^3 (1.25 g/cm^3 is 1250). A deliberate mass scaling "
                "is fine if the test stays quasi-static");
  check_gravity(c, w);
  if (scenario == Scenario::kOedometer) {
    check_speed(c, "oedometer.piston_speed", c.oedometer.piston_speed, w);
    const double area = M_PI / 4.0 * c.oedometer.cylinder_diameter * c.oedometer.cylinder_diameter;
    const double sigma = c.oedometer.stop_force / area;
    check_spring(c, sigma, "oedometer.stop_force's " + format_significant(sigma * 1e-6, 3) + " MPa", w);
    return w;
  }
  check_speed(c, "shear_box.shear_speed", c.shear_box.shear_speed, w);
  for (double sigma : normal_stresses)
    if (sigma < kMinNormalStress || sigma > kMaxNormalStress)
      w.push_back(stress_origin + ": normal stress " + format_shortest(sigma) + " Pa is outside " +
                  format_shortest(kMinNormalStress) + " Pa .. " + format_shortest(kMaxNormalStress * 1e-6) +
                  " MPa: stresses are in Pa (the paper's 25.75 kPa is 25750)");
  if (!normal_stresses.empty()) {
    const double sigma = *std::max_element(normal_stresses.begin(), normal_stresses.end());
    check_spring(c, sigma, "the normal stress " + format_shortest(sigma) + " Pa", w);
  }
  return w;
}

}  // namespace colza
