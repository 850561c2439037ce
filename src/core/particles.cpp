#include "core/particles.hpp"

namespace colza {

double sphere_mass(double radius, double density) {
  return density * 4.0 / 3.0 * kPi * radius * radius * radius;
}

double sphere_inertia(double mass, double radius) { return 0.4 * mass * radius * radius; }

Index ParticleArrays::add(const Vec3& x, double r, double density, std::uint16_t material_index,
                          const Vec3& v, const Vec3& w) {
  const double m = sphere_mass(r, density);
  position.push_back(x);
  velocity.push_back(v);
  angular_velocity.push_back(w);
  force.push_back(Vec3::Zero());
  torque.push_back(Vec3::Zero());
  radius.push_back(r);
  mass.push_back(m);
  inertia.push_back(sphere_inertia(m, r));
  material.push_back(material_index);
  fixed.push_back(0);
  return static_cast<Index>(position.size() - 1);
}

namespace {
template <class T>
void compact_vector(std::vector<T>& values, const std::vector<std::uint8_t>& keep) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (keep[i]) values[out++] = values[i];
  values.resize(out);
}
template <class T>
void permute_vector(std::vector<T>& values, const std::vector<Index>& order) {
  std::vector<T> result(values.size());
  for (std::size_t k = 0; k < order.size(); ++k) result[k] = values[order[k]];
  values.swap(result);
}
}  // namespace

std::vector<Index> ParticleArrays::compact(const std::vector<std::uint8_t>& keep) {
  std::vector<Index> old_to_new(size(), kRemoved);
  Index next = 0;
  for (std::size_t i = 0; i < size(); ++i)
    if (keep[i]) old_to_new[i] = next++;
  compact_vector(position, keep);
  compact_vector(velocity, keep);
  compact_vector(angular_velocity, keep);
  compact_vector(force, keep);
  compact_vector(torque, keep);
  compact_vector(radius, keep);
  compact_vector(mass, keep);
  compact_vector(inertia, keep);
  compact_vector(material, keep);
  compact_vector(fixed, keep);
  return old_to_new;
}

void ParticleArrays::permute(const std::vector<Index>& order) {
  permute_vector(position, order);
  permute_vector(velocity, order);
  permute_vector(angular_velocity, order);
  permute_vector(force, order);
  permute_vector(torque, order);
  permute_vector(radius, order);
  permute_vector(mass, order);
  permute_vector(inertia, order);
  permute_vector(material, order);
  permute_vector(fixed, order);
}

void ParticleArrays::clear_forces() {
  for (auto& f : force) f.setZero();
  for (auto& t : torque) t.setZero();
}

}  // namespace colza
