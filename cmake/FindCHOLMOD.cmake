# FindCHOLMOD: SuiteSparse's sparse Cholesky factorization (Debian: libsuitesparse-dev), as the
# imported target CHOLMOD::CHOLMOD. Debian 12 ships no CMake configuration for SuiteSparse 5,
# so this module looks for the header and the shared library directly (the shared library
# brings AMD, COLAMD, CAMD, CCOLAMD, SuiteSparse_config, BLAS and LAPACK along).
find_path(CHOLMOD_INCLUDE_DIR NAMES cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY NAMES cholmod)
find_library(CHOLMOD_CONFIG_LIBRARY NAMES suitesparseconfig)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(
  CHOLMOD REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_CONFIG_LIBRARY CHOLMOD_INCLUDE_DIR
  REASON_FAILURE_MESSAGE "install Debian's libsuitesparse-dev (scripts/install-deps.sh)")
if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
  add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(CHOLMOD::CHOLMOD PROPERTIES IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
                        INTERFACE_LINK_LIBRARIES "${CHOLMOD_CONFIG_LIBRARY}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY CHOLMOD_CONFIG_LIBRARY)
