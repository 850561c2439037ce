#include "config/sample_depth.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "io/format_number.hpp"

namespace colza {

namespace {

// A container wider than this many particle diameters is taken for a length in mm (the
// paper's 100 mm cylinder and 200 mm box are 14 and 29 of its 7 mm seeds).
constexpr double kWidestPlausible = 50.0;

// "100000 mm", "8.93 mm", "0.000106 mm": three significant digits, never in e-notation.
std::string mm(double metres) { return format_shortest(std::stod(format_significant(metres * 1e3, 3))) + " mm"; }

}  // namespace

double mean_sphere_volume(const ParticleSpec& particle) {
  const double dmin = particle.diameter_min, dmax = particle.diameter_max;
  const double mean_cube =
      dmax > dmin ? (std::pow(dmax, 4) - std::pow(dmin, 4)) / (4.0 * (dmax - dmin)) : dmin * dmin * dmin;
  return std::numbers::pi / 6.0 * mean_cube;
}

void require_a_sample_deep_enough(const RunConfig& c, Scenario scenario, const ConfigNode& root) {
  const double dmax = c.particle.diameter_max;
  const double solid = static_cast<double>(c.sample.count) * mean_sphere_volume(c.particle);  // m^3
  const std::string spheres = std::to_string(c.sample.count) + " spheres of " + format_shortest(c.particle.diameter_min) +
                              " .. " + format_shortest(dmax) + " m";
  if (scenario == Scenario::kOedometer && c.oedometer.packing_file.empty()) {
    const double d = c.oedometer.cylinder_diameter;
    const double deepest = solid / (kLoosestSettledFraction * std::numbers::pi / 4.0 * d * d);
    if (deepest >= 3.0 * dmax) return;
    const std::string why = spheres + " settle at most " + mm(deepest) + " deep in a cylinder of " + mm(d) +
                            " diameter (packing fraction " + format_shortest(kLoosestSettledFraction) +
                            "): fewer than three layers, no oedometer sample";
    if (d > kWidestPlausible * dmax)
      root.table("oedometer").fail("cylinder_diameter", format_shortest(d) + " m: " + why + " (lengths are in metres)");
    root.table("sample").fail("count", why + "; generate more spheres");
  }
  if (scenario == Scenario::kShear && c.shear_box.packing_file.empty()) {
    const ShearBoxSpec& b = c.shear_box;
    const double deepest = solid / (kLoosestSettledFraction * b.length * b.width);
    if (deepest >= b.shear_plane + dmax) return;
    const std::string why = spheres + " settle at most " + mm(deepest) + " deep in a box of " + mm(b.length) + " x " +
                            mm(b.width) + " (packing fraction " + format_shortest(kLoosestSettledFraction) +
                            "), not a layer above the shear plane at " + mm(b.shear_plane) +
                            ": the shear would not pass through the sample";
    if (std::max(b.length, b.width) > kWidestPlausible * dmax) {
      const bool length = b.length >= b.width;
      root.table("shear_box").fail(length ? "length" : "width", format_shortest(length ? b.length : b.width) + " m: " +
                                                                    why + " (lengths are in metres)");
    }
    root.table("sample").fail("count", why + "; generate more spheres");
  }
}

}  // namespace colza
