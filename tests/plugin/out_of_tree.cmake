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
# The example beyond the paper's, which reuses the installed vision/ headers and wraps the
# registered `paper` strategy: every symbol it takes from argus resolves in a run.
step("${WORK}/prefix/bin/argus" run "${SOURCE}/scenarios/penn_station.yaml" --seed 3
     --out "${WORK}/run_predictive" --no-feeds --duration 20s
     "--set" "controller.strategy=plugin:${WORK}/build/predictive.so#predictive")
# With Python (ARGUS_PYTHON): the installed argus runs a strategy written in Python from the
# package installed beside it.
file(GLOB installed_python "${WORK}/prefix/lib*/argus/python/argus/__init__.py")
if(installed_python)
  step("${CMAKE_COMMAND}" -E env "PYTHONPATH=${SOURCE}/examples/strategies"
       "${WORK}/prefix/bin/argus" run "${SOURCE}/scenarios/penn_station_emulated.yaml"
       --out "${WORK}/run_python" --no-feeds --duration 20s
       --set controller.strategy=python:lone_tracker:LoneTracker)
endif()
