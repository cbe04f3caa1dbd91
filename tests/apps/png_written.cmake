# Runs `argus` with ARGS ('|'-separated words), checks that it exits with 0 and writes a PNG,
# then runs CHECK (png_check.cpp) on it to see that the picture shows what it must:
#   cmake -DARGUS=argus "-DARGS=plan|file.yaml|--out|out.png" -DPNG=out.png
#         "-DCHECK=png_check|plan|out.png|file.yaml|60|10" -P png_written.cmake
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
# What the picture must show: CHECK is the png_check command ('|'-separated words).
string(REPLACE "|" ";" CHECK "${CHECK}")
execute_process(COMMAND ${CHECK} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "${PNG} does not show what it must (png_check exited with ${code}):\n"
                      "${out}${err}")
endif()
message(STATUS "${out}")
