// The result table crosscheck prints: one row per compared metric (colza, YADE, difference,
// tolerance, PASS/FAIL), informational rows without a verdict, and notes.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace crosscheck {

struct Row {
  std::string metric;
  std::string colza, yade, difference, tolerance;
  bool pass = true;
  bool info = false;  // informational row, no verdict
};

// printf-formats one number (format `f`, default "%.4g").
std::string fmt(double v, const char* f = "%.4g");

class Report {
 public:
  void add(Row r) { rows_.push_back(std::move(r)); }
  // A row that passes when difference <= tolerance (a NaN or infinite difference fails). A
  // colza or YADE value that is not finite fails it too, and its difference column then says
  // which code's value was not finite.
  void check(const std::string& metric, double colza, double yade, double difference, double tolerance,
             const char* f = "%.4g");
  void fail(const std::string& metric, const std::string& why) { add(Row{metric, "-", "-", why, "-", false, false}); }
  void info(const std::string& metric, const std::string& colza, const std::string& yade, const std::string& note) {
    add(Row{metric, colza, yade, note, "-", true, true});
  }
  void note(const std::string& text) { notes_.push_back(text); }
  bool all_passed() const;
  const std::vector<Row>& rows() const { return rows_; }
  void print() const;

 private:
  std::vector<Row> rows_;
  std::vector<std::string> notes_;
};

}  // namespace crosscheck
