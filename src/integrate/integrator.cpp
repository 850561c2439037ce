#include "integrate/integrator.hpp"

#include <algorithm>
#include <limits>

#include "core/kernel_isa.hpp"
#include "integrate/integrate_range.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace colza {

const char* to_string(DampingForm form) { return form == DampingForm::kPfc ? "pfc" : "yade"; }

namespace {

// The particle ranges compiled for the instruction set this process runs (core/kernel_isa.hpp).
void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin, std::size_t end,
                     RangeReport& r, double* unbalanced_out, IntegrationSums sums) {
  integrate_range_for(active_kernel_isa())(p, s, dt, begin, end, r, unbalanced_out, sums);
}

// The sums a step did not compute are NaN.
void mark_untracked(IntegrationReport& report, IntegrationSums sums) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!sums.unbalanced) report.mean_unbalanced_force = report.max_unbalanced_force = nan;
  if (!sums.damping_work) report.damping_work = nan;
}

}  // namespace

void integrate_motion(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin, std::size_t end) {
  RangeReport unused;
  integrate_range(p, s, dt, begin, end, unused, nullptr, IntegrationSums{.unbalanced = false, .damping_work = false});
}

IntegrationReport report_without_sums() {
  IntegrationReport report;
  mark_untracked(report, IntegrationSums{.unbalanced = false, .damping_work = false});
  return report;
}

IntegrationReport integrate_step(ParticleArrays& p, const IntegratorSettings& s, double dt, IntegrationSums sums) {
  IntegrationReport report;
  RangeReport r;
  integrate_range(p, s, dt, 0, p.size(), r, nullptr, sums);
  report.max_unbalanced_force = r.max_unbalanced;
  report.mean_unbalanced_force = r.free_count ? r.unbalanced_sum / r.free_count : 0.0;
  report.damping_work = r.damping_work;
  mark_untracked(report, sums);
  return report;
}

IntegrationReport integrate_step(ParticleArrays& p, const IntegratorSettings& s, double dt, int threads,
                                 std::vector<double>& unbalanced_scratch, IntegrationSums sums) {
  const std::size_t n = p.size();
  if (threads <= 1 || n < kMinParticlesPerThread * 2) return integrate_step(p, s, dt, sums);
  unbalanced_scratch.resize(n);
  std::vector<RangeReport> parts(static_cast<std::size_t>(threads));
#ifdef _OPENMP
#pragma omp parallel num_threads(threads)
  {
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t nt = static_cast<std::size_t>(omp_get_num_threads());
    if (t < parts.size())
      integrate_range(p, s, dt, n * t / nt, n * (t + 1) / nt, parts[t], unbalanced_scratch.data(), sums);
  }
#else
  for (std::size_t t = 0; t < parts.size(); ++t)
    integrate_range(p, s, dt, n * t / parts.size(), n * (t + 1) / parts.size(), parts[t], unbalanced_scratch.data(),
                    sums);
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
  if (sums.unbalanced)
    for (std::size_t i = 0; i < n; ++i) unbalanced_sum += unbalanced_scratch[i];
  report.mean_unbalanced_force = free_count ? unbalanced_sum / free_count : 0.0;
  report.damping_work = damping_work;
  mark_untracked(report, sums);
  return report;
}

}  // namespace colza
