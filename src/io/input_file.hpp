// Why an input file named by the user cannot be read, said the same way by every reader
// (configs, specs, packings, measured data): a folder where a file was expected opens
// without error on Linux and then reads as empty, which would otherwise surface as a
// misleading "missing key" or "holds no sphere".
#pragma once
#include <string>

namespace colza {

// "" when `path` is a regular file or a pipe (such as <(...)) this process can open for
// reading; otherwise the reason: "does not exist", "is a directory, not a file", "is not a
// regular file" (a device such as /dev/zero would be read forever) or "cannot be read:
// <system message>" (e.g. Permission denied).
std::string unreadable_file_reason(const std::string& path);

}  // namespace colza
