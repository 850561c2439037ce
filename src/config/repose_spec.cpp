#include "config/repose_spec.hpp"

#include "io/format_number.hpp"

namespace colza {

namespace {
// A column narrower than this many of its largest spheres arches against the wall instead of
// flowing out as the cylinder rises (a hopper's outlet needs ~5-6 diameters to flow).
constexpr double kMinCylinderDiameters = 5.0;
// The glued disc's default diameter, in cylinder diameters: a heap of the column's volume at
// 15 deg spreads to ~3 cylinder diameters (cone volume pi R^3 tan(alpha) / 3 = column volume).
constexpr double kGluedLayerCylinderDiameters = 3.5;
}  // namespace

ReposeSpec read_repose(const ConfigNode& t, double particle_diameter_max, double wall_friction) {
  ReposeSpec r;
  r.cylinder_diameter = t.positive("cylinder_diameter", r.cylinder_diameter);
  r.fill_height = t.positive("fill_height", r.fill_height);
  r.generation_height = t.positive("generation_height", r.generation_height);
  const char* plate = repose_base_name(ReposeBase::kPlate);
  r.base = t.choice("base", plate, {plate, repose_base_name(ReposeBase::kGluedLayer)}) == plate ? ReposeBase::kPlate
                                                                                               : ReposeBase::kGluedLayer;
  r.glued_layer_diameter = t.positive("glued_layer_diameter", kGluedLayerCylinderDiameters * r.cylinder_diameter);
  r.lift_speed = t.positive("lift_speed", r.lift_speed);
  r.base_friction = t.non_negative("base_friction", wall_friction);
  r.rest_unbalanced_force = t.positive("rest_unbalanced_force", r.rest_unbalanced_force);
  r.rest_max_time = t.positive("rest_max_time", r.rest_max_time);
  r.sectors = t.integer("sectors", r.sectors, 1);
  r.fit_inner = t.number_in("fit_inner", r.fit_inner, 0.0, 1.0);
  r.fit_outer = t.number_in("fit_outer", r.fit_outer, 0.0, 1.0);
  const auto m = [](double v) { return format_shortest(v) + " m"; };
  if (r.cylinder_diameter < kMinCylinderDiameters * particle_diameter_max)
    t.fail("cylinder_diameter", m(r.cylinder_diameter) + " is narrower than " + format_shortest(kMinCylinderDiameters) +
                                    " particle diameters (particle.diameter_max " + m(particle_diameter_max) +
                                    "): the column would arch against the wall instead of flowing out "
                                    "(lengths are in metres)");
  if (r.generation_height < r.fill_height)
    t.fail("generation_height", m(r.generation_height) + " must be at least repose.fill_height, " + m(r.fill_height));
  if (r.glued_layer_diameter <= r.cylinder_diameter + 2.0 * particle_diameter_max)
    t.fail("glued_layer_diameter", m(r.glued_layer_diameter) + " must exceed repose.cylinder_diameter (" +
                                       m(r.cylinder_diameter) + ") by more than two particle diameters: the heap "
                                       "spreads beyond the cylinder");
  if (!(r.fit_inner < r.fit_outer)) t.fail("fit_inner", "must be below repose.fit_outer");
  return r;
}

}  // namespace colza
