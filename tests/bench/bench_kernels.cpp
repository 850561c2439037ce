// Micro-benchmarks of the contact kernel (force computation over the candidate pairs), the
// neighbour rebuild and the integrator, on a jammed lattice packing of 6-7 mm spheres with
// the oedometer's default materials. Items processed = particles, so the reported rate is
// particle-steps per second of that stage alone. The context printed first names the CPU and
// the copy of the force loops that runs (core/kernel_isa.hpp: the widest this CPU runs, or
// the one $COLZA_ISA names, e.g. COLZA_ISA=avx2) with every copy's target options.
#include <benchmark/benchmark.h>

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <cmath>
#include <cstdlib>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/cpu_model.hpp"
#include "core/kernel_isa.hpp"
#include "engine/pair_batch.hpp"
#include "engine/stepper.hpp"
#include "io/packing_file.hpp"
#include "scenario/oedometer.hpp"

using namespace colza;

namespace {

PhysicsSettings physics() {
  PhysicsSettings s;
  s.particle_materials.push_back(ParticleMaterial{"seed", 1250.0, 437e3, 100e3, 0.20});
  s.wall_materials.push_back(WallMaterial{"steel", 4000e3, 1000e3, 0.23});
  s.skin = 0.5e-3;
  return s;
}

// n spheres on a cubic lattice of spacing 6.4 mm (radii 3.1-3.3 mm, so about half of the
// lattice neighbours overlap by up to 0.2 mm), positions jittered by 20 um, small random
// velocities; a floor plane.
World packing(std::size_t n) {
  World w;
  boost::random::mt19937 rng(42);
  boost::random::uniform_real_distribution<double> u(-1.0, 1.0), rad(3.1e-3, 3.3e-3);
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(n))));
  const double a = 6.4e-3;
  for (std::size_t k = 0; k < n; ++k) {
    const int x = static_cast<int>(k % side), y = static_cast<int>((k / side) % side), z = static_cast<int>(k / (side * side));
    const Vec3 pos(a * x + 2e-5 * u(rng), a * y + 2e-5 * u(rng), a * (z + 0.5) + 2e-5 * u(rng));
    w.particles.add(pos, rad(rng), 1250.0, 0, Vec3(1e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng)));
  }
  w.walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  return w;
}

// The settled oedometer packing named by the environment variable COLZA_BENCH_PACKING (a
// packing file, e.g. the one tests/bench/compare_codes.py prepares in
// /tmp/colza-compare/prep/packing.txt), in the oedometer scenario's container with its
// piston resting on the top sphere (the paper's defaults: 100 mm cylinder, 500 mm/min): the
// benchmark's real contact statistics (about 2.2 contacts and 3.1 candidate pairs per
// particle) instead of the lattice's. Empty world when the variable is unset.
World oedometer_packing() {
  World w;
  const char* file = std::getenv("COLZA_BENCH_PACKING");
  if (!file) return w;
  double top = 0.0;
  for (const PackedSphere& s : read_packing(file, "COLZA_BENCH_PACKING")) {
    w.particles.add(s.position, s.radius, 1250.0);
    top = std::max(top, s.position[2] + s.radius);
  }
  const OedometerSpec paper_defaults;
  build_oedometer_container(w, paper_defaults);
  add_oedometer_piston(w, paper_defaults, top);
  return w;
}

void set_threads(benchmark::State& state) {
#ifdef _OPENMP
  omp_set_num_threads(static_cast<int>(state.range(1)));
#else
  if (state.range(1) != 1) state.SkipWithError("built without OpenMP");
#endif
}

