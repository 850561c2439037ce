// Version and provenance of the running code.
#pragma once

namespace colza {

inline constexpr const char* kVersion = "0.1.0";
// Short git revision of the source tree at build time ("-dirty" if it had uncommitted
// changes, "unknown" outside a git checkout).
const char* git_revision();

}  // namespace colza
