// Contact-law slots (physics.md sections 2 and 7). A contact model is one implementation per
// slot:
//   normal     - force from the overlap (linear, Hertz, Walton-Braun elasto-plastic);
//   tangential - incremental shear spring and its sliding limit (Coulomb, Mindlin);
//   damping    - viscous contact dashpots (none, viscous);
//   rolling    - a moment resisting relative rolling (none, elastic-plastic spring);
//   bond       - contact bond, load-induced cohesion, or none.
// Each implementation is a small struct of typed parameters with pure functions, in the
// slot's header (normal_laws.hpp, ...), one alternative of the slot's variant here and one
// row in slot_registry.cpp. Per-contact state beyond the core history (ContactHistory) is
// declared by kStateDoubles and kept in columns (contact/slot_state.hpp).
//
// Two tiers run a model (engine/force_loops_body.hpp): the baseline (linear, Coulomb, no damping, no
// rolling, no bond or the contact bond) runs the batched kernels, and so do its particle pairs
// with one lane mechanism (rolling resistance, viscous damping, Walton-Braun or load-induced
// cohesion), or with viscous damping and one of the others; any other combination runs the
// generic law (contact/generic_law.hpp), one loop with a run-time choice
// per slot.
#pragma once
#include <variant>
#include "contact/bond_laws.hpp"
#include "contact/damping_laws.hpp"
#include "contact/normal_laws.hpp"
#include "contact/rolling_laws.hpp"
#include "contact/tangential_laws.hpp"

namespace colza {

using NormalSlot = std::variant<LinearNormal, HertzNormal, WaltonBraunNormal>;
using TangentialSlot = std::variant<CoulombTangential, MindlinTangential>;
using DampingSlot = std::variant<NoDamping, ViscousDamping>;
using RollingSlot = std::variant<NoRolling, ElasticPlasticRolling>;
using BondSlot = std::variant<NoBond, ContactBond, LoadInducedBond>;

struct ContactModel {
  NormalSlot normal;
  TangentialSlot tangential;
  DampingSlot damping;
  RollingSlot rolling;
  BondSlot bond;
  BondInstallMoment bond_install = BondInstallMoment::kNever;
  double bond_gap = 0.0;  // bonds also join pairs whose gap (-un) is at most this (m)
};

// Calls f with the implementation a slot holds: a chain of index tests, which the compiler
// inlines (std::visit may go through a table of function pointers), for the generic law's
// per-contact dispatch.
template <std::size_t I, class F, class... Impl>
[[gnu::always_inline]] inline decltype(auto) visit_slot_from(const std::variant<Impl...>& slot, F& f) {
  if constexpr (I + 1 == sizeof...(Impl)) {
    return f(*std::get_if<I>(&slot));
  } else {
    if (slot.index() == I) return f(*std::get_if<I>(&slot));
    return visit_slot_from<I + 1>(slot, f);
  }
}

template <class F, class... Impl>
[[gnu::always_inline]] inline decltype(auto) visit_slot(const std::variant<Impl...>& slot, F&& f) {
  return visit_slot_from<0>(slot, f);
}
// The baseline of physics.md section 2, which the batched kernels compute: linear normal,
// Coulomb tangential, no contact damping, no rolling resistance, no bond or the contact bond.
inline bool is_baseline(const ContactModel& m) {
  return std::holds_alternative<LinearNormal>(m.normal) && std::holds_alternative<CoulombTangential>(m.tangential) &&
         std::holds_alternative<NoDamping>(m.damping) && std::holds_alternative<NoRolling>(m.rolling) &&
         (std::holds_alternative<NoBond>(m.bond) || std::holds_alternative<ContactBond>(m.bond));
}

// Whether the model's bond slot can bond a pair at all.
inline bool has_bonds(const ContactModel& m) { return !std::holds_alternative<NoBond>(m.bond); }

}  // namespace colza
