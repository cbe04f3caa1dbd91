# `argus generate station`: the shipped large station is what the generator writes (so it can
# be made again, and changed by its options), and a small generated station runs end to end.
#   cmake -DARGUS=... -DSOURCE=<repo> -DOUT=<scratch dir> -P generated_station.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${ARGUS} generate station --out ${OUT}/large_station.yaml
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "generate station: exit ${code}\n${out}\n${err}")
endif()
foreach(f large_station.yaml large_station_layout.yaml)
  file(READ ${OUT}/${f} made)
  file(READ ${SOURCE}/scenarios/${f} shipped)
  if(NOT made STREQUAL shipped)
    message(FATAL_ERROR "scenarios/${f} is not what `argus generate station` writes: "
                        "generate it again")
  endif()
endforeach()
file(READ ${OUT}/large_station.yaml scenario)
string(REGEX MATCHALL "\n  - {id: " cameras "${scenario}")
list(LENGTH cameras n)
if(NOT n EQUAL 1024)
  message(FATAL_ERROR "large_station.yaml has ${n} cameras, expected 1024")
endif()

# Two halls, 40 cameras, 300 pedestrians, 2 tasks: it loads, runs 20 s, both tasks are issued
# and at least one finds its target (the other camera may see no one enter in 20 s).
execute_process(COMMAND ${ARGUS} generate station --halls-east 2 --halls-north 1 --cameras 40
                        --pedestrians 300 --tasks 2 --partitions 2 --out ${OUT}/small.yaml
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "2 x 1 halls, 40 cameras, 300 pedestrians, 2 tasks")
  message(FATAL_ERROR "generate small station: exit ${code}\n${out}\n${err}")
endif()
execute_process(COMMAND ${ARGUS} run ${OUT}/small.yaml --duration "20 s" --no-progress
                        --no-feeds --out ${OUT}/small_run
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "run small station: exit ${code}\n${out}\n${err}")
endif()
file(READ ${OUT}/small_run/metrics.json metrics)
string(JSON tasks LENGTH "${metrics}" tasks)
if(tasks LESS 1)
  message(FATAL_ERROR "small station: no task found its target\n${metrics}")
endif()
file(STRINGS ${OUT}/small_run/events.jsonl issued REGEX "\"kind\":\"task_issued\"")
list(LENGTH issued n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "small station: ${n} tasks issued, expected 2")
endif()
