// Numbers in reports: printf's %g with a chosen number of significant digits, or the
// shortest text that reads back as the same double.
#pragma once
#include <charconv>
#include <cstdio>
#include <string>

namespace colza {

inline std::string format_significant(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

// The shortest decimal text that parses back to exactly `value` (std::to_chars): 0.3 for
// 0.3, 0.99900009999999999 stays distinct from 0.999. For a value that is passed on as
// text (a config override) and also shown to the user.
inline std::string format_shortest(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// A value's unit as printed after it: " " + unit, or nothing for a dimensionless one ("" or "-").
inline std::string unit_suffix(const std::string& unit) { return unit.empty() || unit == "-" ? "" : " " + unit; }

}  // namespace colza
