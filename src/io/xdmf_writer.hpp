// result.xmf: an XDMF 2 description of result.h5's snapshots (io/hdf5_writer.hpp) that
// ParaView opens as a time series (its "Xdmf Reader"; VTK's vtkXdmfReader). Three temporal
// collections, one grid per snapshot each, all reading the HDF5 file beside it:
//   particles  N points (a Polyvertex cell each) with radius, velocity, angular_velocity,
//              force and coordination: render with Point Gaussian (scale array radius) or
//              Glyph (sphere, scale by radius, factor 2 for diameter-sized spheres);
//   contacts   M lines between the centres of the pairs in contact, cell arrays normal_force,
//              shear_force and bonded (colour by normal_force; a snapshot without contacts
//              gets no contacts grid);
//   walls      Q quadrilaterals, cell arrays wall (index into /snapshots/wall_names) and force.
#pragma once
#include <string>
#include "io/snapshot.hpp"

namespace colza {

// The XDMF text for `series`, naming the HDF5 file `h5_name` (a name relative to the .xmf file).
std::string xdmf_text(const SnapshotSeries& series, const std::string& h5_name);

// Writes xdmf_text to `file`.
void write_xdmf(const std::string& file, const SnapshotSeries& series, const std::string& h5_name);

}  // namespace colza
