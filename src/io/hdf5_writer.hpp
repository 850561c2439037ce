// HDF5 result files (result.h5). Layout, schema version 2 (1 had no /snapshots):
//   /                 attributes: schema_version, colza_version, git_revision, scenario,
//                     seed, config_toml (the configuration as used) and summary_json (the
//                     summary without timings)
//   /curve            one 1-D dataset per recorded column (SI units, see curve.csv)
//   /particles/<tag>  position (N x 3), velocity (N x 3), angular_velocity (N x 3), radius (N)
//   /snapshots        only when the run took snapshots (output.snapshot_interval > 0);
//                     attributes schema_version (kSnapshotSchemaVersion), interval (s), count;
//                     datasets time (K, s since the test began), step (K), wall_names (W);
//   /snapshots/<kkkkkk>              k = 000000 ... K-1 (io/snapshot.hpp, single precision):
//                     position, velocity, angular_velocity, force (N x 3), radius (N),
//                     coordination (N); attributes time (s), step
//   /snapshots/<kkkkkk>/contacts     pairs (M x 2, particle indices), normal_force (M),
//                     shear_force (M x 3), bonded (M, 0 or 1)
//   /snapshots/<kkkkkk>/walls        points (P x 3), quads (Q x 4, indices into points),
//                     wall (Q, index into wall_names), force (Q x 3, the wall's total force)
//                     Snapshot datasets are chunked (at most 64 KiB a chunk) and compressed
//                     (shuffle + deflate level 4); result.xmf (io/xdmf_writer.hpp) maps them.
// Groups and datasets carry no creation or modification times, so equal results give equal
// files, byte for byte. The file format is HDF5 1.8's or later (read by any HDF5 >= 1.8 and
// h5py), whose dense attribute storage holds a config_toml longer than 64 KiB (a scene
// listing a thousand particles inline); the 1.6 format refuses such an attribute. A file
// with snapshots is in HDF5 1.10's format (Hdf5Writer's `many_chunked`).
#pragma once
#include <memory>
#include <stdexcept>
#include <string>
#include "core/particles.hpp"
#include "io/output_error.hpp"
#include "io/snapshot.hpp"
#include "io/table.hpp"

namespace H5 { class H5File; }

namespace colza {

inline constexpr int kResultSchemaVersion = 2;
inline constexpr int kSnapshotSchemaVersion = 1;

// Any failure of the HDF5 library while writing (a full disk, say), with the file and the
// failing call: HDF5's own exceptions do not derive from std::exception.
class Hdf5WriteError : public OutputWriteError {
 public:
  using OutputWriteError::OutputWriteError;
};

class Hdf5Writer {
 public:
  // `many_chunked`: the file will hold many small chunked datasets (snapshots), so it is
  // written in HDF5 1.10's format, whose chunk indexes need no B-tree for a dataset of one
  // chunk (1.8's take ~2.1 KB each: a small oedometer's 9 snapshots of 117 spheres took
  // 209 KB instead of 530 KB); read by HDF5 >= 1.10 (Debian 12's 1.10.8, h5py, ParaView).
  // Without it, HDF5 1.8's format.
  explicit Hdf5Writer(const std::string& file, bool many_chunked = false);
  ~Hdf5Writer();
  void attribute(const std::string& name, const std::string& value);
  void attribute(const std::string& name, double value);
  void attribute(const std::string& name, std::int64_t value);
  void write_table(const std::string& group, const Table& table);
  void write_particles(const std::string& group, const ParticleArrays& particles);
  // /snapshots (io/hdf5_snapshots.cpp); nothing when `series` holds none.
  void write_snapshots(const SnapshotSeries& series);
  void close();

 private:
  template <class Body>
  void translating_errors(Body&& body);  // runs body, HDF5's exceptions as Hdf5WriteError
  std::string name_;
  std::unique_ptr<H5::H5File> file_;
};

// The group of snapshot k in result.h5: "/snapshots/000042".
std::string snapshot_group(std::size_t k);

// Writes the standard root attributes (schema, version, git revision, scenario, seed, config).
void write_provenance(Hdf5Writer& h5, const std::string& scenario, std::uint64_t seed, const std::string& config_toml);

}  // namespace colza
