// A finished run of the cross-check stands only when it was made from the same inputs
// (crosscheck/run_stamp.hpp): with --reuse, and always for the shear box's sample kept in
// the work dir (a run without a stamp, made by hand, stands under --reuse with a notice). Before, --reuse took any folder holding summary.json, and the sample was
// reused whenever packing.txt existed, so a changed scene, packing or colza was silently
// compared with runs of the old one. The runs here are of a fake colza (a shell script that
// writes summary.json and counts its calls).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "crosscheck/code_runs.hpp"
#include "crosscheck/run_stamp.hpp"
#include "scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;
using crosscheck::CodeRuns;
using crosscheck::Options;
using crosscheck::Reuse;
using crosscheck::first_change;
using crosscheck::read_stamp;
using crosscheck::run_stamp;
using crosscheck::stamp_file;

// A fake colza: writes <--out>/summary.json, packing.txt and curve.csv and a line to calls.txt beside
// itself; exits 1 when fail.flag exists beside it.
fs::path write_fake_colza(const colza::testing::ScratchDir& dir) {
  const fs::path exe = dir / "fake-colza";
  std::ofstream(exe) << "#!/bin/sh\n"
                        "here=$(dirname \"$0\")\n"
                        "echo \"$*\" >> \"$here/calls.txt\"\n"
                        "[ -e \"$here/fail.flag\" ] && exit 1\n"
                        "while [ $# -gt 0 ]; do\n"
                        "  if [ \"$1\" = --out ]; then\n"
                        "    mkdir -p \"$2\" && echo '{}' > \"$2/summary.json\" && echo '0 0 0 1' > \"$2/packing.txt\"\n"
                        "    echo 'step,force' > \"$2/curve.csv\" && echo '0,1' >> \"$2/curve.csv\"\n"
                        "  fi\n"
                        "  shift\n"
                        "done\n";
  fs::permissions(exe, fs::perms::owner_all);
  return exe;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

int calls(const colza::testing::ScratchDir& dir) {
  std::ifstream in(dir / "calls.txt");
  int n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

TEST(CrosscheckRunStamp, NamesEveryFileTheRunReadsByContent) {
  colza::testing::ScratchDir dir;
  dir.write("packing.txt", "0 0 0.01 0.003\n");
  dir.write("other.txt", "0 0 0.02 0.003\n");
  // A packing named by a path relative to the config's folder, a --set naming a file, and a
  // string that names no file (not stamped).
  const fs::path config = dir.write("run.toml", "[oedometer]\npacking_file = \"packing.txt\"\nlabel = \"x\"\n");
  const std::string set = "shear_box.packing_file=" + (dir / "other.txt").string();
  const std::string a = run_stamp("colza run", {}, config, {set});
  EXPECT_NE(a.find("input " + config.string() + " "), std::string::npos) << a;
  EXPECT_NE(a.find("input " + (dir / "packing.txt").string() + " "), std::string::npos) << a;
  EXPECT_NE(a.find("input " + (dir / "other.txt").string() + " "), std::string::npos) << a;
  EXPECT_EQ(a, run_stamp("colza run", {}, config, {set}));

  // A changed byte in any input file, or another command, is another stamp; the change is named.
  dir.write("packing.txt", "0 0 0.01 0.0031\n");
  const std::string b = run_stamp("colza run", {}, config, {set});
  EXPECT_NE(a, b);
  EXPECT_EQ(first_change(a, b).rfind("input " + (dir / "packing.txt").string() + " ", 0), 0u) << first_change(a, b);
  EXPECT_EQ(first_change(b, run_stamp("colza run --seed 2", {}, config, {set})), "command colza run --seed 2");
  EXPECT_EQ(first_change(b, b), "");

  EXPECT_THROW(run_stamp("colza run", {}, dir / "missing.toml", {}), std::runtime_error);
}

TEST(CrosscheckRunStamp, AConfigNamesFilesRelativeToItsFolderNotTheWorkingFolder) {
  colza::testing::ScratchDir dir;
  fs::create_directories(dir / "scene");
  dir.write("scene/packing.txt", "0 0 0.01 0.003\n");
  dir.write("packing.txt", "a file of the working folder, which colza does not read\n");
  const fs::path config = dir.write("scene/run.toml", "[oedometer]\npacking_file = \"packing.txt\"\n");
  const fs::path before = fs::current_path();
  fs::current_path(dir.path());
  const std::string stamp = run_stamp("colza run", {}, config, {});
  fs::current_path(before);
  EXPECT_NE(stamp.find("input " + (dir / "scene" / "packing.txt").string() + " "), std::string::npos) << stamp;
  EXPECT_EQ(stamp.find("input " + (dir / "packing.txt").string() + " "), std::string::npos) << stamp;
}

TEST(CrosscheckRunStamp, AYadeRunIsStampedWithItsScriptAndTheModules) {
  colza::testing::ScratchDir dir;
  fs::create_directories(dir / "yade-scripts");
  dir.write("yade-scripts/run_shear.py", "import colza_yade\n");
  dir.write("yade-scripts/run_scene.py", "import colza_yade\n");
  dir.write("yade-scripts/colza_yade.py", "# the module\n");
  const fs::path yade = dir / "fake-yade";  // yade -n -j 1 -x <script> <config> <out>: $7 is out
  std::ofstream(yade) << "#!/bin/sh\necho \"$*\" >> \"$(dirname \"$0\")/calls.txt\"\n"
                         "mkdir -p \"$7\" && echo '{}' > \"$7/summary.json\"\n";
  fs::permissions(yade, fs::perms::owner_all);
  Options opt;
  opt.yade = yade.string();
  opt.source = dir.path();
  opt.reuse = true;
  const CodeRuns runs(opt);
  const fs::path config = dir.write("run.toml", "[shear_box]\nwidth = 0.2\n"), out = dir / "work" / "yade";

  ASSERT_TRUE(runs.run_yade("run_shear.py", config, out));
  ASSERT_TRUE(runs.run_yade("run_shear.py", config, out));
  EXPECT_EQ(calls(dir), 1);
  dir.write("yade-scripts/run_scene.py", "import colza_yade  # edited\n");  // another setup's script
  ASSERT_TRUE(runs.run_yade("run_shear.py", config, out));
  EXPECT_EQ(calls(dir), 1);
  dir.write("yade-scripts/colza_yade.py", "# the module, edited\n");
  ASSERT_TRUE(runs.run_yade("run_shear.py", config, out));
  EXPECT_EQ(calls(dir), 2);
  dir.write("yade-scripts/run_shear.py", "import colza_yade  # edited\n");
  ASSERT_TRUE(runs.run_yade("run_shear.py", config, out));
  EXPECT_EQ(calls(dir), 3);
}

TEST(CrosscheckRunStamp, ReuseTakesOnlyARunOfTheSameInputs) {
  colza::testing::ScratchDir dir;
  Options opt;
  opt.colza = write_fake_colza(dir);
  opt.reuse = true;
  const CodeRuns runs(opt);
  const fs::path packing = dir.write("packing.txt", "0 0 0.01 0.003\n");
  const fs::path config = dir.write("run.toml", "[oedometer]\npacking_file = \"" + packing.string() + "\"\n");
  const fs::path out = dir / "work" / "colza";

  ASSERT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(calls(dir), 1);
  ASSERT_TRUE(read_stamp(out).has_value());
  EXPECT_TRUE(runs.run_colza("oedometer", config, out));  // reused
  EXPECT_EQ(calls(dir), 1);

  // Another packing (same path), another --set, another colza: run again.
  std::ofstream(packing) << "0 0 0.01 0.0031\n";
  EXPECT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(calls(dir), 2);
  EXPECT_TRUE(runs.run_colza("oedometer", config, out, {"integration.time_step=1e-6"}));
  EXPECT_EQ(calls(dir), 3);
  std::ofstream(opt.colza, std::ios::app) << "# rebuilt\n";  // a rebuilt colza at the same path
  EXPECT_TRUE(runs.run_colza("oedometer", config, out, {"integration.time_step=1e-6"}));
  EXPECT_EQ(calls(dir), 4);
  EXPECT_TRUE(runs.run_colza("oedometer", config, out, {"integration.time_step=1e-6"}));
  EXPECT_EQ(calls(dir), 4);

  // A failed run leaves the earlier result, its stamp and its log as they were (a walk-through
  // found a failed re-run deleting finished runs: hours of YADE at full size). The stamp
  // vouches for the earlier inputs only, so the failed command's are not answered with it.
  const std::string before = read_stamp(out).value();
  const std::string summary_before = read_text(out / "summary.json");
  std::ofstream(dir / "fail.flag") << "";
  EXPECT_FALSE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(read_text(out / "summary.json"), summary_before);
  EXPECT_EQ(read_stamp(out).value(), before);
  EXPECT_TRUE(fs::exists(out.string() + ".log"));
  EXPECT_TRUE(fs::exists(out.string() + ".failed.log"));
  EXPECT_FALSE(fs::exists(out.string() + ".running"));
  EXPECT_FALSE(runs.run_colza("oedometer", config, out));  // not reused: other inputs
  EXPECT_EQ(calls(dir), 6);
  // The table's FAIL row says why (it said "run failed", the reason only on stderr).
  EXPECT_EQ(runs.failure(out), "failed (exit 1; log " + out.string() + ".failed.log)");
  EXPECT_EQ(runs.failure(out, dir / "work" / "yade"), "colza: " + runs.failure(out));
  fs::remove(dir / "fail.flag");

  // A finished run without a stamp (a load run by hand into the work dir) stands under
  // --reuse, with a notice; so do results written into a stamped folder after its stamp,
  // which it does not vouch for.
  ASSERT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_FALSE(fs::exists(out.string() + ".failed.log"));  // a success clears the failure's log
  EXPECT_EQ(runs.failure(out), "");                          // and its reason

  // A folder of the user's where a run goes is not run into, and the row says so.
  const fs::path mine = dir / "work" / "mine";
  fs::create_directories(mine);
  std::ofstream(mine / "notes.txt") << "mine\n";
  EXPECT_FALSE(runs.run_colza("oedometer", config, mine));
  EXPECT_NE(runs.failure(mine).find("holds files crosscheck did not write"), std::string::npos) << runs.failure(mine);
  EXPECT_EQ(read_text(mine / "notes.txt"), "mine\n");
  fs::remove(stamp_file(out));
  EXPECT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(calls(dir), 7);
  const fs::path out_2 = dir / "work" / "colza-2";
  ASSERT_TRUE(runs.run_colza("oedometer", config, out_2));
  ASSERT_TRUE(read_stamp(out_2).has_value());
  std::ofstream(out_2 / "summary.json") << "{\"by\": \"hand\"}\n";
  EXPECT_FALSE(read_stamp(out_2).has_value());
  EXPECT_TRUE(runs.run_colza("oedometer", config, out_2));
  EXPECT_EQ(calls(dir), 8);
}

// A result the stamp vouched for that is missing, emptied or changed while summary.json is the
// run's own: the run is made again under --reuse. Before, the stamp covered summary.json (and
// packing.txt) only, so the check then failed on the damaged file instead of running again.
TEST(CrosscheckRunStamp, ReuseRunsAgainWhenAResultIsDamaged) {
  colza::testing::ScratchDir dir;
  Options opt;
  opt.colza = write_fake_colza(dir);
  opt.reuse = true;
  const CodeRuns runs(opt);
  const fs::path config = dir.write("run.toml", "[oedometer]\nlabel = \"x\"\n");
  const fs::path out = dir / "work" / "colza";
  ASSERT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(crosscheck::damaged_result(out), "");
  ASSERT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(calls(dir), 1);  // reused

  std::ofstream(out / "curve.csv", std::ios::trunc).flush();  // emptied
  EXPECT_EQ(crosscheck::damaged_result(out), (out / "curve.csv").string() + " has changed");
  ASSERT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(calls(dir), 2);  // run again
  EXPECT_EQ(crosscheck::damaged_result(out), "");

  fs::remove(out / "curve.csv");
  EXPECT_EQ(crosscheck::damaged_result(out), (out / "curve.csv").string() + " is missing");
  ASSERT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(calls(dir), 3);

  // Another run's summary.json (a load run by hand into the folder): not damage; the stamp
  // does not vouch for that run, which --reuse takes with a notice, as before.
  std::ofstream(out / "summary.json") << "{\"by\": \"hand\"}\n";
  fs::remove(out / "curve.csv");
  EXPECT_EQ(crosscheck::damaged_result(out), "");
  ASSERT_TRUE(runs.run_colza("oedometer", config, out));
  EXPECT_EQ(calls(dir), 3);
}

TEST(CrosscheckRunStamp, WithoutReuseOnlyAKeptProductStands) {
  colza::testing::ScratchDir dir;
  Options opt;
  opt.colza = write_fake_colza(dir);
  const CodeRuns runs(opt);  // no --reuse
  const fs::path config = dir.write("scene.toml", "[shear_box]\nwidth = 0.2\n");
  const fs::path sample = dir / "work" / "sample", load = dir / "work" / "load";

  ASSERT_TRUE(runs.run_colza("shear", config, load));
  ASSERT_TRUE(runs.run_colza("shear", config, load));
  EXPECT_EQ(calls(dir), 2);  // a run of the check is always run again without --reuse

  ASSERT_TRUE(runs.run_colza("shear", config, sample, {}, {}, Reuse::kIfSameInputs));
  ASSERT_TRUE(runs.run_colza("shear", config, sample, {}, {}, Reuse::kIfSameInputs));
  EXPECT_EQ(calls(dir), 3);  // the sample is kept ...
  dir.write("scene.toml", "[shear_box]\nwidth = 0.1\n");
  ASSERT_TRUE(runs.run_colza("shear", config, sample, {}, {}, Reuse::kIfSameInputs));
  EXPECT_EQ(calls(dir), 4);  // ... until its scene changes
  fs::remove(stamp_file(sample));
  ASSERT_TRUE(runs.run_colza("shear", config, sample, {}, {}, Reuse::kIfSameInputs));
  EXPECT_EQ(calls(dir), 5);  // ... and one without a stamp (an older crosscheck's) is made again
  fs::remove(sample / "packing.txt");
  ASSERT_TRUE(runs.run_colza("shear", config, sample, {}, {}, Reuse::kIfSameInputs));
  EXPECT_EQ(calls(dir), 6);  // ... as is one that lost its packing
}

}  // namespace
