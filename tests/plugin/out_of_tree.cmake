# What a plug-in author does: install Argus, build examples/strategies/ against it with
# find_package(Argus), and run the installed argus with the plug-in.
#   cmake -DBUILD=<argus build> -DSOURCE=<argus source> -DWORK=<scratch> -P out_of_tree.cmake
file(REMOVE_RECURSE "${WORK}")
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "failed (${code}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()
step("${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${WORK}/prefix")
step("${CMAKE_COMMAND}" -S "${SOURCE}/examples/strategies" -B "${WORK}/build" -G Ninja
     -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${WORK}/prefix")
step("${CMAKE_COMMAND}" --build "${WORK}/build")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -DARGUS=${WORK}/prefix/bin/argus
          -DPLUGIN=${WORK}/build/lone_tracker.so
          -DSCENARIO=${SOURCE}/scenarios/penn_station_emulated.yaml -DOUT=${WORK}/run
          -P "${CMAKE_CURRENT_LIST_DIR}/run_plugin.cmake"
  RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the installed argus did not run the out-of-tree plug-in")
endif()