// Forces only: Stepper::begin_step (time-step update every 100 steps, rebuild check, force
// loop). Particles do not move, so the lists stay valid and contacts stay touching.
void run_forces_only(benchmark::State& state, World& w, const PhysicsSettings& settings,
                     IntegrationSums sums = IntegrationSums{}) {
  Stepper stepper(settings);
  stepper.prepare(w);
  stepper.set_integration_sums(sums);
  for (auto _ : state) {
    stepper.begin_step(w);
    ++w.step;
    benchmark::DoNotOptimize(w.particles.force.data());
  }
  state.counters["pairs"] = static_cast<double>(w.contacts.particle_pairs.size());
  state.counters["contacts"] = static_cast<double>(w.contacts.touching_particle_contacts());
  state.counters["wall_pairs"] = static_cast<double>(w.contacts.wall_pairs.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(w.particles.size()));
}

void BM_ContactKernel(benchmark::State& state) {
  set_threads(state);
  World w = packing(static_cast<std::size_t>(state.range(0)));
  run_forces_only(state, w, physics());
}

// Full steps: forces, integration with local damping, wall motion (the oedometer loop).
void BM_FullStep(benchmark::State& state) {
  set_threads(state);
  World w = packing(static_cast<std::size_t>(state.range(0)));
  Stepper stepper(physics());
  stepper.prepare(w);
  for (auto _ : state) stepper.step(w);
  state.counters["rebuilds"] = static_cast<double>(stepper.neighbours().rebuild_count());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// As BM_ContactKernel and BM_FullStep, on the settled oedometer packing (COLZA_BENCH_PACKING)
// with dt = 1e-5 s (the compare_codes.py benchmark's).
PhysicsSettings oedometer_physics() {
  PhysicsSettings s = physics();
  s.time_step.automatic = false;
  s.time_step.fixed_dt = 1e-5;
  return s;
}

// False (and the benchmark skipped) when COLZA_BENCH_PACKING is not set.
bool has_packing(benchmark::State& state, const World& w) {
  if (w.particles.size() > 0) return true;
  state.SkipWithError("set COLZA_BENCH_PACKING to a packing file");
  return false;
}

void BM_OedometerForces(benchmark::State& state) {
  set_threads(state);
  World w = oedometer_packing();
  if (!has_packing(state, w)) return;
  // As the loading runs them: no integration sums, so no energy ledger and no slip energy
  // (the lanes' form without its division).
  run_forces_only(state, w, oedometer_physics(), {.unbalanced = false, .damping_work = false});
}

// The lane arithmetic alone (engine/pair_batch.hpp compute_lanes: geometry and law of
// every contact, the ledger off as in the loading), over the touching contacts of the settled
// oedometer packing loaded into batches once, outside the timing: no copies into lanes, no
// scatter, no history written back. The floor the batched kernel's structure cannot go
// below; items = contacts. Compiled here, for the build's baseline (x86-64: SSE2), not
// through the force loops' copies ($COLZA_ISA does not change it); a -DCOLZA_NATIVE=ON build
// measures the machine's own vectors.
void BM_OedometerLaneArithmetic(benchmark::State& state) {
  World w = oedometer_packing();
  if (!has_packing(state, w)) return;
  Stepper stepper(oedometer_physics());
  stepper.prepare(w);
  stepper.begin_step(w);  // contacts touching after one force step
  const auto& pp = w.contacts.particle_pairs;
  std::vector<detail::PairBatch> batches(1);
  for (std::size_t c = 0; c < pp.size(); ++c) {
    if (!pp.history[c].touching) continue;
    if (batches.back().count == detail::PairBatch::kLanes) batches.emplace_back();
    detail::PairBatch& b = batches.back();
    detail::note_lane(b, b.count++, w.particles.radius.data(), c, pp.first[c], pp.second[c], pp.history[c]);
  }
  for (auto& b : batches) detail::fill_lanes(b, w.particles, pp.history.data());
  const PairParameters& q = stepper.pairs().particle_particle(0, 0);
  const double dt = w.dt;
  std::size_t contacts = 0;
  for (const auto& b : batches) contacts += static_cast<std::size_t>(b.count);
  for (auto _ : state) {
    for (auto& b : batches) detail::compute_lanes<NoBond, false>(b, NoBond{}, q, dt, 0.5 * dt);
    benchmark::DoNotOptimize(batches.data());
    benchmark::ClobberMemory();
  }
  state.counters["contacts"] = static_cast<double>(contacts);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(contacts));
}

