#include "core/version.hpp"

#include "colza_git_revision.hpp"  // generated at build time by cmake/git_revision.cmake

namespace colza {

const char* git_revision() { return COLZA_GIT_REVISION; }

}  // namespace colza
