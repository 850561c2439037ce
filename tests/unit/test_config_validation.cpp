// Configuration validation (config/run_config.hpp, config/config_reader.hpp): every bad input
// is a ConfigError naming the key; the shipped data/oedometer.toml states exactly the built-in
// defaults.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "config/run_config.hpp"

#include "scratch_dir.hpp"

using namespace colza;

namespace {

// Runs `f`, expects a ConfigError and returns it.
template <class F>
ConfigError expect_config_error(F&& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a ConfigError";
  return ConfigError("", "", "");
}

ConfigError oedometer_error(const std::string& toml) {
  return expect_config_error([&] {
    read_run_config(Scenario::kOedometer, ConfigReader::from_string(toml, "test.toml"));
  });
}

}  // namespace

TEST(ConfigValidation, UnknownKeyIsNamed) {
  const ConfigError e = oedometer_error("[particle]\ndensty = 1250.0\n");
  EXPECT_EQ(e.key(), "particle.densty");
  EXPECT_EQ(e.file(), "test.toml");
  // An unknown top-level table too.
  EXPECT_EQ(oedometer_error("[partcle]\ndensity = 1.0\n").key(), "partcle.density");
}

TEST(ConfigValidation, WrongTypeIsNamed) {
  const ConfigError e = oedometer_error("[particle]\ndensity = \"heavy\"\n");
  EXPECT_EQ(e.key(), "particle.density");
  EXPECT_NE(e.reason().find("number"), std::string::npos) << e.reason();
  // A table where a number is expected and vice versa.
  EXPECT_EQ(oedometer_error("particle = 3\n").key(), "particle");
  EXPECT_EQ(oedometer_error("[sample]\ncount = 2.5\n").key(), "sample.count");
}

TEST(ConfigValidation, NegativeStiffnessIsNamed) {
  EXPECT_EQ(oedometer_error("[particle]\nnormal_stiffness = -437e3\n").key(), "particle.normal_stiffness");
  EXPECT_EQ(oedometer_error("[wall]\nshear_stiffness = 0.0\n").key(), "wall.shear_stiffness");
  EXPECT_EQ(oedometer_error("[wall]\nfriction = -0.1\n").key(), "wall.friction");
}

TEST(ConfigValidation, ASettlingCriterionAboveTheSphereWeightIsRefused) {
  // Mean weight rho g (pi / 6) E[d^3], E[d^3] = (dmax^4 - dmin^4) / (4 (dmax - dmin)).
  // A density in g/cm^3: 1.25 kg/m^3, 6-7 mm: E[d^3] = (7^4 - 6^4) / 4 mm^3 = 276.25e-9 m^3,
  // weight 1.25 x 9.81 x 0.5236 x 276.25e-9 = 1.77e-6 N, far below the oedometer's 1e-4 N.
  const ConfigError e = oedometer_error("[particle]\ndensity = 1.25\n");
  EXPECT_EQ(e.key(), "sample.settle_unbalanced_force");
  EXPECT_NE(e.reason().find("0.0001 N is not below the weight of a sphere of the mean size, 1.77e-06 N"),
            std::string::npos) << e.reason();
  EXPECT_NE(e.reason().find("particle.density 1.25 kg/m^3"), std::string::npos) << e.reason();
  // 4.5-5.5 mm seeds of 1230 kg/m^3 at the shear box's 1e-3 N: E[d^3] = (5.5^4 - 4.5^4) / 4
  // mm^3 = 126.25e-9 m^3, weight 1230 x 9.81 x 0.5236 x 126.25e-9 = 7.98e-4 N: refused. The
  // paper's 6-7 mm seeds weigh 1.75e-3 N: accepted.
  const std::string small_seeds = "[particle]\ndensity = 1230.0\ndiameter_min = 0.0045\ndiameter_max = 0.0055\n"
                                  "[sample]\nsettle_unbalanced_force = 1e-3\n";
  const ConfigError shear = expect_config_error(
      [&] { read_run_config(Scenario::kShear, ConfigReader::from_string(small_seeds, "s.toml")); });
  EXPECT_EQ(shear.key(), "sample.settle_unbalanced_force");
  EXPECT_NE(shear.reason().find("0.000798 N"), std::string::npos) << shear.reason();
  EXPECT_NO_THROW(read_run_config(
      Scenario::kShear,
      ConfigReader::from_string("[particle]\ndensity = 1230.0\n[sample]\nsettle_unbalanced_force = 1e-3\ncount = 12800\n",
                                "s.toml")));
  // A run from a packing file does not settle: SmallOedometer.ASettlingCriterionIsNotJudgedWithoutSettling.
}

