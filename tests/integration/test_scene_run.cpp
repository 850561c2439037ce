// The generic scene through the CLI: particles and walls from the config, a fixed number
// of steps or a stop condition, and the time series of chosen particles and walls.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_runner.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

// A 3 mm sphere released 0.5 mm above a plane, gravity on, local damping 0.7.
fs::path write_drop_scene(const fs::path& dir, const std::string& scene_extra) {
  fs::create_directories(dir);
  const fs::path cfg = dir / "drop.toml";
  std::ofstream(cfg) << "scenario = \"scene\"\n"
                        "[integration]\ntime_step = 1e-6\ndamping = 0.7\n"
                        "[scene]\nsteps = 200000\nrecord_interval = 100\nrecord_particles = [0]\n"
                     << scene_extra
                     << "[[scene.particles]]\nposition = [0.0, 0.0, 0.0035]\nradius = 0.003\n"
                        "[[scene.walls]]\nshape = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n";
  return cfg;
}

}  // namespace

TEST(Scene, StopConditionEndsTheRunWhereTheSphereIsInEquilibrium) {
  const fs::path dir = scratch_dir("scene-drop");
  const fs::path cfg = write_drop_scene(dir, "stop_unbalanced_force = 1e-6\n");
  const CliResult r = run_colza("run scene --quiet --config " + cfg.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto s = read_json(dir / "out" / "summary.json");
  EXPECT_TRUE(s["stopped_by_condition"].get<bool>());
  EXPECT_LT(s["steps"].get<int>(), 200000);
  // At rest the wall carries the sphere's weight m g, m = rho 4/3 pi R^3 with the default
  // rho = 1250 kg/m^3: the last row's wall force equals m g to within the stop threshold.
  std::istringstream in(read_file(dir / "out" / "series.csv"));
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line)) last = line;
  std::vector<std::string> names, cells;
  for (std::istringstream h(header); std::getline(h, line, ',');) names.push_back(line);
  for (std::istringstream c(last); std::getline(c, line, ',');) cells.push_back(line);
  ASSERT_EQ(names.size(), cells.size());
  double wall_fz = 0.0, pz = 0.0, vz = 0.0;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k] == "w0_fz") wall_fz = std::stod(cells[k]);
    if (names[k] == "p0_z") pz = std::stod(cells[k]);
    if (names[k] == "p0_vz") vz = std::stod(cells[k]);
  }
  // The run stops once the unbalanced force |F_contact + m g| of the previous step is below
  // 1e-6 N (PFC's criterion; for one damped sphere this happens where it passes through
  // equilibrium). Equilibrium: contact force m g, overlap m g / Kn, with m = rho 4/3 pi R^3
  // (default rho = 1250 kg/m^3) and Kn = series(437 kN/m, 4000 kN/m) = 393.96 kN/m. The
  // recorded row is one step later: the overlap moved by |v| dt, the force by Kn |v| dt.
  const double m = 1250.0 * 4.0 / 3.0 * M_PI * std::pow(0.003, 3);
  const double kn = 437e3 * 4000e3 / (437e3 + 4000e3), dt = 1e-6;
  EXPECT_NEAR(-wall_fz, m * 9.81, 1e-6 + kn * std::abs(vz) * dt);  // force on the wall points down
  EXPECT_NEAR(0.003 - pz, m * 9.81 / kn, 1e-6 / kn + std::abs(vz) * dt);
}

TEST(Scene, WithoutAStopConditionRunsAllSteps) {
  const fs::path dir = scratch_dir("scene-steps");
  fs::path cfg = write_drop_scene(dir, "");
  std::string text = read_file(cfg);
  text.replace(text.find("steps = 200000"), 14, "steps = 1000");
  std::ofstream(cfg) << text;
  const CliResult r = run_colza("run scene --quiet --config " + cfg.string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto s = read_json(dir / "out" / "summary.json");
  EXPECT_EQ(s["steps"].get<int>(), 1000);
  EXPECT_FALSE(s["stopped_by_condition"].get<bool>());
  for (const char* f : {"series.csv", "result.h5", "packing.txt"}) EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
}
