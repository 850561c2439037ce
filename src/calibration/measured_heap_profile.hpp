// A measured heap profile for the angle of repose (format: data/measured/README.md). CSV,
// '#' comment lines allowed, one header line, then one row per point of the heap's surface:
//
//   rho           m    the point's distance from the heap's axis
//   top           m    its height above the heap's base (the plate, or the top of a layer glued to it)
//   azimuth_deg   deg  optional: its direction about the axis (profiles along several lines)
//
// Other columns are ignored, so colza's own heap_profile.csv (one row per sphere, its top) is
// a valid profile. Its features come from analysis/heap_angle.hpp, the fit that reduces
// colza's runs: surface points binned by rho (bins of the model's mean diameter), the highest
// of each bin per sector (the model's repose.sectors when the profile has azimuths, else one),
// the toe at two mean diameters above the plate, the cone fitted between the model's
// repose.fit_inner and fit_outer of the heap's radius.
#pragma once
#include <string>

#include "analysis/heap_angle.hpp"
#include "config/run_config.hpp"

namespace colza::calibration {

inline constexpr const char* kHeapRhoColumn = "rho";
inline constexpr const char* kHeapTopColumn = "top";
inline constexpr const char* kHeapAzimuthColumn = "azimuth_deg";

// The cone fitted to the profile in `model`'s settings. Errors (ConfigError naming spec_file,
// key and the CSV): missing file or column, a cell that is not a number, a negative rho, fewer
// than 5 rows, or a profile no cone fits (heap_angle.hpp: under 3 bins of radius, or fewer than
// 5 surface points in the fit's range; a profile in mm reads as a heap 1000 times too wide).
HeapAngle measured_heap_angle(const std::string& csv, const RunConfig& model, const std::string& spec_file,
                              const std::string& key);

}  // namespace colza::calibration
