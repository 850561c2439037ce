// Why an input file named by the user cannot be read, said the same way by every reader
// (configs, specs, packings, measured data): a folder where a file was expected opens
// without error on Linux and then reads as empty, which would otherwise surface as a
// misleading "missing key" or "holds no sphere".
#pragma once
#include <string>

namespace colza {

// "" when this process can open `path` for reading and it is not a directory (a pipe such as
// <(...) is fine); otherwise the reason: "does not exist", "is a directory, not a file" or
// "cannot be read: <system message>" (e.g. Permission denied).
std::string unreadable_file_reason(const std::string& path);

}  // namespace colza
