# Runs `argus` with ARGS ('|'-separated words) and checks that it exits with 0 and writes PNG.
#   cmake -DARGUS=argus "-DARGS=plan|file.yaml|--out|out.png" -DPNG=out.png -P png_written.cmake
string(REPLACE "|" ";" ARGS "${ARGS}")
file(REMOVE ${PNG})
execute_process(COMMAND ${ARGUS} ${ARGS} RESULT_VARIABLE code OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "argus exited with ${code}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(NOT EXISTS ${PNG})
  message(FATAL_ERROR "argus wrote no ${PNG}")
endif()
file(READ ${PNG} signature LIMIT 8 HEX)
if(NOT signature STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "${PNG} does not start with the PNG signature (got ${signature})")
endif()
