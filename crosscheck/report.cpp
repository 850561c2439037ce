#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace crosscheck {

std::string fmt(double v, const char* f) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

void Report::check(const std::string& metric, double colza, double yade, double difference, double tolerance,
                   const char* f) {
  Row r{metric, fmt(colza, f), fmt(yade, f), fmt(difference, "%.3e"), fmt(tolerance, "%.1e"), false, false};
  // The checks pass a maximum that is NaN when a value behind it was not finite
  // (max_magnitude); such a row must fail whatever its difference, and say why rather than
  // show "nan" as a difference.
  const bool colza_finite = std::isfinite(colza), yade_finite = std::isfinite(yade);
  r.pass = colza_finite && yade_finite && std::isfinite(difference) && difference <= tolerance;
  if (!colza_finite || !yade_finite)
    r.difference = !colza_finite && !yade_finite ? "colza's and YADE's values not finite"
                   : !colza_finite               ? "a colza value not finite"
                                                 : "a YADE value not finite";
  add(r);
}

bool Report::all_passed() const {
  return std::all_of(rows_.begin(), rows_.end(), [](const Row& r) { return r.pass; });
}

void Report::print() const {
  std::size_t w[5] = {6, 5, 4, 10, 9};
  for (const Row& r : rows_) {
    w[0] = std::max(w[0], r.metric.size());
    w[1] = std::max(w[1], r.colza.size());
    w[2] = std::max(w[2], r.yade.size());
    w[3] = std::max(w[3], r.difference.size());
    w[4] = std::max(w[4], r.tolerance.size());
  }
  auto line = [&](const std::string& a, const std::string& b, const std::string& c, const std::string& d,
                  const std::string& e, const std::string& f) {
    std::printf("%-*s  %*s  %*s  %*s  %*s  %s\n", int(w[0]), a.c_str(), int(w[1]), b.c_str(), int(w[2]), c.c_str(),
                int(w[3]), d.c_str(), int(w[4]), e.c_str(), f.c_str());
  };
  line("metric", "colza", "YADE", "difference", "tolerance", "result");
  for (const Row& r : rows_) line(r.metric, r.colza, r.yade, r.difference, r.tolerance, r.info ? "info" : (r.pass ? "PASS" : "FAIL"));
  for (const std::string& n : notes_) std::printf("%s\n", n.c_str());
  std::size_t passed = 0, failed = 0;
  for (const Row& r : rows_)
    if (!r.info) (r.pass ? passed : failed)++;
  std::printf("crosscheck: %zu passed, %zu failed\n", passed, failed);
}

}  // namespace crosscheck
