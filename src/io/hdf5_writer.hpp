// HDF5 result files (result.h5). Layout, schema version 1:
//   /                 attributes: schema_version, colza_version, git_revision, scenario,
//                     seed, config_toml (the configuration as used) and summary_json (the
//                     summary without timings)
//   /curve            one 1-D dataset per recorded column (SI units, see curve.csv)
//   /particles/<tag>  position (N x 3), velocity (N x 3), angular_velocity (N x 3), radius (N)
// Groups and datasets carry no creation or modification times, so equal results give equal
// files, byte for byte. The file format is HDF5 1.8's or later (read by any HDF5 >= 1.8 and
// h5py), whose dense attribute storage holds a config_toml longer than 64 KiB (a scene
// listing a thousand particles inline); the 1.6 format refuses such an attribute.
#pragma once
#include <memory>
#include <stdexcept>
#include <string>
#include "core/particles.hpp"
#include "io/output_error.hpp"
#include "io/table.hpp"

namespace H5 { class H5File; }

namespace colza {

inline constexpr int kResultSchemaVersion = 1;

// Any failure of the HDF5 library while writing (a full disk, say), with the file and the
// failing call: HDF5's own exceptions do not derive from std::exception.
class Hdf5WriteError : public OutputWriteError {
 public:
  using OutputWriteError::OutputWriteError;
};

class Hdf5Writer {
 public:
  explicit Hdf5Writer(const std::string& file);
  ~Hdf5Writer();
  void attribute(const std::string& name, const std::string& value);
  void attribute(const std::string& name, double value);
  void attribute(const std::string& name, std::int64_t value);
  void write_table(const std::string& group, const Table& table);
  void write_particles(const std::string& group, const ParticleArrays& particles);
  void close();

 private:
  template <class Body>
  void translating_errors(Body&& body);  // runs body, HDF5's exceptions as Hdf5WriteError
  std::string name_;
  std::unique_ptr<H5::H5File> file_;
};

// Writes the standard root attributes (schema, version, git revision, scenario, seed, config).
void write_provenance(Hdf5Writer& h5, const std::string& scenario, std::uint64_t seed, const std::string& config_toml);

}  // namespace colza
