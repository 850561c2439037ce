// The cross-check reads both codes' CSV results (crosscheck/result_files.hpp) strictly: a cell
// that is not wholly a number is an error naming the file, line and column. Before, strtod
// read "garbage5e-07" as 0 and an empty cell as 0, so a damaged curve compared as zeros.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "crosscheck/result_files.hpp"
#include "scratch_dir.hpp"

namespace {

using crosscheck::read_csv;

std::string error_of(const colza::testing::ScratchDir& dir, const std::string& text) {
  try {
    read_csv(dir.write("curve.csv", text));
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CrosscheckResultFiles, NumbersAreReadWithNanAndCarriageReturns) {
  const colza::testing::ScratchDir dir;
  const auto csv = read_csv(dir.write("curve.csv", "step,force\r\n0,1.5e-3\r\n10, nan\r\n\r\n20,-inf \r\n"));
  ASSERT_EQ(csv.rows(), 3u);
  EXPECT_EQ(csv.at("step")[2], 20.0);
  EXPECT_EQ(csv.at("force")[0], 1.5e-3);
  EXPECT_TRUE(std::isnan(csv.at("force")[1]));
  EXPECT_EQ(csv.at("force")[2], -INFINITY);
}

TEST(CrosscheckResultFiles, ACellThatIsNotANumberIsNamed) {
  const colza::testing::ScratchDir dir;
  std::string e = error_of(dir, "step,force\n0,1\n10,garbage5e-07\n");
  EXPECT_NE(e.find("curve.csv: line 3, column force: 'garbage5e-07' is not a number"), std::string::npos) << e;
  e = error_of(dir, "step,force\n0,1\n10,5e-07garbage\n");
  EXPECT_NE(e.find("line 3, column force: '5e-07garbage' is not a number"), std::string::npos) << e;
  e = error_of(dir, "step,force\n,1\n");
  EXPECT_NE(e.find("line 2, column step: '' is not a number"), std::string::npos) << e;
  e = error_of(dir, "step,force\n0\n");
  EXPECT_NE(e.find("line 2: short row"), std::string::npos) << e;
}

}  // namespace
