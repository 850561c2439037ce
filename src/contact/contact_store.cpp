#include "contact/contact_store.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "core/particles.hpp"

namespace colza {

namespace {

// Appends row k of `from` (stride doubles) to `to`, or zeros when `from` is null.
void append_row(std::vector<double>& to, const std::vector<double>* from, std::size_t k, std::size_t stride) {
  if (stride == 0) return;
  if (from) to.insert(to.end(), from->begin() + k * stride, from->begin() + (k + 1) * stride);
  else to.insert(to.end(), stride, 0.0);
}

// Merge old (a,b)-sorted pairs with history (and slot-state rows of `stride` doubles) into
// new sorted pairs. Pairs only in the old list are dropped unless bonded, in which case they
// are inserted in order.
void merge_history(std::vector<Index>& new_a, std::vector<Index>& new_b,
                   const std::vector<Index>& old_a, const std::vector<Index>& old_b,
                   const std::vector<ContactHistory>& old_h, std::vector<ContactHistory>& new_h,
                   const std::vector<double>& old_s, std::vector<double>& new_s, std::size_t stride) {
  std::vector<Index> out_a, out_b;
  std::vector<ContactHistory> out_h;
  std::vector<double> out_s;
  out_a.reserve(new_a.size());
  out_b.reserve(new_a.size());
  out_h.reserve(new_a.size());
  out_s.reserve(new_a.size() * stride);
  std::size_t i = 0, j = 0;
  auto key_less = [](Index a1, Index b1, Index a2, Index b2) { return a1 < a2 || (a1 == a2 && b1 < b2); };
  while (i < new_a.size() || j < old_a.size()) {
    const bool take_new = j >= old_a.size() ||
                          (i < new_a.size() && !key_less(old_a[j], old_b[j], new_a[i], new_b[i]));
    if (take_new) {
      const bool same = j < old_a.size() && old_a[j] == new_a[i] && old_b[j] == new_b[i];
      out_a.push_back(new_a[i]);
      out_b.push_back(new_b[i]);
      out_h.push_back(same ? old_h[j] : ContactHistory{});
      append_row(out_s, same ? &old_s : nullptr, j, stride);
      ++i;
      if (same) ++j;
    } else {  // pair only in the old list
      if (old_h[j].bonded) {
        out_a.push_back(old_a[j]);
        out_b.push_back(old_b[j]);
        out_h.push_back(old_h[j]);
        append_row(out_s, &old_s, j, stride);
      }
      ++j;
    }
  }
  new_a.swap(out_a);
  new_b.swap(out_b);
  new_h.swap(out_h);
  new_s.swap(out_s);
}

// Replaces a list's sorted keys (a, b) and histories h by the new sorted keys, the histories
// carried over by merge_history.
void adopt(std::vector<Index>& a, std::vector<Index>& b, std::vector<ContactHistory>& h, std::vector<double>& s,
           std::size_t stride, std::vector<Index> new_a, std::vector<Index> new_b) {
  std::vector<ContactHistory> new_h;
  std::vector<double> new_s;
  merge_history(new_a, new_b, a, b, h, new_h, s, new_s, stride);
  a.swap(new_a);
  b.swap(new_b);
  h.swap(new_h);
  s.swap(new_s);
}

// The rows of `rows` (stride doubles each) in the given order.
std::vector<double> gather_rows(const std::vector<double>& rows, const std::vector<std::size_t>& order,
                                std::size_t stride) {
  std::vector<double> out;
  out.reserve(order.size() * stride);
  for (std::size_t k : order) append_row(out, &rows, k, stride);
  return out;
}

}  // namespace

void ContactStore::adopt_particle_pairs(std::vector<Index> first, std::vector<Index> second) {
  adopt(particle_pairs.first, particle_pairs.second, particle_pairs.history, particle_pairs.slot_state, layout_.stride,
        std::move(first), std::move(second));
  ++revision_;
}

void ContactStore::adopt_wall_pairs(std::vector<Index> wall, std::vector<Index> particle) {
  adopt(wall_pairs.wall, wall_pairs.particle, wall_pairs.history, wall_pairs.slot_state, layout_.stride,
        std::move(wall), std::move(particle));
  ++revision_;
}

void ContactStore::set_slot_state_layout(const SlotStateLayout& layout) {
  if (layout == layout_) return;
  layout_ = layout;
  particle_pairs.slot_state.assign(particle_pairs.size() * layout_.stride, 0.0);
  wall_pairs.slot_state.assign(wall_pairs.size() * layout_.stride, 0.0);
  ++revision_;
}

void ContactStore::renumber_particles(const std::vector<Index>& old_to_new) {
  ++revision_;
  const std::size_t stride = layout_.stride;
  const Index removed = ParticleArrays::kRemoved;
  {  // particle pairs: keep (min, max) order and re-sort (a permutation may reorder pairs)
    auto& L = particle_pairs;
    std::vector<std::size_t> keep;
    for (std::size_t k = 0; k < L.size(); ++k)
      if (old_to_new[L.first[k]] != removed && old_to_new[L.second[k]] != removed) keep.push_back(k);
    std::vector<Index> a(keep.size()), b(keep.size());
    std::vector<ContactHistory> h(keep.size());
    std::vector<double> s = gather_rows(L.slot_state, keep, stride);
    for (std::size_t m = 0; m < keep.size(); ++m) {
      Index i = old_to_new[L.first[keep[m]]], j = old_to_new[L.second[keep[m]]];
      h[m] = L.history[keep[m]];
      if (i > j) {  // swapping bodies 1 and 2 flips the normal and the force on body 2
        std::swap(i, j);
        h[m].shear_force = -h[m].shear_force;
        h[m].normal = -h[m].normal;
        for (std::size_t d = 0; d < stride; ++d) s[m * stride + d] *= layout_.swap_sign[d];  // the slots' own rule
      }
      a[m] = i;
      b[m] = j;
    }
    std::vector<std::size_t> order(keep.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return a[x] < a[y] || (a[x] == a[y] && b[x] < b[y]);
    });
    L.first.resize(order.size());
    L.second.resize(order.size());
    L.history.resize(order.size());
    for (std::size_t m = 0; m < order.size(); ++m) {
      L.first[m] = a[order[m]];
      L.second[m] = b[order[m]];
      L.history[m] = h[order[m]];
    }
    L.slot_state = gather_rows(s, order, stride);
  }
  {  // wall pairs: sorted by (wall, particle)
    auto& L = wall_pairs;
    std::vector<std::size_t> keep;
    for (std::size_t k = 0; k < L.size(); ++k)
      if (old_to_new[L.particle[k]] != removed) keep.push_back(k);
    std::vector<std::size_t> order = keep;
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      const Index px = old_to_new[L.particle[x]], py = old_to_new[L.particle[y]];
      return L.wall[x] < L.wall[y] || (L.wall[x] == L.wall[y] && px < py);
    });
    WallPairList out;
    for (std::size_t k : order) {
      out.wall.push_back(L.wall[k]);
      out.particle.push_back(old_to_new[L.particle[k]]);
      out.history.push_back(L.history[k]);
    }
    out.slot_state = gather_rows(L.slot_state, order, stride);
    L = std::move(out);
  }
}

