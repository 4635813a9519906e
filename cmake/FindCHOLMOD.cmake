# FindCHOLMOD: SuiteSparse's sparse Cholesky factorization (Debian: libsuitesparse-dev): its
# header (CHOLMOD_INCLUDE_DIR) and its shared library (CHOLMOD_LIBRARY). zdg compiles against
# the header and loads the library at run time (kernel/linalg/sparse_spd_solver.cpp), so there is no
# imported target to link; the library is looked for so that a build with CHOLMOD knows it is
# installed. Debian 12 ships no CMake configuration for SuiteSparse 5.
find_path(CHOLMOD_INCLUDE_DIR NAMES cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY NAMES cholmod)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(
  CHOLMOD REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR
  REASON_FAILURE_MESSAGE "install Debian's libsuitesparse-dev (scripts/install-deps.sh)")
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY)
