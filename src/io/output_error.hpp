// A result file that could not be written (a full disk, a folder made read-only meanwhile):
// not colza's fault, so the CLI reports it as an error with the file and the system's reason
// (exit 1) after removing the run's staging folder, not as an internal error.
#pragma once
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace colza {

class OutputWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "cannot write FILE: <strerror(errno)>" (the reason left out when errno is 0).
[[noreturn]] inline void throw_cannot_write(const std::string& file) {
  const int e = errno;
  throw OutputWriteError("cannot write " + file + (e != 0 ? std::string(": ") + std::strerror(e) : std::string()));
}

}  // namespace colza
