// How one shear load's results are named, and the check that a list of loads can share one
// series or calibration directory (the shear box, scenario/shear_box.cpp; the series and
// calibration commands; the config and spec checks).
#pragma once
#include <string>
#include <vector>

namespace colza {

// The name of one load's results, "load-<sigma>Pa" (sigma in Pa, to the nearest pascal):
// a series' load directory, a calibration run's load curve (+ ".csv").
std::string load_label(double normal_stress);
// Whether `name` has that form, load-<digits>Pa (a folder of a series' load, say).
bool is_load_label(const std::string& name);

// Why a list of loads cannot be run as one series or calibration, or "" when it can: two
// loads with the same label would write to one directory (or curve file), so every load
// must appear once and loads must be at least ~1 Pa apart.
std::string loads_sharing_a_label(const std::vector<double>& normal_stresses);

}  // namespace colza
