# Warnings for zdg's own targets: -Wall -Wextra -Wpedantic -Wshadow, as errors in Debug or
# when ZDG_WERROR is set (CI sets it).
function(zdg_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                                           -Wnon-virtual-dtor -Wimplicit-fallthrough)
  if(ZDG_WERROR OR CMAKE_BUILD_TYPE STREQUAL "Debug")
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(ZDG_SANITIZE)
    # GCC's -Wmaybe-uninitialized is unreliable on sanitizer-instrumented code (GCC manual):
    # it fires inside CGAL's Epic_converter at -O1 -fsanitize=address. The Release build
    # keeps the warning.
    target_compile_options(${target} PRIVATE -Wno-maybe-uninitialized)
  endif()
endfunction()
