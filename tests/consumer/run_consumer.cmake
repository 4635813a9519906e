# Installs the build in ZDG_BUILD_DIR into a scratch prefix, then configures, builds and runs
# the consumer project against it. Run with cmake -P (see tests/CMakeLists.txt).
file(REMOVE_RECURSE ${ZDG_SCRATCH})
set(prefix ${ZDG_SCRATCH}/prefix)
function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGV}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()
run(${CMAKE_COMMAND} --install ${ZDG_BUILD_DIR} --prefix ${prefix} --component Unspecified)
# The property-campaign oracles (convergence/check/, the library zdg_check) are not installed,
# and the operations' headers are.
foreach(absent include/zdg/convergence/check include/zdg/cli)
  if(EXISTS ${prefix}/${absent})
    message(FATAL_ERROR "the install holds ${absent}: the campaign oracles and the command line "
                        "are not part of zdg::zdg")
  endif()
endforeach()
file(GLOB check_libs ${prefix}/lib*/libzdg_check*)
if(check_libs)
  message(FATAL_ERROR "the install holds ${check_libs}")
endif()
if(NOT EXISTS ${prefix}/include/zdg/operations/arith_operations.hpp)
  message(FATAL_ERROR "the install lacks the operations' headers")
endif()
run(${CMAKE_COMMAND} -S ${ZDG_CONSUMER_SOURCE} -B ${ZDG_SCRATCH}/build -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release)
run(${CMAKE_COMMAND} --build ${ZDG_SCRATCH}/build)
run(${ZDG_SCRATCH}/build/consumer)
