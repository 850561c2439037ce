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
  if (status.type() == fs::file_type::not_found) return "does not exist";
  if (ec) return "cannot be read: " + ec.message();  // e.g. a folder on the way that cannot be entered
  if (fs::is_directory(status)) return "is a directory, not a file";
  if (!fs::is_regular_file(status) && !fs::is_fifo(status)) return "is not a regular file";  // /dev/zero, ...
  errno = 0;
  std::ifstream in(path);
  if (!in) return std::string("cannot be read: ") + (errno ? std::strerror(errno) : "open failed");
  return "";
}

}  // namespace colza
