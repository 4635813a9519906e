// Where the test programs find the zdg command line and the source tree. The paths live in one
// object of zdg_test_main (tests/support/paths.cpp, the only file compiled with them), so that
// the test sources do not depend on where the tree is cloned: a compiler cache serves them from
// any clone.
#pragma once

namespace zdg::test {

/// The zdg program of this build ("" when the command line is not built).
const char* cli_path();
/// The MPI launcher (mpiexec) of a zdg built with MPI, "" otherwise.
const char* mpiexec_path();
/// The root of the source tree.
const char* source_dir();

} // namespace zdg::test
