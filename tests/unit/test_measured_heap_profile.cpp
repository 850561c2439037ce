// A measured heap profile (calibration/measured_heap_profile.hpp) goes through the cone fit
// that reduces colza's runs: a profile of points on a cone of known angle gives that angle;
// colza's own heap_profile.csv read back gives the run's angle; bad files are ConfigErrors
// naming the spec, the key and the reason.
#include <gtest/gtest.h>

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <cmath>
#include <fstream>

#include "calibration/measured_heap_profile.hpp"
#include "config/config_error.hpp"
#include "core/types.hpp"
#include "io/table.hpp"
#include "scenario/repose.hpp"
#include "scratch_dir.hpp"

using namespace colza;
using calibration::measured_heap_angle;
using colza::testing::ScratchDir;

namespace {

// The paper's particles (d 6-7 mm, mean 6.5 mm) and the repose defaults (16 sectors, fit
// between 0.25 and 0.75 of the heap's radius).
RunConfig model() {
  RunConfig c;
  c.particle.diameter_min = 0.006;
  c.particle.diameter_max = 0.007;
  return c;
}

std::string write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
  return file.string();
}

}  // namespace

TEST(MeasuredHeapProfile, PointsOnAConeGiveItsAngle) {
  // A ruler's readings along one line: top = 60 mm - rho tan(31 deg) every 2 mm out to the foot.
  const ScratchDir dir;
  const double t = std::tan(31.0 * kPi / 180.0);
  std::string text = "# heap profile, one line\nrho,top\n";
  for (double rho = 0.0; 0.060 - rho * t > 0.0; rho += 0.002)
    text += std::to_string(rho) + "," + std::to_string(0.060 - rho * t) + "\n";
  const HeapAngle h = measured_heap_angle(write(dir.path() / "p.csv", text), model(), "spec.toml", "tests.curve");
  ASSERT_TRUE(h.valid);
  EXPECT_NEAR(h.angle_deg, 31.0, 0.05);  // the points' 6-digit rounding only
  EXPECT_NEAR(h.height, 0.060, 1e-6);
}

TEST(MeasuredHeapProfile, ColzasOwnHeapProfileGivesTheRunsAngle) {
  // Spheres of d 6.5 mm whose tops lie on a 28 deg cone, at random azimuths, with buried ones
  // below: the run's fit (repose_fit_settings, the spheres themselves) and the fit of the
  // profile colza writes (heap_profile_table) read back as a measured file agree, on the bare
  // plate and on a glued layer whose top stands one diameter above it (the profile's tops
  // are heights above the heap's base).
  for (const double base : {0.0, 0.0065}) {
    ParticleArrays heap;
    const double h = 0.060, r = 0.00325, t = std::tan(28.0 * kPi / 180.0);
    boost::random::mt19937 rng(11);
    boost::random::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> x, y, z, radius;
    for (int k = 0; k < 3000; ++k) {
      const double rho = h / t * std::sqrt(unit(rng)), theta = 2.0 * kPi * unit(rng);
      for (double depth : {0.0, 2.0 * r * (1.0 + 2.0 * unit(rng))}) {
        const double zc = base + h - rho * t - depth - r;
        heap.add(Vec3(rho * std::cos(theta), rho * std::sin(theta), zc), r, 1000.0);
        x.push_back(rho * std::cos(theta)), y.push_back(rho * std::sin(theta)), z.push_back(zc);
        radius.push_back(r);
      }
    }
    const RunConfig c = model();
    const HeapAngle run = fit_heap_angle(x, y, z, radius, repose_fit_settings(c.repose, base));
    const ScratchDir dir;
    const std::string csv = (dir.path() / "heap_profile.csv").string();
    write_csv(csv, heap_profile_table(heap, base, run));
    const HeapAngle read = measured_heap_angle(csv, c, "spec.toml", "tests.curve");
    ASSERT_TRUE(run.valid && read.valid) << "base " << base;
    EXPECT_NEAR(read.angle_deg, run.angle_deg, 1e-6) << "base " << base;
    EXPECT_NEAR(read.radius, run.radius, 1e-9) << "base " << base;
    // Heights above the base on both sides: the heap's height and the cone's apex.
    EXPECT_NEAR(read.height, run.height, 1e-9) << "base " << base;
    EXPECT_NEAR(run.height, 0.060, 0.002) << "base " << base;
    EXPECT_NEAR(read.intercept, run.intercept, 1e-9) << "base " << base;
  }
}

TEST(MeasuredHeapProfile, BadProfilesNameTheSpecTheKeyAndTheReason) {
  const ScratchDir dir;
  const auto message = [&](const std::string& text) {
    try {
      measured_heap_angle(write(dir.path() / "bad.csv", text), model(), "spec.toml", "tests.curve");
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string no_top = message("rho,height\n0,0.06\n0.01,0.05\n0.02,0.04\n0.03,0.03\n0.04,0.02\n");
  EXPECT_NE(no_top.find("spec.toml"), std::string::npos) << no_top;
  EXPECT_NE(no_top.find("tests.curve"), std::string::npos) << no_top;
  EXPECT_NE(no_top.find("top"), std::string::npos) << no_top;
  EXPECT_NE(message("rho,top\n0,0.06\n0.01,0.05\n").find("at least 5 points"), std::string::npos);
  EXPECT_NE(message("rho,top\n-0.01,0.06\n0.01,0.05\n0.02,0.04\n0.03,0.03\n0.04,0.02\n").find("negative"), std::string::npos);
  // A flat layer one millimetre high stands nowhere two diameters above the plate: no heap.
  EXPECT_NE(message("rho,top\n0,0.001\n0.01,0.001\n0.02,0.001\n0.03,0.001\n0.04,0.001\n").find("no cone fits"),
            std::string::npos);
}
