#include "integrate/time_step.hpp"

#include <cmath>
#include <limits>

#include <variant>

#include "contact/slots.hpp"

namespace colza {

namespace {

// Overlap now (un > 0, m), for pairs no force pass has flagged: two spheres, a sphere and a wall.
bool spheres_overlap(const ParticleArrays& p, Index i, Index j) {
  const double reach = p.radius[i] + p.radius[j];
  return (p.position[j] - p.position[i]).squaredNorm() < reach * reach;
}
bool sphere_overlaps_wall(const ParticleArrays& p, Index i, const Wall& wall) {
  const WallContactGeometry g = wall_sphere_geometry(wall, p.position[i], p.radius[i]);
  return g.in_range && g.overlap > 0.0;
}

// Tangent stiffnesses of one contact at overlap un (N/m, rolling N m / rad).
struct TangentStiffness {
  double normal = 0.0, shear = 0.0, rolling = 0.0;
};
TangentStiffness tangent_stiffness(const ContactModel& m, const PairContext& c, double overlap, const double* state) {
  TangentStiffness k;
  k.normal = std::visit([&](const auto& n) { return n.tangent_stiffness(c, overlap, state); }, m.normal);
  k.shear = std::visit([&](const auto& t) { return t.stiffness(c, overlap); }, m.tangential);
  if (const auto* r = std::get_if<ElasticPlasticRolling>(&m.rolling); r && r->acts(c)) k.rolling = r->stiffness(c);
  return k;
}

// critical_time_step for the generic tier's slots (time_step.hpp).
double critical_time_step_of_slots(const ParticleArrays& p, const std::vector<Wall>& walls,
                                   const ContactStore& contacts, const PairTable& pairs, CountedContacts counted,
                                   const ContactModel& model) {
  const bool overlaps_count = counted == CountedContacts::kTouchingOrOverlapping;
  const SlotStateLayout& layout = contacts.slot_state_layout();
  const std::size_t n = p.size();
  std::vector<double> k_trans(n, 0.0), k_rot(n, 0.0);
  std::vector<std::uint8_t> has_contact(n, 0);
  const auto& pp = contacts.particle_pairs;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const Index i = pp.first[c], j = pp.second[c];
    if (!pp.history[c].touching && !(overlaps_count && spheres_overlap(p, i, j))) continue;
    const PairContext ctx = particle_pair_context(p, pairs, i, j, 0.0);
    const double overlap = ctx.radius_1 + ctx.radius_2 - (p.position[j] - p.position[i]).norm();
    const TangentStiffness k = tangent_stiffness(model, ctx, overlap, contacts.particle_pair_state(c) + layout.normal);
    for (const Index b : {i, j}) {
      k_trans[b] += k.normal + k.shear;
      k_rot[b] += k.shear * p.radius[b] * p.radius[b] + k.rolling;
      has_contact[b] = 1;
    }
  }
  const auto& pw = contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    const Index i = pw.particle[c];
    const Wall& wall = walls[pw.wall[c]];
    if (!pw.history[c].touching && !(overlaps_count && sphere_overlaps_wall(p, i, wall))) continue;
    const PairContext ctx = wall_pair_context(p, pairs, i, wall.material, 0.0);
    const double r = ctx.radius_2;
    const double overlap = wall_sphere_geometry(wall, p.position[i], r).overlap;
    const TangentStiffness k = tangent_stiffness(model, ctx, overlap, contacts.wall_pair_state(c) + layout.normal);
    k_trans[i] += k.normal + k.shear;
    k_rot[i] += k.shear * r * r + k.rolling;
    has_contact[i] = 1;
  }
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const double r = p.radius[i];
    if (!has_contact[i]) {  // one contact with its own material at 1 % of its radius
      const PairContext ctx = particle_pair_context(p, pairs, i, i, 0.0);
      const TangentStiffness k = tangent_stiffness(model, ctx, 0.01 * r, kZeroSlotRow);
      k_trans[i] = k.normal + k.shear;
      k_rot[i] = k.shear * r * r + k.rolling;
    }
    dt = std::min(dt, std::sqrt(p.mass[i] / k_trans[i]));
    if (k_rot[i] > 0.0) dt = std::min(dt, std::sqrt(p.inertia[i] / k_rot[i]));
  }
  return dt;
}

}  // namespace

double critical_time_step(const ParticleArrays& p, const std::vector<Wall>& walls, const ContactStore& contacts,
                          const PairTable& pairs, CountedContacts counted, const ContactModel& model) {
  if (!is_baseline(model)) return critical_time_step_of_slots(p, walls, contacts, pairs, counted, model);
  const bool overlaps_count = counted == CountedContacts::kTouchingOrOverlapping;
  const std::size_t n = p.size();
  std::vector<double> k_trans(n, 0.0), k_shear(n, 0.0);
  const auto& pp = contacts.particle_pairs;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const Index i = pp.first[c], j = pp.second[c];
    if (!pp.history[c].touching && !(overlaps_count && spheres_overlap(p, i, j))) continue;
    const PairParameters& q = pairs.particle_particle(p.material[i], p.material[j]);
    k_trans[i] += q.kn + q.ks;
    k_trans[j] += q.kn + q.ks;
    k_shear[i] += q.ks;
    k_shear[j] += q.ks;
  }
  const auto& pw = contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    const Index i = pw.particle[c];
    if (!pw.history[c].touching && !(overlaps_count && sphere_overlaps_wall(p, i, walls[pw.wall[c]]))) continue;
    const PairParameters& q = pairs.particle_wall(p.material[i], walls[pw.wall[c]].material);
    k_trans[i] += q.kn + q.ks;
    k_shear[i] += q.ks;
  }
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    if (k_trans[i] == 0.0) {
      const PairParameters& q = pairs.particle_particle(p.material[i], p.material[i]);
      k_trans[i] = q.kn + q.ks;
      k_shear[i] = q.ks;
    }
    const double r = p.radius[i];
    dt = std::min(dt, std::sqrt(p.mass[i] / k_trans[i]));
    if (k_shear[i] > 0.0) dt = std::min(dt, std::sqrt(p.inertia[i] / (k_shear[i] * r * r)));
  }
  return dt;
}

}  // namespace colza
