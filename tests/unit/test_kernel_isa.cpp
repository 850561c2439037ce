// Every compiled copy of the kernels (core/kernel_isa.hpp: generic, avx2, avx512; the force
// loops and the integrator's ranges) that this CPU runs gives the generic copy's bits: the vector width changes how many contacts a
// vector instruction computes, never an operation or the order of a sum (each lane is one
// contact, results are consumed in pair order, no FMA is formed: -ffp-contract=off).
// Compared: the small oedometer (tests/data/small_oedometer.toml: generation, settling, the
// piston's loading; its curve and final state) and the jostling box of the force-path tests
// (tests/unit/jostling_box.hpp) on the kinds of force-loop path: the batched particle and
// wall kernels with bonds and every wall shape, the threaded loop with the motion inside it
// and candidates apart, two kinds of lane mechanism (a moment with slot state; bond
// strengths per lane, bonds forming), and the generic tier.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "config/run_config.hpp"
#include "core/kernel_isa.hpp"
#include "engine/force_loops.hpp"
#include "integrate/integrate_range.hpp"
#include "io/progress.hpp"
#include "jostling_box.hpp"
#include "scenario/oedometer.hpp"

using namespace colza;
using namespace jostling_box;

namespace {

// Runs the force loops' `isa` copy while in scope, then the one active before.
class KernelIsaScope {
 public:
  explicit KernelIsaScope(KernelIsa isa) : before_(active_kernel_isa()) { set_kernel_isa(isa); }
  ~KernelIsaScope() { set_kernel_isa(before_); }
  KernelIsaScope(const KernelIsaScope&) = delete;
  KernelIsaScope& operator=(const KernelIsaScope&) = delete;

 private:
  KernelIsa before_;
};

// The copies this CPU runs besides the generic one, as a list for messages.
std::vector<KernelIsa> wider_copies_here() {
  std::vector<KernelIsa> here = kernel_isas_here();
  here.erase(here.begin());  // generic
  return here;
}

std::string names(const std::vector<KernelIsa>& isas) {
  std::string s;
  for (KernelIsa isa : isas) s += std::string(s.empty() ? "" : ", ") + to_string(isa);
  return s;
}

OedometerResult small_oedometer(KernelIsa isa) {
  const KernelIsaScope scope(isa);
  const RunConfig config = load_run_config(Scenario::kOedometer, COLZA_SOURCE_DIR "/tests/data/small_oedometer.toml", {});
  Progress quiet = Progress::quiet();
  return run_oedometer(config, quiet);
}

template <class T>
bool same_vector_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expect_same_arrays(const ParticleArrays& a, const ParticleArrays& b) {
  EXPECT_TRUE(same_vector_bits(a.position, b.position));
  EXPECT_TRUE(same_vector_bits(a.velocity, b.velocity));
  EXPECT_TRUE(same_vector_bits(a.angular_velocity, b.angular_velocity));
  EXPECT_TRUE(same_vector_bits(a.force, b.force));
  EXPECT_TRUE(same_vector_bits(a.torque, b.torque));
}

}  // namespace

TEST(KernelIsa, NamesReadBackAndUnknownNamesAreRefused) {
  for (KernelIsa isa : {KernelIsa::kGeneric, KernelIsa::kAvx2, KernelIsa::kAvx512})
    EXPECT_EQ(parse_kernel_isa(to_string(isa)), isa);
  EXPECT_FALSE(parse_kernel_isa("sse2"));
  EXPECT_FALSE(parse_kernel_isa("AVX2"));
  EXPECT_FALSE(parse_kernel_isa(""));
}

// The generic copy is in every binary and runs on every CPU; the widest copy that runs here
// is the default (COLZA_ISA unset in the test environment); a copy that does not run here
// cannot be chosen.
TEST(KernelIsa, TheGenericCopyRunsEverywhereAndOnlyCopiesThatRunHereCanBeChosen) {
  ASSERT_TRUE(kernel_isa_runs_here(KernelIsa::kGeneric));
  EXPECT_EQ(kernel_isas_here().front(), KernelIsa::kGeneric);
  EXPECT_EQ(widest_kernel_isa_here(), kernel_isas_here().back());
  for (KernelIsa isa : {KernelIsa::kGeneric, KernelIsa::kAvx2, KernelIsa::kAvx512}) {
    EXPECT_EQ(kernel_isa_built(isa), force_loops_for(isa) != nullptr);
    EXPECT_EQ(kernel_isa_built(isa), integrate_range_for(isa) != nullptr);
    if (!kernel_isa_runs_here(isa)) EXPECT_THROW(set_kernel_isa(isa), std::invalid_argument) << to_string(isa);
  }
#if defined(__x86_64__)
  EXPECT_EQ(kernel_isa_built(KernelIsa::kAvx2), kernel_isa_built(KernelIsa::kAvx512));
#endif
  const std::string report = kernel_isa_report();
  EXPECT_NE(report.find("built: generic ("), std::string::npos) << report;
}

