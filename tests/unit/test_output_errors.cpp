// A result file that cannot be written is an OutputWriteError naming the file and the
// system's reason (io/output_error.hpp), which the CLI reports as an error (exit 1), not as
// an internal error. /dev/full accepts the open and fails the flush with ENOSPC, as a full
// disk does.
#include <gtest/gtest.h>

#include <string>

#include "io/output_error.hpp"
#include "io/summary.hpp"
#include "io/table.hpp"

using namespace colza;

namespace {

template <class Write>
std::string write_error(Write&& write) {
  try {
    write();
  } catch (const OutputWriteError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(OutputErrors, AFullDiskNamesTheFileAndTheReason) {
  Table t({"time", "force"}, {"s", "N"});
  for (int k = 0; k < 1000; ++k) t.add_row({1e-3 * k, 1.5 * k});
  EXPECT_EQ(write_error([&] { write_csv("/dev/full", t); }), "cannot write /dev/full: No space left on device");
  EXPECT_EQ(write_error([&] { write_json("/dev/full", nlohmann::json{{"particles", 2278}}); }),
            "cannot write /dev/full: No space left on device");
  EXPECT_EQ(write_error([&] { write_csv("/no-such-folder/curve.csv", t); }),
            "cannot write /no-such-folder/curve.csv: No such file or directory");
}
