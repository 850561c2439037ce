// Checks of a settled packing read from a file (io/packing_check.hpp): spheres must fit
// the container within 10 % of their radius and overlap each other by at most 10 % of the
// smaller radius; otherwise a ConfigError names the file, the key and the lines.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "config/config_error.hpp"
#include "io/packing_check.hpp"

using namespace colza;

namespace {

PackedSphere sphere(double x, double y, double z, double r, int line) {
  PackedSphere s{Vec3(x, y, z), r};
  s.line = line;
  return s;
}

// The reason of the ConfigError `f` throws (empty if it throws none), with its key checked.
template <class F>
std::string reason_of(F&& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "p.txt");
    EXPECT_EQ(e.key(), "oedometer.packing_file");
    return e.reason();
  }
  return "";
}

const std::string kFile = "p.txt", kKey = "oedometer.packing_file";

}  // namespace

TEST(PackingCheck, CylinderAcceptsSettledSpheresAndNamesTheOneOutside) {
  const double R = 0.05, r = 0.003;
  // Touching the wall and the floor, penetrating each by 9 % of r: a settled packing.
  std::vector<PackedSphere> p = {sphere(R - r + 0.09 * r, 0.0, r, r, 2), sphere(0.0, 0.0, r - 0.09 * r, r, 3)};
  EXPECT_EQ(reason_of([&] { check_packing_in_cylinder(p, R, kFile, kKey); }), "");
  // 11 % of r into the wall, at 45 degrees (the radial distance counts, not x alone).
  const double c = (R - r + 0.11 * r) / std::sqrt(2.0);
  p.push_back(sphere(c, c, 0.02, r, 7));
  std::string m = reason_of([&] { check_packing_in_cylinder(p, R, kFile, kKey); });
  EXPECT_NE(m.find("line 7:"), std::string::npos) << m;
  EXPECT_NE(m.find("beyond the wall"), std::string::npos) << m;
  p.pop_back();
  p.push_back(sphere(0.01, 0.0, r - 0.11 * r, r, 8));  // into the floor
  m = reason_of([&] { check_packing_in_cylinder(p, R, kFile, kKey); });
  EXPECT_NE(m.find("line 8:"), std::string::npos) << m;
  EXPECT_NE(m.find("beyond the floor"), std::string::npos) << m;
}

TEST(PackingCheck, BoxNamesTheWallASphereCrosses) {
  const double L = 0.2, W = 0.1, r = 0.003;
  std::vector<PackedSphere> p = {sphere(r, r, r, r, 2), sphere(L - r, W - r, 0.05, r, 3)};
  EXPECT_EQ(reason_of([&] { check_packing_in_box(p, L, W, kFile, kKey); }), "");
  const std::vector<std::pair<PackedSphere, std::string>> outside = {
      {sphere(r - 0.2 * r, 0.05, 0.02, r, 4), "the wall x = 0"},
      {sphere(L, 0.05, 0.02, r, 5), "the wall x = length"},
      {sphere(0.1, -0.01, 0.02, r, 6), "the wall y = 0"},
      {sphere(0.1, W + 0.5 * r, 0.02, r, 7), "the wall y = width"},
      {sphere(0.1, 0.05, 0.0, r, 8), "the floor"}};
  for (const auto& [s, where] : outside) {
    std::vector<PackedSphere> q = p;
    q.push_back(s);
    const std::string m = reason_of([&] { check_packing_in_box(q, L, W, kFile, kKey); });
    EXPECT_NE(m.find("line " + std::to_string(s.line) + ":"), std::string::npos) << m;
    EXPECT_NE(m.find(where), std::string::npos) << where << ": " << m;
  }
}

TEST(PackingCheck, APackingThatDoesNotFillItsContainerIsRefused) {
  // A settled packing rests against the walls. One from a 40 mm cylinder in the 100 mm one
  // (a user's mistake: it loaded as a heap at 89 kg/m^3) reaches 20 mm of 50: refused. One
  // reaching within a diameter of the wall passes.
  const double R = 0.05, r = 0.003;
  std::vector<PackedSphere> narrow = {sphere(0.02 - r, 0.0, r, r, 2), sphere(0.0, 0.0, 3 * r, r, 3)};
  std::string m = reason_of([&] { check_packing_in_cylinder(narrow, R, kFile, kKey); });
  EXPECT_NE(m.find("reach only 20 mm of the 50 mm radius"), std::string::npos) << m;
  std::vector<PackedSphere> near_wall = {sphere(R - 3 * r + 1e-4, 0.0, r, r, 2)};
  EXPECT_EQ(reason_of([&] { check_packing_in_cylinder(near_wall, R, kFile, kKey); }), "");
  // The box: spanning its length, but only 50 of its 100 mm width.
  const double L = 0.2, W = 0.1;
  const std::vector<PackedSphere> half_wide = {sphere(r, r, r, r, 2), sphere(L - r, 0.05 - r, r, r, 3)};
  m = reason_of([&] { check_packing_in_box(half_wide, L, W, kFile, kKey); });
  EXPECT_NE(m.find("reach only 50 mm of the 100 mm width (y)"), std::string::npos) << m;
}

TEST(PackingCheck, OverlapsAboveATenthOfTheSmallerRadiusAreNamed) {
  const double r = 0.003, small = 0.002;
  // Pairs overlapping by 9 % of the smaller radius, in one cell and across cells.
  std::vector<PackedSphere> p = {sphere(0.0, 0.0, 0.0, r, 2), sphere(r + small - 0.09 * small, 0.0, 0.0, small, 3),
                                 sphere(0.1, 0.1, 0.1, r, 4), sphere(0.1, 0.1, 0.1 + 2 * r - 0.09 * r, r, 5)};
  EXPECT_EQ(reason_of([&] { check_packing_overlaps(p, kFile, kKey); }), "");
  p.push_back(sphere(-0.05, 0.02, 0.03, r, 9));
  p.push_back(sphere(-0.05 + 2 * r - 0.11 * r, 0.02, 0.03, r, 12));  // 11 %
  const std::string m = reason_of([&] { check_packing_overlaps(p, kFile, kKey); });
  EXPECT_NE(m.find("lines 9 and 12:"), std::string::npos) << m;
  EXPECT_NE(m.find("not a settled packing"), std::string::npos) << m;
}
