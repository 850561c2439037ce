// What the writers of result.h5 share (io/hdf5_writer.cpp, io/hdf5_snapshots.cpp): HDF5's
// exceptions as Hdf5WriteError, and groups and datasets without creation times.
#pragma once
#include <H5Cpp.h>

#include <string>

#include "io/hdf5_writer.hpp"

namespace colza {

template <class Body>
inline void Hdf5Writer::translating_errors(Body&& body) {
  try {
    body();
  } catch (const H5::Exception& e) {
    throw Hdf5WriteError("cannot write " + name_ + ": HDF5: " + e.getFuncName() + ": " + e.getDetailMsg());
  }
}

namespace hdf5_detail {

// Object creation properties without modification times: HDF5 stamps every group and dataset
// header with its creation time by default, so two runs with the same results would write
// different bytes (H5Pset_obj_track_times).
inline H5::DSetCreatPropList untimed_dataset() {
  H5::DSetCreatPropList p;
  if (H5Pset_obj_track_times(p.getId(), false) < 0) throw H5::PropListIException("H5Pset_obj_track_times", "failed");
  return p;
}

inline void create_untimed_group(H5::H5File& file, const std::string& path) {
  const hid_t gcpl = H5Pcreate(H5P_GROUP_CREATE);
  const bool ok = gcpl >= 0 && H5Pset_obj_track_times(gcpl, false) >= 0;
  const hid_t g = ok ? H5Gcreate2(file.getId(), path.c_str(), H5P_DEFAULT, gcpl, H5P_DEFAULT) : -1;
  if (gcpl >= 0) H5Pclose(gcpl);
  if (g < 0) throw H5::GroupIException("H5Gcreate2", "cannot create group " + path);
  H5Gclose(g);
}

inline H5::Group ensure_group(H5::H5File& file, const std::string& path) {
  std::string partial;
  std::size_t start = 0;
  while (start < path.size()) {
    const auto slash = path.find('/', start);
    partial += '/';
    partial.append(path, start, slash == std::string::npos ? std::string::npos : slash - start);
    if (!file.nameExists(partial)) create_untimed_group(file, partial);
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return file.openGroup(partial);
}

}  // namespace hdf5_detail

}  // namespace colza
