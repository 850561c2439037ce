#include "io/load_label.hpp"

#include <cstdio>

#include "io/format_number.hpp"

namespace colza {

std::string load_label(double normal_stress) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "load-%.0fPa", normal_stress);
  return buf;
}

bool is_load_label(const std::string& name) {
  if (name.size() <= 7 || name.rfind("load-", 0) != 0 || name.compare(name.size() - 2, 2, "Pa") != 0) return false;
  return name.find_first_not_of("0123456789", 5) == name.size() - 2;
}

std::string loads_sharing_a_label(const std::vector<double>& normal_stresses) {
  for (std::size_t a = 0; a < normal_stresses.size(); ++a)
    for (std::size_t b = a + 1; b < normal_stresses.size(); ++b)
      if (load_label(normal_stresses[a]) == load_label(normal_stresses[b]))
        return "loads " + format_significant(normal_stresses[a], 12) + " and " +
               format_significant(normal_stresses[b], 12) + " Pa would share the results directory " +
               load_label(normal_stresses[a]) + " (labels are to the nearest pascal): give each load once, " +
               "at least 1 Pa apart";
  return "";
}

}  // namespace colza
