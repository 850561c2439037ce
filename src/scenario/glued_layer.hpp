// A monolayer of spheres glued to a base plate (z = 0), as angle of repose tests roughen their
// base so that the heap's lowest spheres cannot roll away on a smooth plate (physics.md
// section 8). The layer's spheres are fixed particles (not integrated), each resting on the
// plate (centre at z = r), within a disc about the z axis. The repose test's walls do not
// touch them (Wall::meets_fixed_spheres), so the layer may lie across the cylinder.
//
// Placement, in two passes, each sphere resting on the plate and overlapping none glued (two
// spheres of radii r, r_k resting on the plate overlap when their centres' horizontal
// distance is below 2 sqrt(r r_k)):
//  1. random sequential addition of spheres of diameters uniform on [d_min, d_max]:
//     `random_attempts_per_sphere` x (disc area / mean sphere cross-section) draws of a
//     diameter, then x, then y (mt19937_64 from `seed` mixed with a stream constant, so the
//     layer's draws are not the sample's);
//  2. a fill: a sphere of radius r_fill tried at every node of a square lattice of spacing
//     s = r_min / 8, row by row. Any point of the disc lies within s / sqrt(2) of a node;
//     where the fill's sphere did not fit, a glued sphere k lies closer than
//     2 sqrt(r_fill r_k) + s / sqrt(2) to that point, which is at most 2 sqrt(r_min r_k) when
//     sqrt(r_k) (sqrt(r_min) - sqrt(r_fill)) >= s / (2 sqrt(2)) for every r_k >= r_fill:
//     r_fill = a^2 r_min with a (1 - a) = 1 / (16 sqrt(2)), a = 0.954, r_fill = 0.910 r_min.
//     So no sphere of the sample (radius >= r_min) reaches the plate inside the disc, a
//     diameter from its rim.
#pragma once
#include <cstdint>

#include "core/particles.hpp"

namespace colza {

struct GluedLayerRequest {
  double disc_radius = 0.0;           // m, sphere centres within it
  double diameter_min = 0.0, diameter_max = 0.0;  // m
  double density = 0.0;               // kg/m^3 (mass of fixed spheres: the time step's estimate)
  std::uint64_t seed = 1;
  double random_attempts_per_sphere = 20.0;
};

// The layer's spheres, all fixed. Throws std::invalid_argument on a non-positive radius,
// diameter or density, or d_min > d_max.
ParticleArrays glued_layer(const GluedLayerRequest& request);

}  // namespace colza
