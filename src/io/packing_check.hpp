// Checks of a settled packing read from a file before a run starts from it (oedometer and
// shear box: `packing_file`). A packing written for another container, or one that is not
// settled, would otherwise run and give a wrong answer quietly: a sphere outside the
// cylinder is pushed back by the one-sided wall at once, and deeply overlapping spheres
// fly apart. Both are input errors (ConfigError naming the file, the key and the lines).
//
// Tolerance: a settled packing's overlaps under gravity and the test's loads are microns
// (Fn / Kn); a penetration of a wall or an overlap of more than 10 % of the (smaller)
// radius is not one.
#pragma once
#include <string>
#include <vector>
#include "io/packing_file.hpp"

namespace colza {

inline constexpr double kMaxSettledOverlapFraction = 0.1;

// Spheres must lie in the vertical cylinder of radius `radius` around the z axis, above the
// floor z = 0, and reach within a largest diameter of its wall (the oedometer,
// scenario/oedometer.cpp).
void check_packing_in_cylinder(const std::vector<PackedSphere>& spheres, double radius, const std::string& file,
                               const std::string& key);

// Spheres must lie in 0 <= x <= length, 0 <= y <= width, above the floor z = 0, and span
// each of the box's length and width to within two largest diameters (the shear box,
// scenario/shear_box.cpp).
void check_packing_in_box(const std::vector<PackedSphere>& spheres, double length, double width,
                          const std::string& file, const std::string& key);

// No two spheres may overlap by more than kMaxSettledOverlapFraction of the smaller radius.
void check_packing_overlaps(const std::vector<PackedSphere>& spheres, const std::string& file,
                            const std::string& key);

}  // namespace colza