std::vector<std::uint8_t> ContactStore::particles_in_pairs(std::size_t particle_count, bool touching_only) const {
  std::vector<std::uint8_t> in_pair(particle_count, 0);
  for (std::size_t k = 0; k < particle_pairs.size(); ++k)
    if (!touching_only || particle_pairs.history[k].touching)
      in_pair[particle_pairs.first[k]] = in_pair[particle_pairs.second[k]] = 1;
  for (std::size_t k = 0; k < wall_pairs.size(); ++k)
    if (!touching_only || wall_pairs.history[k].touching) in_pair[wall_pairs.particle[k]] = 1;
  return in_pair;
}

std::size_t ContactStore::touching_particle_contacts() const {
  return std::count_if(particle_pairs.history.begin(), particle_pairs.history.end(),
                       [](const ContactHistory& h) { return h.touching != 0; });
}
std::size_t ContactStore::touching_wall_contacts() const {
  return std::count_if(wall_pairs.history.begin(), wall_pairs.history.end(),
                       [](const ContactHistory& h) { return h.touching != 0; });
}
std::size_t ContactStore::bonded_contacts() const {
  return std::count_if(particle_pairs.history.begin(), particle_pairs.history.end(),
                       [](const ContactHistory& h) { return h.bonded != 0; });
}

}  // namespace colza
