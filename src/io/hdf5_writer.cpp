#include "io/hdf5_writer.hpp"

#include <H5Cpp.h>

#include "io/hdf5_internal.hpp"

#include "core/version.hpp"

namespace colza {

Hdf5Writer::Hdf5Writer(const std::string& file, bool many_chunked) : name_(file) {
  translating_errors([&] {
    // Format of HDF5 1.8 or later: dense attribute storage (attributes over 64 KiB); 1.10's
    // with snapshots (`many_chunked`). Its root group's header would carry times; the file
    // creation list sets them off.
    H5::FileAccPropList access;
    access.setLibverBounds(many_chunked ? H5F_LIBVER_V110 : H5F_LIBVER_V18, H5F_LIBVER_LATEST);
    H5::FileCreatPropList creation;
    if (H5Pset_obj_track_times(creation.getId(), false) < 0)
      throw H5::PropListIException("H5Pset_obj_track_times", "failed on the file creation list");
    file_ = std::make_unique<H5::H5File>(file, H5F_ACC_TRUNC, creation, access);
  });
}

Hdf5Writer::~Hdf5Writer() = default;

void Hdf5Writer::close() {
  translating_errors([&] {
    if (file_) file_->close();
  });
  file_.reset();
}

void Hdf5Writer::attribute(const std::string& name, const std::string& value) {
  translating_errors([&] {
    H5::StrType type(H5::PredType::C_S1, std::max<std::size_t>(1, value.size()));
    H5::Attribute a = file_->createAttribute(name, type, H5::DataSpace(H5S_SCALAR));
    a.write(type, value.empty() ? std::string(" ") : value);
  });
}

void Hdf5Writer::attribute(const std::string& name, double value) {
  translating_errors([&] {
    H5::Attribute a = file_->createAttribute(name, H5::PredType::NATIVE_DOUBLE, H5::DataSpace(H5S_SCALAR));
    a.write(H5::PredType::NATIVE_DOUBLE, &value);
  });
}

void Hdf5Writer::attribute(const std::string& name, std::int64_t value) {
  translating_errors([&] {
    H5::Attribute a = file_->createAttribute(name, H5::PredType::NATIVE_INT64, H5::DataSpace(H5S_SCALAR));
    a.write(H5::PredType::NATIVE_INT64, &value);
  });
}

namespace {

using hdf5_detail::ensure_group;
using hdf5_detail::untimed_dataset;

// A dataset of doubles with its unit as the string attribute "units" (none if `unit` is empty).
void write_doubles(H5::Group& g, const std::string& name, const double* data, hsize_t rows, hsize_t cols,
                   const std::string& unit) {
  const hsize_t dims[2] = {rows, cols};
  H5::DataSpace space(cols == 1 ? 1 : 2, dims);
  H5::DataSet ds = g.createDataSet(name, H5::PredType::NATIVE_DOUBLE, space, untimed_dataset());
  if (rows > 0) ds.write(data, H5::PredType::NATIVE_DOUBLE);
  if (unit.empty()) return;
  H5::StrType type(H5::PredType::C_S1, unit.size());
  ds.createAttribute("units", type, H5::DataSpace(H5S_SCALAR)).write(type, unit);
}

}  // namespace

void Hdf5Writer::write_table(const std::string& group, const Table& table) {
  translating_errors([&] {
    H5::Group g = ensure_group(*file_, group);
    for (std::size_t k = 0; k < table.names.size(); ++k)
      write_doubles(g, table.names[k], table.columns[k].data(), table.columns[k].size(), 1,
                    k < table.units.size() ? table.units[k] : std::string());
  });
}

void Hdf5Writer::write_particles(const std::string& group, const ParticleArrays& p) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  translating_errors([&] {
    H5::Group g = ensure_group(*file_, group);
    write_doubles(g, "position", p.position.empty() ? nullptr : p.position[0].data(), p.size(), 3, "m");
    write_doubles(g, "velocity", p.velocity.empty() ? nullptr : p.velocity[0].data(), p.size(), 3, "m/s");
    write_doubles(g, "angular_velocity", p.angular_velocity.empty() ? nullptr : p.angular_velocity[0].data(), p.size(),
                  3, "rad/s");
    write_doubles(g, "radius", p.radius.data(), p.size(), 1, "m");
  });
}

void write_provenance(Hdf5Writer& h5, const std::string& scenario, std::uint64_t seed, const std::string& config_toml) {
  h5.attribute("schema_version", static_cast<std::int64_t>(kResultSchemaVersion));
  h5.attribute("colza_version", std::string(kVersion));
  h5.attribute("git_revision", std::string(git_revision()));
  h5.attribute("scenario", scenario);
  h5.attribute("seed", static_cast<std::int64_t>(seed));
  h5.attribute("config_toml", config_toml);
}

}  // namespace colza
