// The integrator's particle ranges (integrate/integrate_range.hpp), compiled once per
// instruction set: included only by integrate/isa/integrate_range_<isa>.cpp, which names the
// copy's namespace (COLZA_KERNEL_NAMESPACE) and is compiled with that instruction set's options
// (src/CMakeLists.txt). Everything but the entry point has internal linkage; the wider copies
// are compiled with -fno-weak, as the force loops are (engine/force_loops_body.hpp explains).
#ifndef COLZA_KERNEL_NAMESPACE
#error "integrate/integrate_range_body.hpp is compiled by integrate/isa/integrate_range_<isa>.cpp only"
#endif

#include <algorithm>
#include <cmath>

#include "integrate/integrate_range.hpp"

namespace colza::COLZA_KERNEL_NAMESPACE {

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

// The particle state as plain arrays: a Vec3 array is three contiguous doubles per particle
// (x y z), so position[3 i + d] is component d of particle i.
struct FlatState {
  double *position, *velocity, *spin;
  const double *force, *torque, *mass, *inertia;
  const std::uint8_t* fixed;
};
inline FlatState flat_state(ParticleArrays& p) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  return {p.position.data()->data(), p.velocity.data()->data(), p.angular_velocity.data()->data(),
          p.force.data()->data(),    p.torque.data()->data(),   p.mass.data(),
          p.inertia.data(),          p.fixed.data()};
}


// Integrates particles [begin, end) in blocks of kBlock. The state update runs one particle
// per SIMD lane; what is summed over particles (unbalanced force, damping work) is stored per
// lane and summed afterwards in particle order, in the order of the original single loop
// (six damping terms per particle: x, rotation x, y, rotation y, z, rotation z), so one range
// over all particles gives the same bits as that loop. With `unbalanced_out`, |load| of
// particle i (0 for fixed ones) is stored there instead of being summed (the caller sums it
// in particle order). kUnbalanced / kWork: whether those sums are wanted (IntegrationSums);
// the state update is the same either way.
template <DampingForm kForm, bool kUnbalanced, bool kWork>
void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin,
                     std::size_t end, RangeReport& r, double* unbalanced_out) {
  constexpr std::size_t kBlock = 64;
  const double alpha = s.damping;
  const double gx = s.gravity[0], gy = s.gravity[1], gz = s.gravity[2];
  double unbalanced_sum = 0.0, max_unbalanced = r.max_unbalanced, damping_work = 0.0;
  std::size_t free_count = 0;
  // Not a structured binding: clang (the ThreadSanitizer build) cannot capture one in the
  // OpenMP simd region below.
  const FlatState st = flat_state(p);
  alignas(64) double unbalanced[kBlock];
  alignas(64) double work[6][kBlock];  // damping work terms in the order they are summed
  for (std::size_t block = begin; block < end; block += kBlock) {
    const std::size_t count = std::min(kBlock, end - block);
#pragma omp simd
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = block + k;
      const bool is_fixed = st.fixed[i] != 0;
      const double m = st.mass[i], in = st.inertia[i];
      const double inv_m = 1.0 / m, inv_i = 1.0 / in;
      const double load[3] = {st.force[3 * i] + m * gx, st.force[3 * i + 1] + m * gy, st.force[3 * i + 2] + m * gz};
      unbalanced[k] = std::sqrt((load[0] * load[0] + load[1] * load[1]) + load[2] * load[2]);
#pragma GCC unroll 3
      for (int d = 0; d < 3; ++d) {
        const double v = st.velocity[3 * i + d], w = st.spin[3 * i + d], t = st.torque[3 * i + d];
        const double a = damped_acceleration<kForm>(load[d], v, inv_m, alpha, dt);
        const double v_new = v + dt * a;
        // Work of the damping force over the step, with the mean of the two mid-step velocities.
        work[2 * d][k] = (a - load[d] * inv_m) * m * 0.5 * (v + v_new) * dt;
        const double alpha_w = damped_acceleration<kForm>(t, w, inv_i, alpha, dt);
        const double w_new = w + dt * alpha_w;
        work[2 * d + 1][k] = (alpha_w - t * inv_i) * in * 0.5 * (w + w_new) * dt;
        // A fixed particle keeps its prescribed velocity.
        const double v_next = is_fixed ? v : v_new;
        st.velocity[3 * i + d] = v_next;
        st.spin[3 * i + d] = is_fixed ? w : w_new;
        st.position[3 * i + d] += dt * v_next;
      }
    }
    if constexpr (!kUnbalanced && !kWork) continue;
    for (std::size_t k = 0; k < count; ++k) {  // particle order
      if (st.fixed[block + k]) {
        if (kUnbalanced && unbalanced_out) unbalanced_out[block + k] = 0.0;
        continue;
      }
      if constexpr (kUnbalanced) {
        if (unbalanced_out) unbalanced_out[block + k] = unbalanced[k];
        else unbalanced_sum += unbalanced[k];
        max_unbalanced = std::max(max_unbalanced, unbalanced[k]);
        ++free_count;
      }
      if constexpr (kWork)
        for (int term = 0; term < 6; ++term) damping_work -= work[term][k];
    }
  }
  r.free_count += free_count;
  r.unbalanced_sum = unbalanced_sum;
  r.max_unbalanced = max_unbalanced;
  r.damping_work = damping_work;
}

