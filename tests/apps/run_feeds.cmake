# `argus run` draws DIR/feeds/ (the cameras' frames at the key events and their contact sheet;
# docs/reports.md), `--no-feeds` leaves it out, and a garbled poses.csv leaves it out of
# `argus report`, saying where.
#   cmake -DARGUS=... -DCHECK=feeds_check -DPENN=penn_station.yaml -DMINIMAL=minimal.yaml
#         -DOUT=dir -P run_feeds.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${OUT}")

function(run_argus)
  execute_process(COMMAND ${ARGUS} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "argus ${ARGN}: exit ${code}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

# Penn Station: camera 7's task starts at 16 s (seed 1); its frame shows the tracker's box.
run_argus(run ${PENN} --duration "18 s" --out ${OUT}/penn --no-progress)
if(NOT out MATCHES "feeds: ")
  message(FATAL_ERROR "argus run does not say where the feeds are:\n${out}")
endif()
execute_process(COMMAND ${CHECK} ${OUT}/penn RESULT_VARIABLE code OUTPUT_VARIABLE checked
                ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "feeds/ does not show what it must:\n${checked}${err}")
endif()
message(STATUS "${checked}")

# minimal: camera 3 crashes at 10 s, a key event. Drawn, then run again with --no-feeds into the
# same folder: the feeds are gone (an earlier run's frames are not this run's).
run_argus(run ${MINIMAL} --duration "12 s" --out ${OUT}/minimal --no-progress)
file(GLOB frames ${OUT}/minimal/feeds/t*_camera_failed_cam3.png)
if(NOT frames OR NOT EXISTS ${OUT}/minimal/feeds/contact_sheet.png)
  message(FATAL_ERROR "minimal: no feeds/ with camera 3's failure")
endif()
run_argus(run ${MINIMAL} --duration "12 s" --out ${OUT}/minimal --no-progress --no-feeds)
if(EXISTS ${OUT}/minimal/feeds)
  message(FATAL_ERROR "--no-feeds left a feeds folder")
endif()
file(READ ${OUT}/minimal/report.html html)
if(html MATCHES "contact_sheet")
  message(FATAL_ERROR "--no-feeds: report.html still shows a contact sheet")
endif()

# A garbled poses.csv: the feeds are left out, naming the file and line; the rest is drawn.
file(READ ${OUT}/minimal/poses.csv poses)
string(REGEX REPLACE "\n([0-9]+),([0-9.]+),([0-9]+),[-0-9.]+," "\n\\1,\\2,\\3,east," poses
       "${poses}")
file(WRITE ${OUT}/minimal/poses.csv "${poses}")
run_argus(report ${OUT}/minimal)
if(NOT out MATCHES "left out: feeds/ \\([^\n]*poses\\.csv:2: column pan: expected a number, got 'east'\\)")
  message(FATAL_ERROR "argus report on a garbled poses.csv:\n${out}")
endif()
if(EXISTS ${OUT}/minimal/feeds OR NOT out MATCHES "wrote [^\n]*report\\.html")
  message(FATAL_ERROR "argus report on a garbled poses.csv:\n${out}")
endif()
