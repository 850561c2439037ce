// IntegrationSums (integrate/integrator.hpp): switching off the sums over particles
// (unbalanced force, damping work) must not change the motion by a single bit, on the
// serial and the threaded path, and a sum not computed is NaN. The reference is the
// integrator with every sum on; equality is memcmp of the state arrays.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "integrate/integrator.hpp"

using namespace colza;

namespace {

// 1500 spheres (above the threaded path's 2 x 512), every tenth fixed, with random
// velocities, spins, forces and torques of both signs (damping acts in both directions).
ParticleArrays random_particles() {
  ParticleArrays p;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 1500; ++i) {
    p.add(Vec3(u(rng), u(rng), u(rng)), 0.003 + 0.0005 * u(rng), 1230.0, 0, Vec3(u(rng), u(rng), u(rng)),
          Vec3(10 * u(rng), 10 * u(rng), 10 * u(rng)));
    if (i % 10 == 0) p.fixed.back() = 1;
  }
  p.force.assign(p.size(), Vec3::Zero());
  p.torque.assign(p.size(), Vec3::Zero());
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.force[i] = Vec3(u(rng), u(rng), u(rng));
    p.torque[i] = 1e-3 * Vec3(u(rng), u(rng), u(rng));
  }
  return p;
}

bool same_bytes(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

}  // namespace

TEST(IntegrationSums, MotionIsTheSameWhicheverSumsAreComputed) {
  for (DampingForm form : {DampingForm::kPfc, DampingForm::kYade}) {
    IntegratorSettings s;
    s.damping_form = form;
    ParticleArrays reference = random_particles();
    std::vector<IntegrationReport> reference_reports;
    for (int step = 0; step < 3; ++step) reference_reports.push_back(integrate_step(reference, s, 1e-5));
    for (int threads : {1, 2}) {
      for (bool unbalanced : {false, true}) {
        for (bool work : {false, true}) {
          ParticleArrays p = random_particles();
          std::vector<double> scratch;
          for (int step = 0; step < 3; ++step) {
            const IntegrationReport r =
                integrate_step(p, s, 1e-5, threads, scratch, {.unbalanced = unbalanced, .damping_work = work});
            const IntegrationReport& ref = reference_reports[static_cast<std::size_t>(step)];
            if (unbalanced) {  // summed in particle order on both paths: the same bits
              EXPECT_EQ(r.mean_unbalanced_force, ref.mean_unbalanced_force);
              EXPECT_EQ(r.max_unbalanced_force, ref.max_unbalanced_force);
            } else {
              EXPECT_TRUE(std::isnan(r.mean_unbalanced_force));
              EXPECT_TRUE(std::isnan(r.max_unbalanced_force));
            }
            if (work)  // summed per range on the threaded path: the last bits may differ
              EXPECT_NEAR(r.damping_work, ref.damping_work, 1e-12 * std::abs(ref.damping_work));
            else
              EXPECT_TRUE(std::isnan(r.damping_work));
          }
          const std::string where = std::string(to_string(form)) + ", " + std::to_string(threads) + " thread(s), sums " +
                                    std::to_string(unbalanced) + std::to_string(work);
          EXPECT_TRUE(same_bytes(p.position, reference.position)) << where;
          EXPECT_TRUE(same_bytes(p.velocity, reference.velocity)) << where;
          EXPECT_TRUE(same_bytes(p.angular_velocity, reference.angular_velocity)) << where;
        }
      }
    }
  }
}