TEST(ConfigValidation, DiameterOrder) {
  const ConfigError e = oedometer_error("[particle]\ndiameter_min = 0.008\ndiameter_max = 0.007\n");
  EXPECT_EQ(e.key(), "particle.diameter_min");
  // Equal diameters are allowed (monodisperse).
  EXPECT_NO_THROW(read_run_config(Scenario::kOedometer,
                                  ConfigReader::from_string("[particle]\ndiameter_min = 0.007\ndiameter_max = 0.007\n",
                                                            "test.toml")));
}

TEST(ConfigValidation, OtherRangeAndChoiceErrors) {
  EXPECT_EQ(oedometer_error("[integration]\ndamping = 1.5\n").key(), "integration.damping");
  EXPECT_EQ(oedometer_error("[integration]\ndamping_form = \"viscous\"\n").key(), "integration.damping_form");
  EXPECT_EQ(oedometer_error("[integration]\ntime_step = \"fast\"\n").key(), "integration.time_step");
  EXPECT_EQ(oedometer_error("[integration]\ntime_step = -1e-6\n").key(), "integration.time_step");
  EXPECT_EQ(oedometer_error("[integration]\ngravity = [0.0, -9.81]\n").key(), "integration.gravity");
  EXPECT_EQ(oedometer_error("[contact]\nstiffness_rule = \"parallel\"\n").key(), "contact.stiffness_rule");
  EXPECT_EQ(oedometer_error("[contact]\nwall_friction = \"pfc\"\n").key(), "contact.wall_friction");
  EXPECT_EQ(oedometer_error("[contact]\nbond = \"glue\"\n").key(), "contact.bond");
  EXPECT_EQ(oedometer_error("[contact.contact_bond]\nnormal_strength = -1.0\n[contact]\nbond = \"contact_bond\"\n").key(),
            "contact.contact_bond.normal_strength");
  EXPECT_EQ(oedometer_error("scenario = \"scene\"\n").key(), "scenario");
  EXPECT_EQ(oedometer_error("[oedometer]\nfit_force_min = 3e4\nfit_force_max = 2e4\n").key(), "oedometer.fit_force_min");
  // TOML syntax error: no key, the reason names the line.
  const ConfigError e = oedometer_error("[particle]\ndensity = = 3\n");
  EXPECT_EQ(e.key(), "");
  EXPECT_NE(e.reason().find("line 2"), std::string::npos) << e.reason();
}

TEST(ConfigValidation, BondGapMustBeBelowTheSkin) {
  // Bonds are put on candidate pairs, and only pairs closer than the Verlet skin are sure to
  // be candidates (install_bonds, scenario/bonds.hpp).
  const ConfigError e = oedometer_error(
      "[contact]\nbond = \"contact_bond\"\nbond_gap = 0.0005\n[integration]\nverlet_skin = 0.0005\n");
  EXPECT_EQ(e.key(), "contact.bond_gap");
  EXPECT_NE(e.reason().find("integration.verlet_skin"), std::string::npos) << e.reason();
  // Both values are printed, since either may come from --set.
  EXPECT_NE(e.reason().find("0.0005 m must be below integration.verlet_skin = 0.0005 m"), std::string::npos)
      << e.reason();
  // Below the skin it stands; without bonds, or with bonds formed on new contacts (no gap
  // is used), any gap stands.
  const auto reads = [](const std::string& toml) {
    return read_run_config(Scenario::kOedometer, ConfigReader::from_string(toml, "test.toml"));
  };
  EXPECT_NO_THROW(reads("[contact]\nbond = \"contact_bond\"\nbond_gap = 0.0004\n"));
  EXPECT_NO_THROW(reads("[contact]\nbond = \"none\"\nbond_gap = 0.001\n"));
  EXPECT_NO_THROW(reads("[contact]\nbond = \"contact_bond\"\nbond_install = \"on_new_contacts\"\nbond_gap = 0.001\n"));
}

