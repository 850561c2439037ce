// The cross-check's tolerances file is checked before anything runs
// (crosscheck/tolerances.hpp): the shipped file passes for every command; a misspelt key, a
// value of the wrong type or range, or a section the command needs that is missing is a
// ToleranceError naming the key.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "crosscheck/tolerances.hpp"
#include "scratch_dir.hpp"

namespace {

using crosscheck::read_tolerances;
using crosscheck::ToleranceError;

const std::string kSource = COLZA_SOURCE_DIR;
const std::string kShipped = kSource + "/data/crosscheck-tolerances.toml";

std::string shipped_text() {
  std::ifstream in(kShipped);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The message of the ToleranceError that reading `text` for `command` raises ("" if none).
std::string error_of(const colza::testing::ScratchDir& dir, const std::string& text, const std::string& command,
                     const std::string& size = "small") {
  const std::string file = dir.write("tol.toml", text);
  try {
    read_tolerances(file, command, size, kSource);
  } catch (const ToleranceError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(CrosscheckTolerances, TheShippedFilePassesForEveryCommand) {
  for (const char* command : {"micro", "oedometer", "shear", "all"})
    for (const char* size : {"small", "full"}) EXPECT_NO_THROW(read_tolerances(kShipped, command, size, kSource));
}

TEST(CrosscheckTolerances, MisspeltKeysWrongTypesAndRangesAreNamed) {
  const colza::testing::ScratchDir dir;
  const std::string text = shipped_text();
  std::string e = error_of(dir, replaced(text, "rms_relative = 0.15", "rms_relativ = 0.15"), "oedometer");
  EXPECT_NE(e.find("key 'oedometer.small.rms_relativ': unknown key"), std::string::npos) << e;
  e = error_of(dir, replaced(text, "ensemble_realisations = 12", "ensemble_realisations = 12.5"), "shear");
  EXPECT_NE(e.find("key 'shear.small.ensemble_realisations': must be a whole number"), std::string::npos) << e;
  e = error_of(dir, replaced(text, "ensemble_alpha = 0.01", "ensemble_alpha = 1.5"), "oedometer");
  EXPECT_NE(e.find("key 'oedometer.small.ensemble_alpha': must be between 0 and 1"), std::string::npos) << e;
  e = error_of(dir, replaced(text, "force = 1e-12", "force = \"tiny\""), "micro");
  EXPECT_NE(e.find("key 'micro.floor.force': must be a number"), std::string::npos) << e;
  e = error_of(dir, replaced(text, "[shear.full]", "[shear.ful]"), "micro");
  EXPECT_NE(e.find("key 'shear.ful': unknown size"), std::string::npos) << e;
  e = error_of(dir, replaced(text, "loads = [25.75e3, 78.75e3]", "loads = [25.75e3, -1.0]"), "shear");
  EXPECT_NE(e.find("key 'shear.small.loads': must be a list of numbers > 0"), std::string::npos) << e;
  // Two loads the same to the pascal would share their run folders (load_run_name).
  e = error_of(dir, replaced(text, "loads = [25.75e3, 78.75e3]", "loads = [25750, 25750.3]"), "shear");
  EXPECT_NE(e.find("key 'shear.small.loads': loads 25750 and 25750.3 Pa are the same to the pascal"),
            std::string::npos)
      << e;
  // A strength window out of order or past the shear's end, and travels in mm: refused before
  // any run (each used to run the whole ensemble and fail every row).
  e = error_of(dir, replaced(text, "strength_window_start = 0.002", "strength_window_start = 0.005"), "shear");
  EXPECT_NE(e.find("key 'shear.full.strength_window_end': must be above strength_window_start (0.005 m), got"),
            std::string::npos) << e;
  e = error_of(dir, replaced(text, "strength_window_end = 0.004", "strength_window_end = 0.006"), "shear");
  EXPECT_NE(e.find("key 'shear.full.strength_window_end': must be at most shear_displacement (0.004 m), got 0.006 m"),
            std::string::npos) << e;
  e = error_of(dir, replaced(text, "travels = [0.005, 0.006, 0.007]", "travels = [5, 6, 7]"), "oedometer");
  EXPECT_NE(e.find("key 'oedometer.small.travels': a travel of 5 m is more than"), std::string::npos) << e;
  // Loads in kPa (a walk-through's --loads 25.75,78.75 ran 0.03 kPa loads): refused, as --loads.
  e = error_of(dir, replaced(text, "loads = [25.75e3, 78.75e3]", "loads = [25.75, 78.75]"), "shear");
  EXPECT_NE(e.find("key 'shear.small.loads': 25.75 Pa is below a lab shear box's least normal stress (100 Pa)"),
            std::string::npos) << e;
  e = error_of(dir, replaced(text, "loads = [25.75e3, 78.75e3]", ""), "shear");
  EXPECT_NE(e.find("key 'shear.small.loads': missing"), std::string::npos) << e;
}

// A file the command needs that is not in the source tree (a misspelt config or scene) is bad
// usage before any run, naming the key; it was a FAIL row, exit 1, after the other runs. A
// section the command does not run is not looked at.
TEST(CrosscheckTolerances, FilesTheCommandNeedsMustBeInTheSourceTree) {
  const colza::testing::ScratchDir dir;
  const std::string text = shipped_text();
  const std::string misspelt_config =
      replaced(text, "config = \"crosscheck/scenes/shear_small.toml\"", "config = \"crosscheck/scenes/shear_smal.toml\"");
  std::string e = error_of(dir, misspelt_config, "shear");
  EXPECT_NE(e.find("key 'shear.small.config': names " + kSource + "/crosscheck/scenes/shear_smal.toml, which is not a file"),
            std::string::npos)
      << e;
  EXPECT_EQ(error_of(dir, misspelt_config, "oedometer"), "");
  e = error_of(dir, replaced(text, "settle_config = \"data/oedometer.toml\"", "settle_config = \"data\""), "oedometer",
               "full");
  EXPECT_NE(e.find("key 'oedometer.full.settle_config': names " + kSource + "/data, which is not a file"),
            std::string::npos)
      << e;
  e = error_of(dir, replaced(text, "micro_tangential = 1e-6", "micro_tangental = 1e-6"), "micro");
  EXPECT_NE(e.find("key 'micro.scenes.micro_tangental': names " + kSource +
                   "/crosscheck/scenes/micro_tangental.toml, which is not a file"),
            std::string::npos)
      << e;
}

// The oedometer's ensemble judges the mean forces at `travels` only: without them its runs
// would judge no row (and pass), so the file is refused; a single run needs no travels.
TEST(CrosscheckTolerances, AnOedometerEnsembleNeedsTravels) {
  const colza::testing::ScratchDir dir;
  const std::string text = shipped_text();
  const std::string travels = "travels = [0.005, 0.006, 0.007]";
  const std::string no_travels = replaced(text, travels, "");
  std::string e = error_of(dir, no_travels, "oedometer");
  EXPECT_NE(e.find("tol.toml: key 'oedometer.small.travels': missing: with ensemble_realisations = 8"),
            std::string::npos)
      << e;
  e = error_of(dir, replaced(text, travels, "travels = []"), "oedometer");
  EXPECT_NE(e.find("key 'oedometer.small.travels': must be a list of numbers > 0"), std::string::npos) << e;
  EXPECT_EQ(error_of(dir, replaced(no_travels, "ensemble_realisations = 8", "ensemble_realisations = 1"), "oedometer"),
            "");
}

TEST(CrosscheckTolerances, ASectionTheCommandNeedsMustBeThere) {
  const colza::testing::ScratchDir dir;
  const std::string no_full_shear = shipped_text().substr(0, shipped_text().find("[shear.full]"));
  EXPECT_EQ(error_of(dir, no_full_shear, "shear", "small"), "");
  const std::string e = error_of(dir, no_full_shear, "all", "full");
  EXPECT_NE(e.find("key 'shear.full': missing"), std::string::npos) << e;
  const std::string folder = (dir / "folder").string();
  std::filesystem::create_directory(folder);
  EXPECT_THROW(read_tolerances(folder, "micro", "small", kSource), ToleranceError);
}

}  // namespace
