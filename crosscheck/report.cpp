#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace crosscheck {

const char* measure_name(Measure m) {
  switch (m) {
    case Measure::kRelative: return "rel";
    case Measure::kAbsolute: return "abs";
    case Measure::kTTest: return "t test";
  }
  return "?";
}

Tolerance ToleranceSection::get(const std::string& key, double fallback) const {
  const std::string full = path.empty() ? key : path + "." + key;
  if (const auto v = table.at_path(key).value<double>()) return {*v, full};
  return {fallback, full + " (default)"};
}

std::string fmt(double v, const char* f) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

void Report::check(const std::string& metric, double colza, double yade, double difference, Measure measure,
                   const Tolerance& tolerance, const char* f) {
  Row r{metric, fmt(colza, f), fmt(yade, f), fmt(difference, "%.3e"), measure_name(measure),
        fmt(tolerance.value, "%.1e"), false, false, tolerance.key};
  // The checks pass a maximum that is NaN when a value behind it was not finite
  // (max_magnitude); such a row must fail whatever its difference, and say why rather than
  // show "nan" as a difference.
  const bool colza_finite = std::isfinite(colza), yade_finite = std::isfinite(yade);
  r.pass = colza_finite && yade_finite && std::isfinite(difference) && difference <= tolerance.value;
  if (!colza_finite || !yade_finite)
    r.difference = !colza_finite && !yade_finite ? "colza's and YADE's values not finite"
                   : !colza_finite               ? "a colza value not finite"
                                                 : "a YADE value not finite";
  add(r);
}

bool Report::all_passed() const {
  return std::all_of(rows_.begin(), rows_.end(), [](const Row& r) { return r.pass; });
}

namespace {

const char* result_of(const Row& r) { return r.info ? "info" : (r.pass ? "PASS" : "FAIL"); }

std::string or_dash(const std::string& s) { return s.empty() ? "-" : s; }

}  // namespace

std::string Report::text() const {
  const std::string header[8] = {"metric", "colza", "YADE", "difference", "kind", "tolerance", "result", "tolerance key"};
  std::vector<std::vector<std::string>> cells;
  for (const Row& r : rows_)
    cells.push_back({r.metric, r.colza, r.yade, r.difference, or_dash(r.measure), r.tolerance, result_of(r), or_dash(r.key)});
  std::size_t w[8];
  for (int k = 0; k < 8; ++k) w[k] = header[k].size();
  for (const auto& c : cells)
    for (int k = 0; k < 8; ++k) w[k] = std::max(w[k], c[k].size());
  std::string out;
  auto line = [&](const std::string* c) {
    // metric left-aligned, numbers right-aligned, the last column unpadded
    std::string s = c[0] + std::string(w[0] - c[0].size(), ' ');
    for (int k = 1; k < 7; ++k) s += "  " + std::string(w[k] - c[k].size(), ' ') + c[k];
    s += "  ";
    s += c[7];
    out += s + "\n";
  };
  line(header);
  for (const auto& c : cells) line(c.data());
  out += "kind: rel = |colza - YADE| over the scale the metric names (a micro scene's: max |colza - YADE| / max "
         "|colza| over its series, at least micro.floor); abs = |colza - YADE| in the metric's unit; t test = Welch's t "
         "test of the two means, passing when p >= the tolerance.\n"
         "tolerance key: the tolerances file's key that sets the tolerance (\"(default)\": the file leaves it out and "
         "the check's own value is used; \"/ R\": alpha shared by the R rows of an ensemble; \"(fixed)\": required "
         "by the check).\n";
  for (const std::string& n : notes_) out += n + "\n";
  std::size_t passed = 0, failed = 0;
  for (const Row& r : rows_)
    if (!r.info) (r.pass ? passed : failed)++;
  out += "crosscheck: " + std::to_string(passed) + " passed, " + std::to_string(failed) + " failed\n";
  return out;
}

namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + "\"";
}

}  // namespace

std::string Report::csv() const {
  std::string out = "metric,colza,yade,difference,kind,tolerance,result,tolerance_key\n";
  for (const Row& r : rows_) {
    const std::string c[8] = {r.metric, r.colza, r.yade, r.difference, r.measure, r.tolerance, result_of(r), r.key};
    for (int k = 0; k < 8; ++k) out += (k ? "," : "") + csv_field(c[k]);
    out += "\n";
  }
  return out;
}

}  // namespace crosscheck