TEST(ConfigValidation, MissingPackingFileOfASceneIsNamed) {
  const colza::testing::ScratchDir dir;
  const std::string cfg = dir.write("scene.toml",
                                    "scenario = \"scene\"\n"
                                    "[integration]\ntime_step = 1e-6\n"
                                    "[scene]\nsteps = 10\npacking_file = \"no_such_packing.txt\"\n");
  const ConfigError e = expect_config_error([&] { load_run_config(Scenario::kScene, cfg, {}); });
  EXPECT_EQ(e.key(), "scene.packing_file");
  // The relative path is resolved next to the config file.
  EXPECT_EQ(std::filesystem::path(e.file()), dir / "no_such_packing.txt");

  // With the file present the scene reads it ("x y z r" per line).
  dir.write("no_such_packing.txt", "# x y z r\n0.0 0.0 0.01 0.003\n0.0 0.0 0.02 0.0035\n");
  const RunConfig c = load_run_config(Scenario::kScene, cfg, {});
  ASSERT_EQ(c.scene.particles.size(), 2u);
  EXPECT_EQ(c.scene.particles[1].radius, 0.0035);
  EXPECT_EQ(c.integration.time_step, 1e-6);
  EXPECT_FALSE(c.integration.automatic_time_step);
}

TEST(ConfigValidation, PackingLinesWithMoreThanFourNumbersAndFoldersAreRefused) {
  const colza::testing::ScratchDir dir;
  const std::string cfg = dir.write("scene.toml",
                                    "scenario = \"scene\"\n"
                                    "[integration]\ntime_step = 1e-6\n"
                                    "[scene]\nsteps = 10\npacking_file = \"p.txt\"\n");
  for (const char* bad : {"0 0 0.01 0.003mm\n", "0 0 0.01 0.003 99\n"}) {
    dir.write("p.txt", std::string("# x y z r\n") + bad);
    const ConfigError e = expect_config_error([&] { load_run_config(Scenario::kScene, cfg, {}); });
    EXPECT_EQ(e.key(), "scene.packing_file");
    EXPECT_NE(e.reason().find("line 2: expected four numbers"), std::string::npos) << e.what();
  }
  std::filesystem::remove(dir / "p.txt");
  std::filesystem::create_directory(dir / "p.txt");
  const ConfigError e = expect_config_error([&] { load_run_config(Scenario::kScene, cfg, {}); });
  EXPECT_NE(e.reason().find("is a directory, not a file"), std::string::npos) << e.what();
}

TEST(ConfigValidation, SceneSpheresAtOneCentreAndMissingRadiusAreRefused) {
  const colza::testing::ScratchDir dir;
  const std::string head = "scenario = \"scene\"\n[integration]\ntime_step = 1e-6\n[scene]\nsteps = 10\n";
  const std::string twice = dir.write("twice.toml", head + "packing_file = \"p.txt\"\n"
                                                          "[[scene.particles]]\nposition = [0.0, 0.0, 0.02]\nradius = 0.003\n");
  dir.write("p.txt", "0 0 0.01 0.003\n0 0 0.02 0.003\n");
  ConfigError e = expect_config_error([&] { load_run_config(Scenario::kScene, twice, {}); });
  EXPECT_EQ(e.key(), "scene.packing_file");
  EXPECT_NE(e.reason().find("particles[0] and line 2 of " + (dir / "p.txt").string() + " have the same centre"),
            std::string::npos)
      << e.what();
  const std::string no_radius = dir.write("no_radius.toml", head + "[[scene.particles]]\nposition = [0.0, 0.0, 0.02]\n");
  e = expect_config_error([&] { load_run_config(Scenario::kScene, no_radius, {}); });
  EXPECT_EQ(e.key(), "scene.particles[0].radius");
  EXPECT_EQ(e.reason(), "is required (the sphere's radius, m)");
  // A misspelt key is named beside the missing one (it would be reported as unknown only
  // after the required one).
  const std::string misspelt =
      dir.write("radus.toml", head + "[[scene.particles]]\nposition = [0.0, 0.0, 0.02]\nradus = 0.003\n");
  e = expect_config_error([&] { load_run_config(Scenario::kScene, misspelt, {}); });
  EXPECT_EQ(e.reason(), "is required (the sphere's radius, m) (the table has 'radus': misspelt?)");
}

