// Sphere state in structure-of-arrays form (physics.md section 1).
// Mass m = rho 4/3 pi R^3, inertia I = 2/5 m R^2 (solid sphere).
#pragma once
#include <vector>
#include "core/types.hpp"

namespace colza {

// ParticleArrays::fixed: a free sphere is integrated; a fixed one is not, its velocity is
// prescribed (kPrescribed) or zero for good (kAnchored: a base glued to a plate). Two anchored
// spheres never form a candidate pair (neighbour/neighbour_search.hpp): neither moves, so a
// force between them would do nothing.
inline constexpr std::uint8_t kFree = 0;
inline constexpr std::uint8_t kPrescribed = 1;
inline constexpr std::uint8_t kAnchored = 2;

struct ParticleArrays {
  // State, leapfrog convention: position at t, velocities at t - dt/2.
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;
  std::vector<Vec3> angular_velocity;
  // Accumulators for the current step: contact force and torque (no gravity, no damping).
  std::vector<Vec3> force;
  std::vector<Vec3> torque;
  // Constant properties.
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inertia;   // scalar moment of inertia (kg m^2)
  std::vector<std::uint16_t> material;  // index into the particle material table
  std::vector<std::uint8_t> fixed;      // kFree, kPrescribed or kAnchored (above)

  std::size_t size() const { return position.size(); }

  // Append one sphere; mass and inertia from density.
  Index add(const Vec3& x, double r, double density, std::uint16_t material_index = 0,
            const Vec3& v = Vec3::Zero(), const Vec3& w = Vec3::Zero());

  // Keep only the particles with keep[i] != 0, preserving order.
  // Returns the map old index -> new index (or kRemoved).
  std::vector<Index> compact(const std::vector<std::uint8_t>& keep);

  void clear_forces();
  // Reorder all arrays so that new index k holds old particle order[k].
  void permute(const std::vector<Index>& order);

  static constexpr Index kRemoved = 0xffffffffu;
};

double sphere_mass(double radius, double density);
double sphere_inertia(double mass, double radius);

}  // namespace colza
