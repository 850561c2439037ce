// Short stable fingerprints of configuration text, used to decide whether a finished run
// (a shear load, a calibration design run) can be reused: FNV-1a 64 as 16 hex digits.
#pragma once
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace colza {

inline std::string fingerprint_text(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a 64 offset basis
  for (unsigned char ch : text) h = (h ^ ch) * 1099511628211ull;  // FNV 64 prime
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// Whether `s` has the form fingerprint_text gives: 16 lowercase hex digits (a calibration's
// design run folders are named so).
inline bool is_fingerprint_text(const std::string& s) {
  if (s.size() != 16) return false;
  for (char ch : s)
    if (!((ch >= '0' && ch <= '9') || (ch >= 'a' && ch <= 'f'))) return false;
  return true;
}

// A line for a fingerprint's text that stands for the contents of `file` (a packing file a
// run loads): a file replaced under the same path then makes other runs, where its path
// alone would have reused the runs made from the old contents. "" for no file.
inline std::string file_contents_line(const std::string& file) {
  if (file.empty()) return "";
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return "\n# contents of " + file + ": " + fingerprint_text(bytes.str()) + "\n";
}

}  // namespace colza
