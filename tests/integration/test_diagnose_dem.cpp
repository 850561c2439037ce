// `colza diagnose` end to end on small DEM samples (diagnose_dem_cases.hpp): data made by
// colza without a hidden effect, at seeds the diagnosis never uses, must come out "no
// significant discrepancy"; a spec with a mistake is refused before any run (exit 2, the
// spec, the key and the reason). The cases with a hidden effect run under the label full
// (tests/full/test_diagnose_dem_hidden.cpp).
#include <gtest/gtest.h>

#include <cstdlib>

#include "diagnose_dem_cases.hpp"
#include "../unit/scratch_dir.hpp"

using namespace colza::testing;

TEST(DiagnoseDem, DataWithoutAHiddenEffectPass) {
  const ScratchDir dir;
  const nlohmann::json s = diagnose_small({"", 0.0, {}}, 1, dir.path());
  EXPECT_EQ(s["verdict"]["kind"], "no significant discrepancy") << s["verdict"]["text"];
  EXPECT_GT(s["forward_runs"].get<int>(), 10);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / "report.md"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / "model-baseline-oedometer.toml"));
}

TEST(DiagnoseDem, ASpecWithAMistakeIsRefusedBeforeAnyRun) {
  const ScratchDir dir;
  std::string spec = small_spec(6, [](std::size_t) { return 1.0; });
  const auto replace = [&](const std::string& from, const std::string& to) {
    std::string s = spec;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  struct Case {
    std::string text, key;
  };
  const std::vector<Case> cases = {
      {replace("uncertainty = 2", "uncertainty = -2"), "tests[0].features[0].uncertainty"},
      {replace("name = \"mu_pp\"\nkey = \"particle.friction\"", "name = \"mu_pp\"\nkey = \"particle.frictoin\""),
       "parameters[0].key"},
      {replace("name = \"elasto_plastic\"", "name = \"elasto_plastic\"\nprobe = 9.0"), "candidates[1].probe"},
      {replace("[settings]", "[settings]\nsignificanse = 0.05"), "settings.significanse"},
  };
  for (const Case& c : cases) {
    const std::string file = dir.write("spec.toml", c.text);
    const CliResult r = run_colza("diagnose --spec " + file + " --out " + (dir.path() / "out").string() + " --quiet");
    EXPECT_EQ(r.exit_code, 2) << c.key << ": " << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(c.key), std::string::npos) << c.key << ": " << r.stderr_text;
    EXPECT_NE(r.stderr_text.find("spec.toml"), std::string::npos) << r.stderr_text;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "summary.json"));
  }
}