TEST(ConfigValidation, SetTrimsSpacesAndTheBoxWidthNamesTheDiameter) {
  // "--set 'particle.friction = 0.3'": the spaces are not part of the key or the value.
  const RunConfig c = load_run_config(Scenario::kOedometer, "", {"particle.friction = 0.3"});
  EXPECT_EQ(c.particle.friction, 0.3);
  // Diameters in mm on the shear box: the error gives both lengths and the unit.
  const ConfigError e = expect_config_error([&] {
    load_run_config(Scenario::kShear, "", {"particle.diameter_min=6.0", "particle.diameter_max=7.0"});
  });
  EXPECT_EQ(e.key(), "shear_box.length");
  EXPECT_NE(e.reason().find("must exceed particle.diameter_max, 7 m"), std::string::npos) << e.reason();
  EXPECT_NE(e.reason().find("lengths are in metres"), std::string::npos) << e.reason();
}

TEST(ConfigValidation, AnInactiveContactLawsTableIsCheckedToo) {
  // bond = "none", yet [contact.contact_bond] is read: a misspelt key or a bad value there is
  // an error now, not when the bond is switched on.
  ConfigError e = oedometer_error("[contact]\nbond = \"none\"\n[contact.contact_bond]\nnormal_strenght = 1.0\n");
  EXPECT_EQ(e.key(), "contact.contact_bond.normal_strenght");
  e = oedometer_error("[contact]\nbond = \"none\"\n[contact.contact_bond]\nnormal_strength = -1.0\n");
  EXPECT_EQ(e.key(), "contact.contact_bond.normal_strength");
}

TEST(ConfigValidation, MissingPackingFileOfTheOedometerIsNamed) {
  const colza::testing::ScratchDir dir;
  const std::string cfg = dir.write("oed.toml", "[oedometer]\npacking_file = \"settled.txt\"\n");
  const ConfigError e = expect_config_error([&] { load_run_config(Scenario::kOedometer, cfg, {}); });
  EXPECT_EQ(e.key(), "oedometer.packing_file");
}

