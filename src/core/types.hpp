// Basic numeric types shared by every stage of the solver.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <cstdint>

namespace colza {

using Vec3 = Eigen::Vector3d;   // SI units throughout: m, m/s, N, N m
using Index = std::uint32_t;    // particle / wall index

inline constexpr double kPi = 3.14159265358979323846;

// sign(x) with sign(0) = 0, as used by both local-damping forms (physics.md section 3).
// Written with selects on doubles (not bool arithmetic) so that loops calling it vectorise.
inline double sign_or_zero(double x) { return (x > 0.0 ? 1.0 : 0.0) - (x < 0.0 ? 1.0 : 0.0); }

}  // namespace colza
