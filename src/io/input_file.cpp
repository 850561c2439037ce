#include "io/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace colza {

std::string unreadable_file_reason(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) return "does not exist";
  if (fs::is_directory(status)) return "is a directory, not a file";
  errno = 0;
  std::ifstream in(path);
  if (!in) return std::string("cannot be read: ") + (errno ? std::strerror(errno) : "open failed");
  return "";
}

}  // namespace colza
