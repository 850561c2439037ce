// Hdf5Writer::write_snapshots: the /snapshots group of result.h5 (layout in io/hdf5_writer.hpp).
#include <algorithm>
#include <cstdio>

#include "io/hdf5_internal.hpp"

namespace colza {

namespace {

template <class T>
const H5::PredType& h5_type();
template <>
const H5::PredType& h5_type<float>() { return H5::PredType::NATIVE_FLOAT; }
template <>
const H5::PredType& h5_type<double>() { return H5::PredType::NATIVE_DOUBLE; }
template <>
const H5::PredType& h5_type<std::int32_t>() { return H5::PredType::NATIVE_INT32; }
template <>
const H5::PredType& h5_type<std::uint8_t>() { return H5::PredType::NATIVE_UINT8; }
template <>
const H5::PredType& h5_type<std::uint64_t>() { return H5::PredType::NATIVE_UINT64; }
template <>
const H5::PredType& h5_type<std::int64_t>() { return H5::PredType::NATIVE_INT64; }

constexpr hsize_t kChunkBytes = 64 * 1024;
constexpr int kDeflateLevel = 4;

// values.size() / cols rows of `cols` values (a 1-D dataset when cols == 1), chunked and
// compressed (an empty one contiguous: HDF5 cannot chunk zero rows), with its unit as the
// attribute "units" unless `unit` is empty.
template <class T>
void write_array(H5::Group& g, const std::string& name, const std::vector<T>& values, hsize_t cols,
                 const std::string& unit) {
  const hsize_t rows = values.size() / cols;
  const hsize_t dims[2] = {rows, cols};
  H5::DataSpace space(cols == 1 ? 1 : 2, dims);
  H5::DSetCreatPropList props = hdf5_detail::untimed_dataset();
  if (rows > 0) {
    const hsize_t chunk[2] = {std::clamp<hsize_t>(kChunkBytes / (cols * sizeof(T)), 1, rows), cols};
    props.setChunk(cols == 1 ? 1 : 2, chunk);
    props.setShuffle();
    props.setDeflate(kDeflateLevel);
  }
  H5::DataSet ds = g.createDataSet(name, h5_type<T>(), space, props);
  if (rows > 0) ds.write(values.data(), h5_type<T>());
  if (unit.empty()) return;
  H5::StrType type(H5::PredType::C_S1, unit.size());
  ds.createAttribute("units", type, H5::DataSpace(H5S_SCALAR)).write(type, unit);
}

template <class T>
void scalar_attribute(H5::Group& g, const std::string& name, T value) {
  g.createAttribute(name, h5_type<T>(), H5::DataSpace(H5S_SCALAR)).write(h5_type<T>(), &value);
}

void write_names(H5::Group& g, const std::string& name, const std::vector<std::string>& names) {
  std::size_t width = 1;
  for (const std::string& n : names) width = std::max(width, n.size());
  std::vector<char> packed(names.size() * width, '\0');
  for (std::size_t k = 0; k < names.size(); ++k) std::copy(names[k].begin(), names[k].end(), packed.begin() + k * width);
  const hsize_t dims[1] = {names.size()};
  H5::StrType type(H5::PredType::C_S1, width);
  H5::DataSet ds = g.createDataSet(name, type, H5::DataSpace(1, dims), hdf5_detail::untimed_dataset());
  if (!names.empty()) ds.write(packed.data(), type);
}

void write_one(H5::H5File& file, const std::string& path, const Snapshot& s) {
  H5::Group g = hdf5_detail::ensure_group(file, path);
  scalar_attribute(g, "time", s.time);
  scalar_attribute(g, "step", s.step);
  write_array(g, "position", s.position, 3, "m");
  write_array(g, "velocity", s.velocity, 3, "m/s");
  write_array(g, "angular_velocity", s.angular_velocity, 3, "rad/s");
  write_array(g, "force", s.force, 3, "N");
  write_array(g, "radius", s.radius, 1, "m");
  write_array(g, "coordination", s.coordination, 1, "1");
  H5::Group c = hdf5_detail::ensure_group(file, path + "/contacts");
  write_array(c, "pairs", s.pairs, 2, "");
  write_array(c, "normal_force", s.normal_force, 1, "N");
  write_array(c, "shear_force", s.shear_force, 3, "N");
  write_array(c, "bonded", s.bonded, 1, "1");
  H5::Group w = hdf5_detail::ensure_group(file, path + "/walls");
  write_array(w, "points", s.wall_points, 3, "m");
  write_array(w, "quads", s.wall_quads, 4, "");
  write_array(w, "wall", s.wall_of_quad, 1, "");
  write_array(w, "force", s.wall_force, 3, "N");
}

}  // namespace

std::string snapshot_group(std::size_t k) {
  char name[32];
  std::snprintf(name, sizeof name, "/snapshots/%06zu", k);
  return name;
}

void Hdf5Writer::write_snapshots(const SnapshotSeries& series) {
  if (series.empty()) return;
  translating_errors([&] {
    H5::Group g = hdf5_detail::ensure_group(*file_, "/snapshots");
    scalar_attribute(g, "schema_version", static_cast<std::int64_t>(kSnapshotSchemaVersion));
    scalar_attribute(g, "interval", series.interval);
    scalar_attribute(g, "count", static_cast<std::int64_t>(series.snapshots.size()));
    std::vector<double> time;
    std::vector<std::uint64_t> step;
    for (const Snapshot& s : series.snapshots) {
      time.push_back(s.time);
      step.push_back(s.step);
    }
    write_array(g, "time", time, 1, "s");
    write_array(g, "step", step, 1, "1");
    write_names(g, "wall_names", series.wall_names);
    for (std::size_t k = 0; k < series.snapshots.size(); ++k) write_one(*file_, snapshot_group(k), series.snapshots[k]);
  });
}

}  // namespace colza
