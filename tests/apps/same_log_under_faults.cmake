# Replay under faults (issue 17): scenarios/replay_faults.yaml with --video at --threads 1, 2,
# 3, 4 and 8, each free-running and paced at 30x real time, must give byte-identical
# events.jsonl, trajectories.csv and video; and so that it cannot pass on a run where nothing
# happens, the first run must show every scheduled fault kind applied, a recovery, duplicated
# messages, the camera protocol's join and hand-over, and pedestrians in every tick.
#   cmake -DARGUS=... -DSCENARIO=.../replay_faults.yaml -DOUT=... -DDURATION=12 s
#         -P same_log_under_faults.cmake
set(RUNS "1,0|2,0|3,0|4,0|8,0|1,30|2,30|3,30|4,30|8,30")
set(FILES "events.jsonl|trajectories.csv|video/feeds.avi")
set(ARGS "--video|--video-size|80x60")
include(${CMAKE_CURRENT_LIST_DIR}/same_log_any_threads.cmake)

file(READ "${REFERENCE_DIR}/events.jsonl" events)
foreach(kind crash crash_and_recover link_cut link_heal loss_burst)
  if(NOT events MATCHES "\"fault\":\"${kind}\",[^\n]*\"applied\":true")
    message(FATAL_ERROR "events.jsonl: no applied '${kind}' fault in ${DURATION} of ${SCENARIO}")
  endif()
endforeach()
if(NOT events MATCHES "\"kind\":\"node_recovered\",[^\n]*\"applied\":true")
  message(FATAL_ERROR "events.jsonl: no camera recovered in ${DURATION} of ${SCENARIO}")
endif()
foreach(kind joined handoff)
  if(NOT events MATCHES "\"kind\":\"${kind}\"")
    message(FATAL_ERROR "events.jsonl: no '${kind}' event in ${DURATION} of ${SCENARIO}")
  endif()
endforeach()

file(READ "${REFERENCE_DIR}/summary.json" summary)
string(JSON duplicated GET "${summary}" network totals duplicated)
string(JSON delivered GET "${summary}" network totals delivered)
if(NOT duplicated GREATER 0 OR NOT delivered GREATER 0)
  message(FATAL_ERROR "summary.json: ${duplicated} messages duplicated, ${delivered} delivered")
endif()

# Pedestrians in every tick: rows for the start (tick 0) and after each of the run's ticks.
string(JSON ticks GET "${summary}" ticks)
math(EXPR states "${ticks} + 1")
file(STRINGS "${REFERENCE_DIR}/trajectories.csv" rows REGEX "^[0-9]+,")
list(TRANSFORM rows REPLACE ",.*" "")
list(REMOVE_DUPLICATES rows)
list(LENGTH rows ticks_with_rows)
if(NOT ticks_with_rows EQUAL states)
  message(FATAL_ERROR "trajectories.csv: pedestrians in ${ticks_with_rows} of ${states} ticks")
endif()
message(STATUS "${ticks} ticks identical in ${RUNS}: ${duplicated} duplicates, "
               "${delivered} messages delivered")
