// The build's paths (compile definitions of this file only: tests/CMakeLists.txt).
#include "tests/support/paths.hpp"

namespace zdg::test {

const char* cli_path() {
  return ZDG_CLI_PATH;
}
const char* mpiexec_path() {
  return ZDG_MPIEXEC_PATH;
}
const char* source_dir() {
  return ZDG_SOURCE_DIR;
}

} // namespace zdg::test
