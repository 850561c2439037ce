// Takes particle snapshots (io/snapshot.hpp) of a test at a fixed interval of simulated time:
// one at the start, one after each step that reaches the next multiple of the interval since
// the start, and the state at the end. It only reads the World, so a run's numbers are the
// same with and without snapshots, bit for bit. Called between steps (after Stepper::step or
// finish_step), where positions are x(t + dt), velocities v(t + dt/2) and the forces those of
// step t.
#pragma once
#include "engine/world.hpp"
#include "io/snapshot.hpp"

namespace colza {

class SnapshotRecorder {
 public:
  // `interval` (s) 0: records nothing. `start`: World::time at the test's start.
  SnapshotRecorder(double interval, double start) : start_(start) { series_.interval = interval; }
  bool enabled() const { return series_.interval > 0.0; }
  // Records when the time since the start has reached the next multiple of the interval.
  void observe(const World& world);
  // Records now, unless the last snapshot was taken at this step (the end of a stage).
  void record(const World& world);
  SnapshotSeries take() { return std::move(series_); }

 private:
  double start_;
  std::uint64_t next_ = 0;  // index of the next multiple of the interval
  SnapshotSeries series_;
};

// One snapshot of `world` (time counted from `start`).
Snapshot take_snapshot(const World& world, double start);

}  // namespace colza
