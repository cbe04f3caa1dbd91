# `argus report` on the hand-made run folder and on folders that lack files (older runs, runs
# without tasks): it draws what is there and says what it left out.
#   cmake -DARGUS=... -DDATA=tests/report/data/run -DOUT=dir -P report_command.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${OUT}")

function(expect_report dir expect_stdout)
  execute_process(COMMAND ${ARGUS} report ${dir} RESULT_VARIABLE code OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT code EQUAL 0 OR NOT out MATCHES "${expect_stdout}")
    message(FATAL_ERROR "argus report ${dir}: exit ${code}\n${out}\n${err}")
  endif()
endfunction()

function(expect_files dir)
  foreach(name IN LISTS ARGN)
    if(NOT EXISTS ${dir}/${name})
      message(FATAL_ERROR "${dir}/${name} was not written")
    endif()
  endforeach()
endfunction()

# Everything there: the three reports.
file(COPY ${DATA}/ DESTINATION ${OUT}/full)
expect_report(${OUT}/full "wrote .*plan\\.png.*timeline\\.png.*report\\.html")
expect_files(${OUT}/full plan.png timeline.png report.html)
# feeds/: the fixture's key events (two task starts, two hand-offs, three leader changes, two
# crashes, a recovery: 12 frames), unless no EGL renderer could draw them, which it must say.
file(GLOB frames ${OUT}/full/feeds/t*.png)
list(LENGTH frames frame_count)
if(EXISTS ${OUT}/full/feeds/contact_sheet.png)
  if(NOT frame_count EQUAL 12)
    message(FATAL_ERROR "feeds/ holds ${frame_count} frames, expected 12")
  endif()
  foreach(name t0010.00_task_created_cam7.png t0030.00_handoff_cam7.png t0030.00_handoff_cam6.png
               t0040.00_camera_failed_cam6.png t0047.00_camera_recovered_cam10.png)
    expect_files(${OUT}/full/feeds ${name})
  endforeach()
else()
  expect_report(${OUT}/full "left out: feeds/ \\(cannot render")
endif()
file(READ ${OUT}/full/report.html html)
foreach(part "fixture, seed 3, strategy protocol" "data:image/png;base64," "coverage_iou50"
             "events-data")
  string(FIND "${html}" "${part}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "report.html lacks '${part}'")
  endif()
endforeach()

# No EGL renderer: the feeds are left out, saying why; the rest is drawn.
file(COPY ${DATA}/ DESTINATION ${OUT}/no_egl)
execute_process(COMMAND ${CMAKE_COMMAND} -E env ARGUS_EGL_PLATFORM=no_such_platform
                        ${ARGUS} report ${OUT}/no_egl
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "left out: feeds/ \\(cannot render: EGL")
  message(FATAL_ERROR "argus report without EGL: exit ${code}\n${out}\n${err}")
endif()
expect_files(${OUT}/no_egl plan.png timeline.png report.html)
if(EXISTS ${OUT}/no_egl/feeds)
  message(FATAL_ERROR "feeds/ written without a renderer")
endif()

# An older run: events and summary only. No plan without a scenario; the rest is drawn.
file(MAKE_DIRECTORY ${OUT}/events_only)
file(COPY ${DATA}/events.jsonl ${DATA}/summary.json DESTINATION ${OUT}/events_only)
expect_report(${OUT}/events_only "left out: plan\\.png \\(no scenario\\.yaml")
expect_files(${OUT}/events_only timeline.png report.html)
if(EXISTS ${OUT}/events_only/plan.png)
  message(FATAL_ERROR "a plan was drawn without a scenario")
endif()

# A scenario but no targets: the plan without paths.
file(MAKE_DIRECTORY ${OUT}/no_targets)
file(COPY ${DATA}/scenario.yaml DESTINATION ${OUT}/no_targets)
expect_report(${OUT}/no_targets "left out: target paths on plan\\.png \\(no targets\\.csv\\)")
expect_files(${OUT}/no_targets plan.png report.html)

# An empty folder still gets a page saying what is missing.
file(MAKE_DIRECTORY ${OUT}/empty)
expect_report(${OUT}/empty "report\\.html")

# Not a folder: bad input.
execute_process(COMMAND ${ARGUS} report ${OUT}/no_such_folder RESULT_VARIABLE code
                ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "no_such_folder: not a folder")
  message(FATAL_ERROR "argus report on a missing folder: exit ${code}\n${err}")
endif()
