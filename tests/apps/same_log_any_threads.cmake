# Runs SCENARIO with --threads 1, 2 and 4 and --speed 0 and 40 and requires byte-identical
# events.jsonl files.   cmake -DARGUS=... -DSCENARIO=... -DOUT=... -P same_log_any_threads.cmake
set(runs "1,0" "2,0" "4,0" "2,40")
set(reference "")
foreach(run IN LISTS runs)
  string(REPLACE "," ";" run "${run}")
  list(GET run 0 threads)
  list(GET run 1 speed)
  set(dir "${OUT}/t${threads}_s${speed}")
  execute_process(COMMAND "${ARGUS}" run "${SCENARIO}" --threads ${threads} --speed ${speed}
                          --duration "20 s" --out "${dir}" --no-progress
                  RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "argus run failed (${code}) with --threads ${threads}: ${err}")
  endif()
  file(SHA256 "${dir}/events.jsonl" digest)
  if(reference STREQUAL "")
    set(reference "${digest}")
  elseif(NOT digest STREQUAL reference)
    message(FATAL_ERROR "events.jsonl differs for --threads ${threads} --speed ${speed}")
  endif()
endforeach()
