# Runs SCENARIO once per "threads,speed" pair of RUNS for DURATION, each with ARGS added, and
# requires every file of FILES to be byte-identical across the runs.
#   cmake -DARGUS=... -DSCENARIO=... -DOUT=... [-DRUNS=1,0|2,0] [-DDURATION=20 s]
#         [-DFILES=events.jsonl|trajectories.csv] [-DARGS=--video|--video-size|80x60]
#         -P same_log_any_threads.cmake
# Defaults: threads 1, 2 and 4 at --speed 0 and 2 threads at --speed 40, 20 s, events.jsonl.
# A script that includes this one finds the first run's outputs in REFERENCE_DIR.
foreach(setting RUNS FILES ARGS)
  string(REPLACE "|" ";" ${setting} "${${setting}}")
endforeach()
if(NOT RUNS)
  set(RUNS "1,0" "2,0" "4,0" "2,40")
endif()
if(NOT DURATION)
  set(DURATION "20 s")
endif()
if(NOT FILES)
  set(FILES events.jsonl)
endif()
set(REFERENCE_DIR "")
foreach(run IN LISTS RUNS)
  string(REPLACE "," ";" run "${run}")
  list(GET run 0 threads)
  list(GET run 1 speed)
  set(dir "${OUT}/t${threads}_s${speed}")
  file(REMOVE_RECURSE "${dir}")
  execute_process(COMMAND "${ARGUS}" run "${SCENARIO}" --threads ${threads} --speed ${speed}
                          --duration "${DURATION}" --out "${dir}" --no-progress ${ARGS}
                  RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "argus run failed (${code}) with --threads ${threads}: ${err}")
  endif()
  if(REFERENCE_DIR STREQUAL "")
    set(REFERENCE_DIR "${dir}")
    set(reference_run "--threads ${threads} --speed ${speed}")
  endif()
  foreach(name IN LISTS FILES)
    file(SHA256 "${dir}/${name}" digest)
    file(SHA256 "${REFERENCE_DIR}/${name}" expected)
    if(NOT digest STREQUAL expected)
      message(FATAL_ERROR "${name} differs between ${reference_run} and --threads ${threads} "
                          "--speed ${speed} (${REFERENCE_DIR} and ${dir})")
    endif()
  endforeach()
endforeach()
