// Short stable fingerprints of configuration text, used to decide whether a finished run
// (a shear load, a calibration design run) can be reused: FNV-1a 64 as 16 hex digits.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

namespace colza {

inline std::string fingerprint_text(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a 64 offset basis
  for (unsigned char ch : text) h = (h ^ ch) * 1099511628211ull;  // FNV 64 prime
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

}  // namespace colza