TEST(KernelIsa, EveryCopyGivesTheGenericBitsOnEveryForceLoopPath) {
  const std::vector<KernelIsa> wider = wider_copies_here();
  if (wider.empty()) GTEST_SKIP() << "only the generic copy runs here (" << kernel_isa_report() << ")";
  RecordProperty("compared", "generic, " + names(wider));
  std::printf("comparing the generic copy with: %s\n", names(wider).c_str());
  struct Case {
    const char* name;
    jostling_box::Setup setup;
    int threads;
  };
  const Case cases[] = {
      {"batched kernels, bonds breaking, shaped walls with restricted edges",
       {.bonds = true, .shaped_walls = true, .restricted_plate_edges = true}, 1},
      {"two threads, motion inside the force loop, wide skin (candidates apart)",
       {.bonds = true, .walls_only_between_halves = true, .skin = 2.5e-3}, 2},
      {"rolling lanes (PFC's form), bonds", {.bonds = true, .rolling = true, .rolling_form = RollingForm::kPfc}, 1},
      {"load-induced cohesion lanes (bonds forming and breaking)", {.load_induced = true}, 1},
      {"generic tier with rolling, dashpots and Walton-Braun, bonds", {.bonds = true, .mechanisms = true}, 1},
  };

  for (const Case& c : cases) {
    PathRun generic;
    {
      const KernelIsaScope scope(KernelIsa::kGeneric);
      generic = run_path(c.setup, c.threads);
    }
    for (KernelIsa isa : wider) {
      SCOPED_TRACE(std::string(c.name) + ": " + to_string(isa) + " against generic");
      const KernelIsaScope scope(isa);
      const PathRun run = run_path(c.setup, c.threads);
      expect_same_state(generic.world, run.world);
      expect_same_pair_energies(generic.ledger, run.ledger);
      EXPECT_EQ(generic.broken_tension, run.broken_tension);
      EXPECT_EQ(generic.broken_shear, run.broken_shear);
      for (auto term : {&EnergyLedger::rolling_dissipated, &EnergyLedger::viscous_dissipated,
                        &EnergyLedger::plastic_dissipated})
        EXPECT_EQ(std::memcmp(&(generic.ledger.*term), &(run.ledger.*term), sizeof(double)), 0);
      if (c.threads > 1) EXPECT_EQ(run.threaded_steps, 300u);
    }
  }
}

TEST(KernelIsa, EveryCopyGivesTheGenericBitsOnTheSmallOedometer) {
  const std::vector<KernelIsa> wider = wider_copies_here();
  if (wider.empty()) GTEST_SKIP() << "only the generic copy runs here (" << kernel_isa_report() << ")";
  RecordProperty("compared", "generic, " + names(wider));
  std::printf("comparing the generic copy with: %s\n", names(wider).c_str());
  const OedometerResult generic = small_oedometer(KernelIsa::kGeneric);
  ASSERT_GT(generic.curve.rows(), 10u);
  ASSERT_GT(generic.max_force, 100.0);  // the piston loaded the sample
  for (KernelIsa isa : wider) {
    SCOPED_TRACE(std::string(to_string(isa)) + " against generic");
    const OedometerResult run = small_oedometer(isa);
    EXPECT_EQ(run.particles, generic.particles);
    EXPECT_EQ(run.steps, generic.steps);
    EXPECT_EQ(run.stop_reason, generic.stop_reason);
    ASSERT_EQ(run.curve.columns.size(), generic.curve.columns.size());
    for (std::size_t k = 0; k < generic.curve.columns.size(); ++k)
      EXPECT_TRUE(same_vector_bits(run.curve.columns[k], generic.curve.columns[k])) << generic.curve.names[k];
    expect_same_arrays(run.settled, generic.settled);
    expect_same_arrays(run.final_state, generic.final_state);
  }
}
