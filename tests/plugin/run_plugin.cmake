# Runs a scenario with a strategy plug-in and checks that its strategy ran the cameras: the run
# succeeds, its own events are in events.jsonl, metrics.json names it, and the tasked camera
# (7, in penn_station_emulated.yaml) performed the task from its start to the end: a frame of it
# in tracks.csv for most of the 30 s (450 frames) after the task, as the evaluation saw them.
# How well it follows her is the strategy's business (lone_tracker is as weak as the
# no_collaboration baseline, on this seed 0.9 % coverage).
#   cmake -DARGUS=... -DPLUGIN=... -DSCENARIO=... -DOUT=... -P run_plugin.cmake
file(REMOVE_RECURSE "${OUT}")
execute_process(
  COMMAND "${ARGUS}" run "${SCENARIO}" --duration "40 s" --out "${OUT}" --no-feeds --no-progress
          --set "controller.strategy=plugin:${PLUGIN}"
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "argus run with ${PLUGIN} exited ${code}\n${out}\n${err}")
endif()
file(READ "${OUT}/events.jsonl" events)
if(NOT events MATCHES "\"kind\":\"lone_tracker_started\"")
  message(FATAL_ERROR "events.jsonl has no lone_tracker_started: the plug-in's strategy did not run")
endif()
file(READ "${OUT}/metrics.json" metrics)
string(JSON strategy GET "${metrics}" strategy)
if(NOT strategy MATCHES "^plugin:")
  message(FATAL_ERROR "metrics.json names the strategy '${strategy}'")
endif()
file(STRINGS "${OUT}/tracks.csv" frames REGEX "^[0-9]+,[0-9.]+,7,0,")
list(LENGTH frames count)
if(count LESS 400)
  message(FATAL_ERROR "camera 7 performed task 0 in ${count} frames of 450")
endif()