// Full steps as the oedometer's loading stage runs them: no integration sums and no energy
// ledger (scenario/oedometer.cpp), so the motion goes inside the threaded force loop.
void BM_OedometerStep(benchmark::State& state) {
  set_threads(state);
  World w = oedometer_packing();
  if (!has_packing(state, w)) return;
  Stepper stepper(oedometer_physics());
  stepper.prepare(w);
  stepper.set_integration_sums({.unbalanced = false, .damping_work = false});
  stepper.set_between_halves(Stepper::BetweenHalves::kWallsOnly);
  for (auto _ : state) stepper.step(w);
  state.counters["rebuilds"] = static_cast<double>(stepper.neighbours().rebuild_count());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(w.particles.size()));
}

void BM_NeighbourRebuild(benchmark::State& state) {
  World w = packing(static_cast<std::size_t>(state.range(0)));
  NeighbourSearch search(0.5e-3);
  for (auto _ : state) {
    search.invalidate();
    search.rebuild(w.particles, w.walls, w.contacts);
  }
  state.counters["pairs"] = static_cast<double>(w.contacts.particle_pairs.size());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_RebuildCheck(benchmark::State& state) {
  World w = packing(static_cast<std::size_t>(state.range(0)));
  NeighbourSearch search(0.5e-3);
  search.rebuild(w.particles, w.walls, w.contacts);
  for (auto _ : state) benchmark::DoNotOptimize(search.needs_rebuild(w.particles, w.walls));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_Integrate(benchmark::State& state) {
  set_threads(state);
  World w = packing(static_cast<std::size_t>(state.range(0)));
  IntegratorSettings s;
  std::vector<double> scratch;
  for (auto& f : w.particles.force) f = Vec3(1e-3, -2e-3, 5e-2);
  for (auto _ : state) {
    const IntegrationReport r = integrate_step(w.particles, s, 1e-7, static_cast<int>(state.range(1)), scratch);
    benchmark::DoNotOptimize(r.damping_work);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The motion alone (integrate_motion, one thread, no sums), as the oedometer loading and the
// shear stages run it inside the force loop; items = particles.
void BM_IntegrateMotion(benchmark::State& state) {
  World w = packing(static_cast<std::size_t>(state.range(0)));
  IntegratorSettings s;
  for (auto& f : w.particles.force) f = Vec3(1e-3, -2e-3, 5e-2);
  for (auto _ : state) {
    integrate_motion(w.particles, s, 1e-7, 0, w.particles.size());
    benchmark::DoNotOptimize(w.particles.position.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK(BM_ContactKernel)->ArgsProduct({{2287, 9805}, {1, 2}})->UseRealTime();
BENCHMARK(BM_FullStep)->ArgsProduct({{2287, 9805}, {1, 2}})->UseRealTime();
BENCHMARK(BM_OedometerForces)->ArgsProduct({{0}, {1, 2}})->UseRealTime();
BENCHMARK(BM_OedometerStep)->ArgsProduct({{0}, {1, 2}})->UseRealTime();
BENCHMARK(BM_OedometerLaneArithmetic);
BENCHMARK(BM_NeighbourRebuild)->Arg(2287)->Arg(9805);
BENCHMARK(BM_RebuildCheck)->Arg(2287)->Arg(9805);
BENCHMARK(BM_Integrate)->ArgsProduct({{2287, 9805}, {1, 2}})->UseRealTime();
BENCHMARK(BM_IntegrateMotion)->Arg(2287)->Arg(9805);

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("cpu", cpu_model());
  benchmark::AddCustomContext("force_loops", kernel_isa_report());  // throws on a bad $COLZA_ISA
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