TEST(ConfigValidation, ShearBoxGeometryErrorsAreNamed) {
  const auto shear_error = [](const std::string& toml) {
    return expect_config_error(
        [&] { read_run_config(Scenario::kShear, ConfigReader::from_string(toml, "shear.toml")); });
  };
  EXPECT_EQ(shear_error("[shear_box]\nshear_plane = 0.09\n").key(), "shear_box.shear_plane");
  EXPECT_EQ(shear_error("[shear_box]\nnormal_stresses = [25.75e3, -1.0]\n").key(), "shear_box.normal_stresses");
  EXPECT_EQ(shear_error("[shear_box]\nlenght = 0.2\n").key(), "shear_box.lenght");
  // Each load of a series writes to load-<sigma>Pa (to the nearest pascal): a load given twice,
  // or two loads less than 1 Pa apart, would share that directory.
  for (const char* loads : {"[25.75e3, 43.5e3, 25.75e3]", "[78750.2, 78750.4]"}) {
    const ConfigError e = shear_error(std::string("[shear_box]\nnormal_stresses = ") + loads + "\n");
    EXPECT_EQ(e.key(), "shear_box.normal_stresses") << loads;
    EXPECT_NE(std::string(e.what()).find("share the results directory load-"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(read_run_config(Scenario::kShear,
                                  ConfigReader::from_string("[shear_box]\nnormal_stresses = [78750.0, 78751.0]\n", "s.toml")));
  // The defaults are valid: physics.md section 4 (200 x 200 x 80 mm, shear plane at 40 mm,
  // four normal stresses 25.75 ... 78.75 kPa, 300 mm/min to 30 mm).
  const RunConfig c = read_run_config(Scenario::kShear, ConfigReader::empty());
  EXPECT_EQ(c.shear_box.length, 0.200);
  EXPECT_EQ(c.shear_box.width, 0.200);
  EXPECT_EQ(c.shear_box.height, 0.080);
  EXPECT_EQ(c.shear_box.shear_plane, 0.040);
  EXPECT_EQ(c.shear_box.normal_stresses, (std::vector<double>{25.75e3, 43.50e3, 61.00e3, 78.75e3}));
  EXPECT_NEAR(c.shear_box.shear_speed, 0.3 / 60.0, 1e-18);
  EXPECT_EQ(c.shear_box.shear_displacement, 0.030);
}

TEST(ConfigValidation, SceneNeedsAnExplicitTimeStep) {
  const ConfigError e = expect_config_error([&] {
    read_run_config(Scenario::kScene, ConfigReader::from_string("[scene]\nsteps = 10\n", "s.toml"));
  });
  EXPECT_EQ(e.key(), "integration.time_step");
}

TEST(ConfigValidation, OverrideErrorsNameSet) {
  // Malformed assignment.
  const ConfigError a = expect_config_error([] { load_run_config(Scenario::kOedometer, "", {"particle.density"}); });
  EXPECT_EQ(a.file(), "--set");
  // A bad value given on the command line: the error's origin is the override.
  const ConfigError b = expect_config_error([] { load_run_config(Scenario::kOedometer, "", {"particle.density=-5"}); });
  EXPECT_EQ(b.key(), "particle.density");
  EXPECT_EQ(b.file().rfind("--set", 0), 0u) << b.file();
  // A misspelt key on the command line.
  const ConfigError c = expect_config_error([] { load_run_config(Scenario::kOedometer, "", {"particle.densty=1250"}); });
  EXPECT_EQ(c.key(), "particle.densty");
  EXPECT_EQ(c.file().rfind("--set", 0), 0u) << c.file();
  // Overriding through a non-table.
  const ConfigError d =
      expect_config_error([] { load_run_config(Scenario::kOedometer, "", {"seed=3", "seed.x=1"}); });
  EXPECT_EQ(d.file(), "--set");
  // A valid override is applied.
  EXPECT_EQ(load_run_config(Scenario::kOedometer, "", {"particle.density=1230"}).particle.density, 1230.0);
  EXPECT_EQ(load_run_config(Scenario::kOedometer, "", {"integration.damping_form=yade"}).integration.damping_form,
            DampingForm::kYade);
}

TEST(ConfigValidation, MissingConfigFile) {
  const ConfigError e =
      expect_config_error([] { load_run_config(Scenario::kOedometer, "/nonexistent/colza/cfg.toml", {}); });
  EXPECT_EQ(e.file(), "/nonexistent/colza/cfg.toml");
}

// ---- data/oedometer.toml == built-in defaults ---------------------------------------

namespace {

void expect_same_numbers(const RunConfig& a, const RunConfig& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.particle.density, b.particle.density);
  EXPECT_EQ(a.particle.normal_stiffness, b.particle.normal_stiffness);
  EXPECT_EQ(a.particle.shear_stiffness, b.particle.shear_stiffness);
  EXPECT_EQ(a.particle.friction, b.particle.friction);
  EXPECT_EQ(a.particle.diameter_min, b.particle.diameter_min);
  EXPECT_EQ(a.particle.diameter_max, b.particle.diameter_max);
  EXPECT_EQ(a.wall.normal_stiffness, b.wall.normal_stiffness);
  EXPECT_EQ(a.wall.shear_stiffness, b.wall.shear_stiffness);
  EXPECT_EQ(a.wall.friction, b.wall.friction);
  EXPECT_EQ(a.stiffness_rule, b.stiffness_rule);
  EXPECT_EQ(a.contact.normal.index(), b.contact.normal.index());
  EXPECT_EQ(a.contact.tangential.index(), b.contact.tangential.index());
  EXPECT_EQ(a.contact.bond.index(), b.contact.bond.index());
  EXPECT_EQ(a.contact.bond_install, b.contact.bond_install);
  EXPECT_EQ(a.contact.bond_gap, b.contact.bond_gap);
  EXPECT_EQ(a.integration.damping, b.integration.damping);
  EXPECT_EQ(a.integration.damping_form, b.integration.damping_form);
  EXPECT_EQ(a.integration.gravity, b.integration.gravity);
  EXPECT_EQ(a.integration.automatic_time_step, b.integration.automatic_time_step);
  EXPECT_EQ(a.integration.time_step, b.integration.time_step);
  EXPECT_EQ(a.integration.safety_factor, b.integration.safety_factor);
  EXPECT_EQ(a.integration.recompute_interval, b.integration.recompute_interval);
  EXPECT_EQ(a.integration.verlet_skin, b.integration.verlet_skin);
  EXPECT_EQ(a.sample.count, b.sample.count);
  EXPECT_EQ(a.sample.settle_unbalanced_force, b.sample.settle_unbalanced_force);
  EXPECT_EQ(a.sample.settle_max_time, b.sample.settle_max_time);
  EXPECT_EQ(a.sample.settle_check_interval, b.sample.settle_check_interval);
  EXPECT_EQ(a.sample.max_placement_attempts, b.sample.max_placement_attempts);
  EXPECT_EQ(a.oedometer.cylinder_diameter, b.oedometer.cylinder_diameter);
  EXPECT_EQ(a.oedometer.cylinder_height, b.oedometer.cylinder_height);
  EXPECT_EQ(a.oedometer.generation_height, b.oedometer.generation_height);
  EXPECT_EQ(a.oedometer.piston_speed, b.oedometer.piston_speed);
  EXPECT_EQ(a.oedometer.stop_force, b.oedometer.stop_force);
  EXPECT_EQ(a.oedometer.max_piston_travel, b.oedometer.max_piston_travel);
  EXPECT_EQ(a.oedometer.record_interval, b.oedometer.record_interval);
  EXPECT_EQ(a.oedometer.fit_force_min, b.oedometer.fit_force_min);
  EXPECT_EQ(a.oedometer.fit_force_max, b.oedometer.fit_force_max);
  EXPECT_EQ(a.oedometer.packing_file, b.oedometer.packing_file);
}

}  // namespace

TEST(ConfigDefaults, DataFileEqualsBuiltInDefaults) {
  const std::string file = std::string(COLZA_SOURCE_DIR) + "/data/oedometer.toml";
  const RunConfig from_file = load_run_config(Scenario::kOedometer, file, {});
  const RunConfig builtin = load_run_config(Scenario::kOedometer, "", {});
  const RunConfig member_defaults{};
  expect_same_numbers(from_file, builtin, "data/oedometer.toml vs load_run_config(\"\")");
  expect_same_numbers(from_file, member_defaults, "data/oedometer.toml vs RunConfig{}");
}

// The configuration stored with a result (result.h5's config_toml, a design run's
// config.toml) states every value the run used, defaults included: a run of the built-in
// defaults stores what a run of data/oedometer.toml stores (the file's title, and its
// [contact.contact_bond] table, inactive with bond = "none", aside), and loading the stored
// text gives the same configuration and the same text again.
TEST(ConfigDefaults, ResolvedTextStatesEveryValueUsed) {
  const std::string file = std::string(COLZA_SOURCE_DIR) + "/data/oedometer.toml";
  const RunConfig from_file = load_run_config(Scenario::kOedometer, file, {});
  const RunConfig builtin = load_run_config(Scenario::kOedometer, "", {});
  toml::table a = toml::parse(from_file.resolved_toml), b = toml::parse(builtin.resolved_toml);
  for (toml::table* t : {&a, &b}) {
    t->erase("title");
    t->erase("provenance");
  }
  a["contact"].as_table()->erase("contact_bond");
  EXPECT_TRUE(a == b) << "data/oedometer.toml:\n" << a << "\n\nbuilt-in:\n" << b;
  EXPECT_EQ(b["integration"]["time_step"].value_or(std::string()), "auto");
  const RunConfig again = read_run_config(Scenario::kOedometer, ConfigReader::from_string(builtin.resolved_toml, "r.toml"));
  expect_same_numbers(again, builtin, "the built-in defaults' resolved text, read back");
  EXPECT_EQ(again.resolved_toml, builtin.resolved_toml);
  // The shear box's loads, read only when given, are stated too.
  const RunConfig shear = read_run_config(Scenario::kShear, ConfigReader::from_string("", "s.toml"));
  const toml::table s = toml::parse(shear.resolved_toml);
  ASSERT_TRUE(s["shear_box"]["normal_stresses"].is_array()) << s;
  EXPECT_EQ(s["shear_box"]["normal_stresses"].as_array()->size(), shear.shear_box.normal_stresses.size());
}

TEST(ConfigDefaults, DefaultsAreThePapersTable1) {
  // physics.md section 5, Table 1 column, and section 4 (oedometer geometry and speed).
  const RunConfig c = load_run_config(Scenario::kOedometer, "", {});
  EXPECT_EQ(c.particle.density, 1250.0);
  EXPECT_EQ(c.particle.normal_stiffness, 437e3);
  EXPECT_EQ(c.particle.shear_stiffness, 100e3);
  EXPECT_EQ(c.particle.friction, 0.20);
  EXPECT_EQ(c.particle.diameter_min, 6e-3);
  EXPECT_EQ(c.particle.diameter_max, 7e-3);
  EXPECT_EQ(c.wall.normal_stiffness, 4000e3);
  EXPECT_EQ(c.wall.shear_stiffness, 1000e3);
  EXPECT_EQ(c.wall.friction, 0.23);
  EXPECT_EQ(c.integration.damping, 0.7);
  EXPECT_EQ(c.stiffness_rule, StiffnessRule::kSeries);
  EXPECT_TRUE(std::holds_alternative<NoBond>(c.contact.bond));
  EXPECT_EQ(c.oedometer.cylinder_diameter, 0.100);
  EXPECT_EQ(c.oedometer.cylinder_height, 0.080);
  EXPECT_EQ(c.oedometer.generation_height, 0.200);
  // 500 mm/min = 0.5 m / 60 s.
  EXPECT_NEAR(c.oedometer.piston_speed, 0.5 / 60.0, 1e-18);
  EXPECT_EQ(c.oedometer.fit_force_min, 150.0);
  EXPECT_EQ(c.oedometer.fit_force_max, 29.3e3);
  EXPECT_EQ(c.sample.settle_unbalanced_force, 1e-4);
  EXPECT_EQ(c.integration.gravity, Vec3(0.0, 0.0, -9.81));
}

TEST(ConfigDefaults, MakePhysicsCarriesTheNumbers) {
  RunConfig c = load_run_config(Scenario::kOedometer, "",
                                {"integration.time_step=2e-6", "contact.bond=contact_bond",
                                 "contact.contact_bond.normal_strength=1.1", "contact.contact_bond.shear_strength=3.2"});
  const PhysicsSettings ph = make_physics(c);
  ASSERT_EQ(ph.particle_materials.size(), 1u);
  ASSERT_EQ(ph.wall_materials.size(), 1u);
  EXPECT_EQ(ph.particle_materials[0].kn, 437e3);
  EXPECT_EQ(ph.wall_materials[0].friction, 0.23);
  EXPECT_FALSE(ph.time_step.automatic);
  EXPECT_EQ(ph.time_step.fixed_dt, 2e-6);
  ASSERT_TRUE(std::holds_alternative<ContactBond>(ph.model.bond));
  EXPECT_EQ(std::get<ContactBond>(ph.model.bond).normal_strength, 1.1);
  EXPECT_EQ(std::get<ContactBond>(ph.model.bond).shear_strength, 3.2);
  EXPECT_EQ(ph.model.bond_install, BondInstallMoment::kBeforeLoading);
  EXPECT_EQ(ph.skin, 0.5e-3);
}

TEST(ConfigValidation, WallFrictionRule) {
  // Default: the wall's own mu_pw (physics.md); "min": PFC3D 4's min(mu_pp, mu_pw).
  EXPECT_EQ(read_run_config(Scenario::kOedometer, ConfigReader::from_string("", "a.toml")).wall_friction,
            WallFrictionRule::kOwn);
  const RunConfig c =
      read_run_config(Scenario::kOedometer, ConfigReader::from_string("[contact]\nwall_friction = \"min\"\n", "b.toml"));
  EXPECT_EQ(c.wall_friction, WallFrictionRule::kMinimum);
  EXPECT_EQ(make_physics(c).wall_friction, WallFrictionRule::kMinimum);
}

namespace {
ConfigError shear_error(const std::vector<std::string>& sets) {
  return expect_config_error([&] { load_run_config(Scenario::kShear, "", sets); });
}
}  // namespace

// A generated sample too shallow for its test is refused before the run, naming what is most
// likely wrong (a walk-through's runs: a 100-sphere shear box whose plate came to rest below
// the shear plane, a box of 60 m, cylinders of 1 and 100 m). The bound: count x mean sphere
// volume / (0.45 x floor area); the paper's defaults and the small test configs pass.
TEST(ConfigValidation, ASampleTooShallowForItsTestIsRefused) {
  EXPECT_NO_THROW(load_run_config(Scenario::kOedometer, "", {}));
  // The shear box's built-in count is data/shear.toml's 12800 (the oedometer's 2600 would
  // settle at most 20.9 mm deep, below its shear plane).
  EXPECT_EQ(load_run_config(Scenario::kShear, "", {}).sample.count, 12800);
  EXPECT_NO_THROW(load_run_config(Scenario::kShear, "", {"sample.count=2600", "shear_box.shear_plane=0.01"}));
  // 20 spheres of 6-7 mm (mean volume pi/6 x 276.25 mm^3 = 144.6 mm^3) in the 100 mm cylinder:
  // 20 x 144.6 / (0.45 x 7854) = 0.819 mm, below three layers (21 mm).
  ConfigError e = expect_config_error([] { load_run_config(Scenario::kOedometer, "", {"sample.count=20"}); });
  EXPECT_EQ(e.key(), "sample.count");
  EXPECT_NE(e.reason().find("settle at most 0.819 mm deep"), std::string::npos) << e.reason();
  // A cylinder of 100 m: its diameter is named, with the unit.
  e = expect_config_error([] { load_run_config(Scenario::kOedometer, "", {"oedometer.cylinder_diameter=100"}); });
  EXPECT_EQ(e.key(), "oedometer.cylinder_diameter");
  EXPECT_NE(e.reason().find("lengths are in metres"), std::string::npos) << e.reason();
  // The shear box (200 x 200 mm, shear plane at 40 mm): 1000 spheres stand at most 8.03 mm.
  e = shear_error({"sample.count=1000"});
  EXPECT_EQ(e.key(), "sample.count");
  EXPECT_NE(e.reason().find("not a layer above the shear plane at 40 mm"), std::string::npos) << e.reason();
  EXPECT_EQ(shear_error({"shear_box.width=200"}).key(), "shear_box.width");
  // A packing file is checked as read, not by this bound.
}

TEST(ConfigValidation, AShearDisplacementPastTheBoxIsRefused) {
  // 30 (mm typed for m) would have sheared for ~1e8 steps.
  const ConfigError e = shear_error({"shear_box.shear_displacement=30"});
  EXPECT_EQ(e.key(), "shear_box.shear_displacement");
  EXPECT_NE(e.reason().find("must be below shear_box.length, 0.2 m"), std::string::npos) << e.reason();
}
