// Where the rare per-pair results of the force loop go (internal to the stepper): slip
// dissipation, energy lost or released when contacts and bonds break, and bond-break counts.
#pragma once
#include <cstdint>
#include <vector>
#include "contact/contact_law.hpp"

namespace colza::detail {

struct ForceLoopTotals {
  double slip = 0.0, broken = 0.0, released = 0.0, wall_power = 0.0;
  double rolling = 0.0, viscous = 0.0, plastic = 0.0, stiffness_change = 0.0;  // the generic tier's channels (J)
  std::uint64_t broken_tension = 0, broken_shear = 0;
};

inline void count_event(ContactEvent e, std::uint64_t& tension, std::uint64_t& shear) {
  if (e == ContactEvent::kBondBrokeTension) ++tension;
  if (e == ContactEvent::kBondBrokeShear) ++shear;
}

// Where the rare per-pair results go. The serial sink adds them to the totals at once, in
// pair order (the reference order). The logging sink keeps the non-zero ones of one
// contiguous range of pairs in pair order; range logs replayed in range order give the same
// sums as the serial sink (adding +0.0 to a sum that started at +0.0 changes nothing).
//
// `kKeepsSlip` tells the batched kernels whether the slip energy is wanted at all: when it is
// not (the energy ledger is off, see Stepper::set_integration_sums), the lanes skip its
// division and the sink drops it (WithoutSlip).
struct SerialSink {
  static constexpr bool kKeepsSlip = true;
  ForceLoopTotals& t;
  void slip(double s) { t.slip += s; }
  void rolling(double e) { t.rolling += e; }
  void viscous(double e) { t.viscous += e; }
  void plastic(double e) { t.plastic += e; }
  void stiffness_change(double e) { t.stiffness_change += e; }
  void broken(double e) { t.broken += e; }
  void released(double e) { t.released += e; }
  void event(ContactEvent e) { count_event(e, t.broken_tension, t.broken_shear); }
};
struct LogSink {
  static constexpr bool kKeepsSlip = true;
  std::vector<double> slips, brokens, releases, rollings, viscouses, plastics, stiffness_changes;
  std::uint64_t broken_tension = 0, broken_shear = 0;
  void slip(double s) {
    if (s != 0.0) slips.push_back(s);
  }
  void rolling(double e) {
    if (e != 0.0) rollings.push_back(e);
  }
  void viscous(double e) {
    if (e != 0.0) viscouses.push_back(e);
  }
  void plastic(double e) {
    if (e != 0.0) plastics.push_back(e);
  }
  void stiffness_change(double e) {
    if (e != 0.0) stiffness_changes.push_back(e);
  }
  void broken(double e) {
    if (e != 0.0) brokens.push_back(e);
  }
  void released(double e) {
    if (e != 0.0) releases.push_back(e);
  }
  void event(ContactEvent e) { count_event(e, broken_tension, broken_shear); }
  void clear() {
    slips.clear();
    brokens.clear();
    releases.clear();
    rollings.clear();
    viscouses.clear();
    plastics.clear();
    stiffness_changes.clear();
    broken_tension = broken_shear = 0;
  }
  // Adds the logged values to the totals in logged order (what a SerialSink would have done).
  void replay_into(ForceLoopTotals& t) const {
    for (double v : slips) t.slip += v;
    for (double v : brokens) t.broken += v;
    for (double v : releases) t.released += v;
    for (double v : rollings) t.rolling += v;
    for (double v : viscouses) t.viscous += v;
    for (double v : plastics) t.plastic += v;
    for (double v : stiffness_changes) t.stiffness_change += v;
    t.broken_tension += broken_tension;
    t.broken_shear += broken_shear;
  }
};

// A sink that drops the slip energy and the generic tier's dissipations, and passes
// everything else (bond-break energies and counts, which the results report) to `inner`: for
// steps that keep no energy ledger.
template <class Inner>
struct WithoutSlip {
  static constexpr bool kKeepsSlip = false;
  Inner& inner;
  void slip(double) {}
  void rolling(double) {}
  void viscous(double) {}
  void plastic(double) {}
  void stiffness_change(double) {}
  void broken(double e) { inner.broken(e); }
  void released(double e) { inner.released(e); }
  void event(ContactEvent e) { inner.event(e); }
};

// Calls f(sink) when kSlip, else f(a WithoutSlip wrapper of sink).
template <bool kSlip, class Sink, class F>
[[gnu::always_inline]] inline void with_slip_if(Sink& sink, F&& f) {
  if constexpr (kSlip) {
    f(sink);
  } else {
    WithoutSlip<Sink> dropping{sink};
    f(dropping);
  }
}

}  // namespace colza::detail
