// The result table crosscheck prints and keeps in its work dir: one row per compared metric
// (colza, YADE, difference, what kind of difference, tolerance, PASS/FAIL, and the tolerances
// file's key that set the tolerance), informational rows without a verdict, and notes.
#pragma once
#include <string>
#include <utility>
#include <vector>
#include <toml++/toml.h>

namespace crosscheck {

// What a row's difference is: |colza - YADE| divided by a scale the metric names (kRelative),
// |colza - YADE| in the metric's unit (kAbsolute), or Welch's t test of two means (kTTest,
// passing when its p-value is at least the tolerance).
enum class Measure { kRelative, kAbsolute, kTTest };
const char* measure_name(Measure m);  // "rel", "abs", "t test"

// A tolerance and where it came from: the tolerances file's key ("oedometer.small.rms_relative",
// followed by " (default)" when the file leaves it out and the check's own value is used), or
// "(fixed)" for an agreement the check requires whatever the file says (equal counts).
struct Tolerance {
  double value = 0.0;
  std::string key;
};
inline Tolerance fixed_tolerance(double value) { return {value, "(fixed)"}; }

// One section of the tolerances file and its path ("shear.small"; "" for the whole file).
struct ToleranceSection {
  const toml::table& table;
  std::string path;
  // Its `key` ("early_relative", or "floor.force" below the section), or `fallback` when the
  // file has no such number.
  Tolerance get(const std::string& key, double fallback) const;
};

struct Row {
  std::string metric;
  std::string colza, yade, difference;
  std::string measure;  // measure_name, "" for a row without a comparison
  std::string tolerance;
  bool pass = true;
  bool info = false;    // informational row, no verdict
  std::string key;      // Tolerance::key, "" when no tolerance judged the row
};

// printf-formats one number (format `f`, default "%.4g").
std::string fmt(double v, const char* f = "%.4g");

class Report {
 public:
  void add(Row r) { rows_.push_back(std::move(r)); }
  // A row that passes when difference <= tolerance (a NaN or infinite difference fails). A
  // colza or YADE value that is not finite fails it too, and its difference column then says
  // which code's value was not finite.
  void check(const std::string& metric, double colza, double yade, double difference, Measure measure,
             const Tolerance& tolerance, const char* f = "%.4g");
  void fail(const std::string& metric, const std::string& why) { add(Row{metric, "-", "-", why, "", "-", false, false, ""}); }
  void info(const std::string& metric, const std::string& colza, const std::string& yade, const std::string& note) {
    add(Row{metric, colza, yade, note, "", "-", true, true, ""});
  }
  void note(const std::string& text) { notes_.push_back(text); }
  bool all_passed() const;
  const std::vector<Row>& rows() const { return rows_; }
  // The table as printed: a header, the rows, a legend of the kinds and keys, the notes and
  // the count of passed and failed rows.
  std::string text() const;
  // The rows as CSV (RFC 4180 quoting): metric, colza, yade, difference, kind, tolerance,
  // result, tolerance_key.
  std::string csv() const;

 private:
  std::vector<Row> rows_;
  std::vector<std::string> notes_;
};

}  // namespace crosscheck
