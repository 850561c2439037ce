// Leapfrog integration with local (non-viscous, Cundall) damping (physics.md section 3).
//   v(t + dt/2) = v(t - dt/2) + dt a(t),   x(t + dt) = x(t) + dt v(t + dt/2)
// and the same for rotation with the scalar inertia of a sphere.
#pragma once
#include <vector>
#include "core/particles.hpp"

namespace colza {

enum class DampingForm {
  kPfc,   // Fd_i = -alpha |F_i| sign(v_i), v the mid-step velocity v(t - dt/2) (PFC3D)
  kYade,  // a_i <- a_i (1 - alpha sign(a_i (v_i + dt/2 a_i)))  (YADE NewtonIntegrator)
};
const char* to_string(DampingForm form);

struct IntegratorSettings {
  double damping = 0.7;  // local damping coefficient alpha (-)
  DampingForm damping_form = DampingForm::kPfc;
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  // m/s^2
};

struct IntegrationReport {
  double mean_unbalanced_force = 0.0;  // mean over free particles of |F_contact + m g| (N)
  double max_unbalanced_force = 0.0;
  double damping_work = 0.0;  // energy removed by damping this step (J), >= 0
};

// Which sums over particles a step reports. Each is a serial chain over the particles
// (in particle order, for bits that do not depend on the thread count; the damping work is
// 6 additions per particle): switching both off took the integrator from 13.1 % to 7.6 % of
// a one-thread oedometer loading (perf), so stages that do not read them switch them off. A
// sum not computed is reported as NaN (so is the ledger's damping term from then on: a
// misuse shows). The motion does not depend on these flags.
struct IntegrationSums {
  bool unbalanced = true;    // mean and max unbalanced force (settling, scene stop condition)
  bool damping_work = true;  // energy ledger (scenes)
};

// Advances all free particles by one step using the forces and torques in `particles`.
// Fixed particles move with their prescribed velocity. Gravity is added here.
IntegrationReport integrate_step(ParticleArrays& particles, const IntegratorSettings& settings, double dt,
                                 IntegrationSums sums = {});

// Same with `threads` OpenMP threads over fixed contiguous particle ranges. Particle states
// and the mean/max unbalanced force are bit-for-bit those of the serial call; the damping
// work is summed per range and then in range order, so it is deterministic at a given
// thread count but may differ in the last bits from the serial sum. Small systems (fewer
// than 2 kMinParticlesPerThread particles) take the serial path.
inline constexpr std::size_t kMinParticlesPerThread = 512;
IntegrationReport integrate_step(ParticleArrays& particles, const IntegratorSettings& settings, double dt,
                                 int threads, std::vector<double>& unbalanced_scratch, IntegrationSums sums = {});

// Only the motion of particles [begin, end), no sums: the state update of integrate_step,
// the same bits for every particle whatever the range (the threaded force loop of
// engine/force_loops_body.hpp integrates each thread's particles as soon as their forces are
// final).
void integrate_motion(ParticleArrays& particles, const IntegratorSettings& settings, double dt, std::size_t begin,
                      std::size_t end);
// What a step whose motion was done by integrate_motion reports: no sum (all NaN), as
// integrate_step with both sums off.
IntegrationReport report_without_sums();

}  // namespace colza
