#include "integrate/integrator.hpp"

#include <cmath>

namespace colza {

const char* to_string(DampingForm form) { return form == DampingForm::kPfc ? "pfc" : "yade"; }

namespace {

// Acceleration of one degree of freedom under local damping.
// `load` is the unbalanced generalised force (N or N m), `mobility` is 1/m or 1/I.
inline double damped_acceleration(double load, double velocity, double mobility, double alpha,
                                  DampingForm form, double dt) {
  if (form == DampingForm::kPfc) {
    const double damping_force = -alpha * std::abs(load) * sign_or_zero(velocity);
    return (load + damping_force) * mobility;
  }
  const double a = load * mobility;
  return a * (1.0 - alpha * sign_or_zero(a * (velocity + 0.5 * dt * a)));
}

}  // namespace

IntegrationReport integrate_step(ParticleArrays& p, const IntegratorSettings& s, double dt) {
  IntegrationReport report;
  const std::size_t n = p.size();
  std::size_t free_count = 0;
  double unbalanced_sum = 0.0, damping_work = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (p.fixed[i]) {
      p.position[i] += dt * p.velocity[i];
      continue;
    }
    const double m = p.mass[i];
    const double inv_m = 1.0 / m, inv_i = 1.0 / p.inertia[i];
    const Vec3 load = p.force[i] + m * s.gravity;
    const double unbalanced = load.norm();
    unbalanced_sum += unbalanced;
    report.max_unbalanced_force = std::max(report.max_unbalanced_force, unbalanced);
    ++free_count;
    Vec3& v = p.velocity[i];
    Vec3& w = p.angular_velocity[i];
    for (int d = 0; d < 3; ++d) {
      const double a = damped_acceleration(load[d], v[d], inv_m, s.damping, s.damping_form, dt);
      const double v_new = v[d] + dt * a;
      // Work of the damping force over the step, with the mean of the two mid-step velocities.
      damping_work -= (a - load[d] * inv_m) * m * 0.5 * (v[d] + v_new) * dt;
      v[d] = v_new;
      const double alpha_w = damped_acceleration(p.torque[i][d], w[d], inv_i, s.damping, s.damping_form, dt);
      const double w_new = w[d] + dt * alpha_w;
      damping_work -= (alpha_w - p.torque[i][d] * inv_i) * p.inertia[i] * 0.5 * (w[d] + w_new) * dt;
      w[d] = w_new;
    }
    p.position[i] += dt * v;
  }
  report.mean_unbalanced_force = free_count ? unbalanced_sum / free_count : 0.0;
  report.damping_work = damping_work;
  return report;
}

}  // namespace colza
