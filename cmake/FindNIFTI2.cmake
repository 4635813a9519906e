# FindNIFTI2: the NIfTI-1/2 reference C library (Debian: libnifti2-dev), as the imported
# target NIFTI2::NIFTI2 (nifti2 + znz + zlib). Debian 12's own NIFTIConfig.cmake points at
# files under /usr/lib that the package installs under /usr/lib/<multiarch>, so this module
# looks for the header and the libraries directly.
find_path(NIFTI2_INCLUDE_DIR NAMES nifti2_io.h PATH_SUFFIXES nifti)
find_library(NIFTI2_LIBRARY NAMES nifti2)
find_library(NIFTI2_ZNZ_LIBRARY NAMES znz)
include(CMakeFindDependencyMacro)
find_package(ZLIB QUIET)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(
  NIFTI2 REQUIRED_VARS NIFTI2_LIBRARY NIFTI2_ZNZ_LIBRARY NIFTI2_INCLUDE_DIR ZLIB_FOUND
  REASON_FAILURE_MESSAGE "install Debian's libnifti2-dev (scripts/install-deps.sh)")
if(NIFTI2_FOUND AND NOT TARGET NIFTI2::NIFTI2)
  add_library(NIFTI2::NIFTI2 UNKNOWN IMPORTED)
  set_target_properties(NIFTI2::NIFTI2 PROPERTIES IMPORTED_LOCATION "${NIFTI2_LIBRARY}"
                        INTERFACE_INCLUDE_DIRECTORIES "${NIFTI2_INCLUDE_DIR}"
                        INTERFACE_LINK_LIBRARIES "${NIFTI2_ZNZ_LIBRARY};ZLIB::ZLIB;m")
endif()
mark_as_advanced(NIFTI2_INCLUDE_DIR NIFTI2_LIBRARY NIFTI2_ZNZ_LIBRARY)
