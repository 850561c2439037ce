// result.h5 writer (io/hdf5_writer.hpp): what is written reads back unchanged, and no object
// carries a creation or modification time (HDF5 stamps them by default, which made two runs
// with the same results write different bytes; two runs within the same second cannot show
// it, so the times are read directly here).
#include <gtest/gtest.h>

#include <H5Cpp.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "io/hdf5_writer.hpp"
#include "io/table.hpp"
#include "scenario/oedometer.hpp"
#include "scenario/scene.hpp"
#include "scenario/shear_box.hpp"

#include "scratch_dir.hpp"

using namespace colza;

namespace {

std::vector<double> read_doubles(const H5::H5File& f, const std::string& path) {
  H5::DataSet ds = f.openDataSet(path);
  std::vector<double> v(static_cast<std::size_t>(ds.getSpace().getSimpleExtentNpoints()));
  ds.read(v.data(), H5::PredType::NATIVE_DOUBLE);
  return v;
}

// Creation/modification times of an object (0 when not tracked).
H5O_info_t times_of(const H5::H5File& f, const std::string& path) {
  H5O_info_t info;
  EXPECT_GE(H5Oget_info_by_name2(f.getId(), path.c_str(), &info, H5O_INFO_TIME, H5P_DEFAULT), 0) << path;
  return info;
}

}  // namespace

TEST(Hdf5Writer, WritesWhatReadsBackAndNoTimes) {
  const colza::testing::ScratchDir dir;
  const auto file = dir / "result.h5";
  Table t({"time", "force"}, {"s", "N"});
  t.add_row({0.0, 1.5});
  t.add_row({1e-3, -2.25});
  ParticleArrays p;
  p.add(Vec3(0.1, 0.2, 0.3), 3e-3, 1250.0);
  p.add(Vec3(-0.1, 0.0, 0.05), 3.5e-3, 1250.0, 0, Vec3(1.0, 2.0, 3.0), Vec3(-4.0, 5.0, -6.0));
  {
    Hdf5Writer h5(file.string());
    write_provenance(h5, "oedometer", 7, "[oedometer]\n");
    h5.write_table("curve", t);
    h5.write_particles("particles/final", p);
    h5.close();
  }
  const H5::H5File f(file.string(), H5F_ACC_RDONLY);
  EXPECT_EQ(read_doubles(f, "/curve/force"), (std::vector<double>{1.5, -2.25}));
  EXPECT_EQ(read_doubles(f, "/particles/final/position"), (std::vector<double>{0.1, 0.2, 0.3, -0.1, 0.0, 0.05}));
  EXPECT_EQ(read_doubles(f, "/particles/final/angular_velocity"),
            (std::vector<double>{0.0, 0.0, 0.0, -4.0, 5.0, -6.0}));
  EXPECT_EQ(read_doubles(f, "/particles/final/radius"), (std::vector<double>{3e-3, 3.5e-3}));
  // Each dataset names its unit.
  const auto unit_of = [&](const std::string& path) {
    H5::Attribute a = f.openDataSet(path).openAttribute("units");
    std::string u;
    a.read(a.getStrType(), u);
    return u;
  };
  EXPECT_EQ(unit_of("/curve/time"), "s");
  EXPECT_EQ(unit_of("/curve/force"), "N");
  EXPECT_EQ(unit_of("/particles/final/velocity"), "m/s");
  EXPECT_EQ(unit_of("/particles/final/radius"), "m");
  std::int64_t seed = 0;
  f.openAttribute("seed").read(H5::PredType::NATIVE_INT64, &seed);
  EXPECT_EQ(seed, 7);
  for (const char* path : {"/", "/curve", "/curve/time", "/particles", "/particles/final", "/particles/final/velocity"}) {
    const H5O_info_t info = times_of(f, path);
    EXPECT_EQ(info.ctime, 0) << path;
    EXPECT_EQ(info.mtime, 0) << path;
    EXPECT_EQ(info.btime, 0) << path;
  }
}

TEST(Hdf5Writer, AConfigLongerThan64KiBIsKept) {
  // A scene listing ~1500 particles inline has a config of ~115 KB; HDF5's 1.6 file format
  // cannot hold an attribute over 64 KiB in an object header (colza aborted there after the run).
  const colza::testing::ScratchDir dir;
  const auto file = dir / "result.h5";
  std::string config;
  while (config.size() < 200000) config += "[[scene.particles]]\nposition = [0.01, 0.02, 0.03]\nradius = 0.003\n";
  {
    Hdf5Writer h5(file.string());
    write_provenance(h5, "scene", 1, config);
    h5.close();
  }
  const H5::H5File f(file.string(), H5F_ACC_RDONLY);
  H5::Attribute a = f.openAttribute("config_toml");
  std::string read_back;
  a.read(a.getStrType(), read_back);
  EXPECT_EQ(read_back, config);
}

TEST(Hdf5Writer, AnHdf5FailureIsAnErrorNamingTheFileNotAnAbort) {
  // HDF5's C++ exceptions do not derive from std::exception; the writer turns them into
  // Hdf5WriteError, which the CLI reports (exit 1) after removing its staging folder.
  const colza::testing::ScratchDir dir;
  const std::string file = (dir / "no-such-folder" / "result.h5").string();
  H5::Exception::dontPrint();
  try {
    Hdf5Writer h5(file);
    ADD_FAILURE() << "a file in a missing folder was created";
  } catch (const Hdf5WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write " + file), std::string::npos) << e.what();
  }
  Hdf5Writer h5((dir / "result.h5").string());
  h5.attribute("seed", std::int64_t{1});
  EXPECT_THROW(h5.attribute("seed", std::int64_t{2}), Hdf5WriteError);  // an attribute written twice
}

TEST(Hdf5Writer, EveryRecordedCurveHasAUnitPerColumn) {
  const Table scene = scene_table({0, 3}, 2, ContactModel{});
  ASSERT_EQ(scene.units.size(), scene.names.size());
  EXPECT_EQ(scene.units[2], "m");       // p0_x
  EXPECT_EQ(scene.units[5], "m/s");     // p0_vx
  EXPECT_EQ(scene.units.back(), "J");  // wall_work
  EXPECT_EQ(OedometerResult{}.curve.units.size(), OedometerResult{}.curve.names.size());
  EXPECT_EQ(ShearLoadResult{}.curve.units.size(), ShearLoadResult{}.curve.names.size());
}
