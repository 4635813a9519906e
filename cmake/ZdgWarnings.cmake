# Warnings for zdg's own targets: -Wall -Wextra -Wpedantic -Wshadow, as errors in Debug or
# when ZDG_WERROR is set (CI sets it).
function(zdg_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                                           -Wnon-virtual-dtor -Wimplicit-fallthrough)
  if(ZDG_WERROR OR CMAKE_BUILD_TYPE STREQUAL "Debug")
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
