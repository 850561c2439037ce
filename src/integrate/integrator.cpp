#include "integrate/integrator.hpp"

#include <algorithm>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace colza {

const char* to_string(DampingForm form) { return form == DampingForm::kPfc ? "pfc" : "yade"; }

namespace {

// Acceleration of one degree of freedom under local damping, resolved at compile time
// for the damping form (no branch on the form in the particle loop).
// `load` is the unbalanced generalised force (N or N m), `mobility` is 1/m or 1/I.
template <DampingForm kForm>
inline double damped_acceleration(double load, double velocity, double mobility, double alpha, double dt) {
  if constexpr (kForm == DampingForm::kPfc) {
    const double damping_force = -alpha * std::abs(load) * sign_or_zero(velocity);
    return (load + damping_force) * mobility;
  } else {
    const double a = load * mobility;
    return a * (1.0 - alpha * sign_or_zero(a * (velocity + 0.5 * dt * a)));
  }
}

struct RangeReport {
  std::size_t free_count = 0;
  double unbalanced_sum = 0.0, max_unbalanced = 0.0, damping_work = 0.0;
};

// Integrates particles [begin, end). The arithmetic and the order of the sums over the
// range are those of the original single loop, so one range over all particles gives the
// same bits. With `unbalanced_out`, |load| of particle i (0 for fixed ones) is stored there
// instead of being summed (the caller sums it in particle order).
template <DampingForm kForm>
void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin,
                     std::size_t end, RangeReport& r, double* unbalanced_out) {
  const double alpha = s.damping;
  const Vec3 g = s.gravity;
  double unbalanced_sum = 0.0, max_unbalanced = r.max_unbalanced, damping_work = 0.0;
  std::size_t free_count = 0;
  Vec3* position = p.position.data();
  Vec3* velocity = p.velocity.data();
  Vec3* spin = p.angular_velocity.data();
  const Vec3* force = p.force.data();
  const Vec3* torque = p.torque.data();
  const double* mass = p.mass.data();
  const double* inertia = p.inertia.data();
  const std::uint8_t* fixed = p.fixed.data();
  for (std::size_t i = begin; i < end; ++i) {
    if (fixed[i]) {
      position[i] += dt * velocity[i];
      if (unbalanced_out) unbalanced_out[i] = 0.0;
      continue;
    }
    const double m = mass[i], in = inertia[i];
    const double inv_m = 1.0 / m, inv_i = 1.0 / in;
    const Vec3 load = force[i] + m * g;
    const double unbalanced = load.norm();
    if (unbalanced_out) unbalanced_out[i] = unbalanced;
    else unbalanced_sum += unbalanced;
    max_unbalanced = std::max(max_unbalanced, unbalanced);
    ++free_count;
    Vec3& v = velocity[i];
    Vec3& w = spin[i];
    const Vec3& t = torque[i];
    for (int d = 0; d < 3; ++d) {
      const double a = damped_acceleration<kForm>(load[d], v[d], inv_m, alpha, dt);
      const double v_new = v[d] + dt * a;
      // Work of the damping force over the step, with the mean of the two mid-step velocities.
      damping_work -= (a - load[d] * inv_m) * m * 0.5 * (v[d] + v_new) * dt;
      v[d] = v_new;
      const double alpha_w = damped_acceleration<kForm>(t[d], w[d], inv_i, alpha, dt);
      const double w_new = w[d] + dt * alpha_w;
      damping_work -= (alpha_w - t[d] * inv_i) * in * 0.5 * (w[d] + w_new) * dt;
      w[d] = w_new;
    }
    position[i] += dt * v;
  }
  r.free_count += free_count;
  r.unbalanced_sum = unbalanced_sum;
  r.max_unbalanced = max_unbalanced;
  r.damping_work = damping_work;
}

void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin,
                     std::size_t end, RangeReport& r, double* unbalanced_out) {
  if (s.damping_form == DampingForm::kPfc)
    integrate_range<DampingForm::kPfc>(p, s, dt, begin, end, r, unbalanced_out);
  else
    integrate_range<DampingForm::kYade>(p, s, dt, begin, end, r, unbalanced_out);
}

}  // namespace

IntegrationReport integrate_step(ParticleArrays& p, const IntegratorSettings& s, double dt) {
  IntegrationReport report;
  RangeReport r;
  integrate_range(p, s, dt, 0, p.size(), r, nullptr);
  report.max_unbalanced_force = r.max_unbalanced;
  report.mean_unbalanced_force = r.free_count ? r.unbalanced_sum / r.free_count : 0.0;
  report.damping_work = r.damping_work;
  return report;
}

IntegrationReport integrate_step(ParticleArrays& p, const IntegratorSettings& s, double dt, int threads,
                                 std::vector<double>& unbalanced_scratch) {
  const std::size_t n = p.size();
  if (threads <= 1 || n < kMinParticlesPerThread * 2) return integrate_step(p, s, dt);
  unbalanced_scratch.resize(n);
  std::vector<RangeReport> parts(static_cast<std::size_t>(threads));
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
  {
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t nt = static_cast<std::size_t>(omp_get_num_threads());
    if (t < parts.size())
      integrate_range(p, s, dt, n * t / nt, n * (t + 1) / nt, parts[t], unbalanced_scratch.data());
  }
#else
  for (std::size_t t = 0; t < parts.size(); ++t)
    integrate_range(p, s, dt, n * t / parts.size(), n * (t + 1) / parts.size(), parts[t], unbalanced_scratch.data());
#endif
  IntegrationReport report;
  std::size_t free_count = 0;
  double damping_work = 0.0;
  for (const RangeReport& r : parts) {  // fixed order: deterministic at a given thread count
    free_count += r.free_count;
    report.max_unbalanced_force = std::max(report.max_unbalanced_force, r.max_unbalanced);
    damping_work += r.damping_work;
  }
  // The mean unbalanced force (settling criterion) is summed in particle order, as in the
  // serial loop, so it does not depend on the thread count (fixed particles add +0).
  double unbalanced_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) unbalanced_sum += unbalanced_scratch[i];
  report.mean_unbalanced_force = free_count ? unbalanced_sum / free_count : 0.0;
  report.damping_work = damping_work;
  return report;
}

}  // namespace colza
