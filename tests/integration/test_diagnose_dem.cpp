// `colza diagnose` on small DEM samples with an effect hidden in the data (see
// diagnose_dem_cases.hpp): the diagnosis must name it without being told; data without one
// must pass; the seed study over three data seeds per case runs under the label full.
#include <gtest/gtest.h>

#include <cstdlib>

#include "diagnose_dem_cases.hpp"
#include "../unit/scratch_dir.hpp"

using namespace colza::testing;

namespace {

std::string verdict_of(const nlohmann::json& s) { return s["verdict"]["kind"].get<std::string>(); }
std::string cause_of(const nlohmann::json& s) { return s["verdict"]["cause"].get<std::string>(); }

// COLZA_DIAGNOSE_KEEP=<folder>: each case's data, runs and report are kept in <folder>/<test>
// (to read the report; a second run reuses every finished DEM run).
std::filesystem::path case_dir(const ScratchDir& scratch) {
  const char* keep = std::getenv("COLZA_DIAGNOSE_KEEP");
  if (!keep) return scratch.path();
  const auto dir = std::filesystem::path(keep) / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST(DiagnoseDem, HiddenElastoPlasticContactIsNamed) {
  const ScratchDir dir;
  const nlohmann::json s = diagnose_small({"elasto_plastic", 2.2, {}}, 1, case_dir(dir));
  EXPECT_EQ(verdict_of(s), "explained") << s["verdict"]["text"];
  EXPECT_EQ(cause_of(s), "elasto_plastic") << s["verdict"]["text"];
}

TEST(DiagnoseDem, DataWithoutAHiddenEffectPass) {
  const ScratchDir dir;
  const nlohmann::json s = diagnose_small({"", 0.0, {}}, 1, case_dir(dir));
  EXPECT_EQ(verdict_of(s), "no significant discrepancy") << s["verdict"]["text"];
}
