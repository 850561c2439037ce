// Numbers in reports: printf's %g with a chosen number of significant digits.
#pragma once
#include <cstdio>
#include <string>

namespace colza {

inline std::string format_significant(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

}  // namespace colza