// The motion of particles [begin, end) without sums, one degree of freedom per SIMD lane:
// the Vec3 arrays are read as flat arrays of 3n doubles (component k = 3 i + d), so lanes
// load and store contiguous memory instead of de-interleaving xyz triples. Each component
// gets the operations of integrate_range in the same order (the same bits); each particle's
// weight components m g_d, 1/m, 1/I and fixed flag are first spread over its three
// components, block by block.
template <DampingForm kForm>
void move_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin, std::size_t end) {
  constexpr std::size_t kBlock = 64;  // particles
  const double alpha = s.damping;
  const double gravity[3] = {s.gravity[0], s.gravity[1], s.gravity[2]};
  // Not a structured binding: clang (the ThreadSanitizer build) cannot capture one in the
  // OpenMP simd region below.
  const FlatState st = flat_state(p);
  // Per component of the block: weight m g_d (N), 1/m, 1/I, and 1.0 for a fixed particle.
  alignas(64) double weight[3 * kBlock], inv_m[3 * kBlock], inv_i[3 * kBlock], is_fixed[3 * kBlock];
  for (std::size_t block = begin; block < end; block += kBlock) {
    const std::size_t count = std::min(kBlock, end - block);
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = block + k;
      const double m = st.mass[i], mobility = 1.0 / m, spin_mobility = 1.0 / st.inertia[i];
      const double f = st.fixed[i] != 0 ? 1.0 : 0.0;
      for (int d = 0; d < 3; ++d) {
        weight[3 * k + d] = m * gravity[d];
        inv_m[3 * k + d] = mobility;
        inv_i[3 * k + d] = spin_mobility;
        is_fixed[3 * k + d] = f;
      }
    }
    const std::size_t n = 3 * count;
    double* x = st.position + 3 * block;
    double* v_of = st.velocity + 3 * block;
    double* w_of = st.spin + 3 * block;
    const double* f_of = st.force + 3 * block;
    const double* t_of = st.torque + 3 * block;
#pragma omp simd
    for (std::size_t k = 0; k < n; ++k) {
      const double load = f_of[k] + weight[k];
      const double v = v_of[k], w = w_of[k], t = t_of[k];
      const double v_new = v + dt * damped_acceleration<kForm>(load, v, inv_m[k], alpha, dt);
      const double w_new = w + dt * damped_acceleration<kForm>(t, w, inv_i[k], alpha, dt);
      const double v_next = is_fixed[k] != 0.0 ? v : v_new;  // a fixed particle keeps its velocity
      v_of[k] = v_next;
      w_of[k] = is_fixed[k] != 0.0 ? w : w_new;
      x[k] += dt * v_next;
    }
  }
}

template <DampingForm kForm>
void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin, std::size_t end,
                     RangeReport& r, double* unbalanced_out, IntegrationSums sums) {
  if (!sums.unbalanced && !sums.damping_work) {
    move_range<kForm>(p, s, dt, begin, end);
    return;
  }
  if (sums.unbalanced && sums.damping_work)
    integrate_range<kForm, true, true>(p, s, dt, begin, end, r, unbalanced_out);
  else if (sums.unbalanced)
    integrate_range<kForm, true, false>(p, s, dt, begin, end, r, unbalanced_out);
  else if (sums.damping_work)
    integrate_range<kForm, false, true>(p, s, dt, begin, end, r, unbalanced_out);
  else
    integrate_range<kForm, false, false>(p, s, dt, begin, end, r, unbalanced_out);
}

}  // namespace

void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin,
                     std::size_t end, RangeReport& r, double* unbalanced_out, IntegrationSums sums) {
  if (s.damping_form == DampingForm::kPfc)
    integrate_range<DampingForm::kPfc>(p, s, dt, begin, end, r, unbalanced_out, sums);
  else
    integrate_range<DampingForm::kYade>(p, s, dt, begin, end, r, unbalanced_out, sums);
}

}  // namespace colza::COLZA_KERNEL_NAMESPACE
