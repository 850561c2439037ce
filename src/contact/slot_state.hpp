// Per-contact state of the slots beyond the core history (ContactHistory): one row of
// `stride` doubles per pair, kept in a column beside the histories (ContactStore), so the
// baseline (no slot state) keeps its 64-byte record and moves nothing more. Each slot
// declares its doubles (kStateDoubles) and how they change when a pair's bodies swap
// (a moment on body 2 changes sign, a largest overlap does not).
#pragma once
#include <cassert>
#include <cstddef>
#include <variant>
#include <vector>
#include "contact/slots.hpp"

namespace colza {

// The longest row any combination has (Walton-Braun 1, Mindlin 1, rolling 3, load-induced
// cohesion 2), and a row of zeros for a contact that has none yet.
inline constexpr std::size_t kMaxSlotStride = 8;
inline constexpr double kZeroSlotRow[kMaxSlotStride] = {};

struct SlotStateLayout {
  std::size_t stride = 0;   // doubles per pair
  std::size_t normal = 0;   // offset of the normal slot's state
  std::size_t tangential = 0;  // offset of the tangential slot's state
  std::size_t rolling = 0;  // offset of the rolling slot's state
  std::size_t bond = 0;     // offset of the bond slot's state
  std::vector<double> swap_sign;  // per double: +1 or -1, its factor when the bodies swap

  bool operator==(const SlotStateLayout& o) const {
    return stride == o.stride && normal == o.normal && tangential == o.tangential && rolling == o.rolling &&
           bond == o.bond &&
           swap_sign == o.swap_sign;
  }
};

// Rows laid out normal | tangential | rolling | bond; the rolling moment flips sign on a swap.
inline SlotStateLayout slot_state_layout(const ContactModel& m) {
  SlotStateLayout l;
  const auto doubles = [](const auto& slot) {
    return std::visit([](const auto& impl) { return static_cast<std::size_t>(impl.kStateDoubles); }, slot);
  };
  l.normal = 0;
  l.tangential = l.normal + doubles(m.normal);
  l.rolling = l.tangential + doubles(m.tangential);
  l.bond = l.rolling + doubles(m.rolling);
  l.stride = l.bond + doubles(m.bond);
  assert(l.stride <= kMaxSlotStride);
  l.swap_sign.assign(l.stride, 1.0);
  for (std::size_t k = l.rolling; k < l.bond; ++k) l.swap_sign[k] = -1.0;
  return l;
}

}  // namespace colza
