# report.html loads in headless Chromium with no console errors and every image decoded. The
# page records its own check on #status once loaded (report/html_report.hpp); Chromium's
# --dump-dom prints the page after its scripts ran, and its log carries console messages.
#   cmake -DARGUS=... -DDATA=tests/report/data/run -DOUT=dir -P report_in_browser.cmake
cmake_minimum_required(VERSION 3.25)
find_program(CHROMIUM NAMES chromium chromium-browser)
if(NOT CHROMIUM)
  message("SKIPPED: chromium is not installed (Debian package chromium; scripts/setup.sh "
          "installs it)")
  return()
endif()
file(REMOVE_RECURSE "${OUT}")
file(COPY ${DATA}/ DESTINATION ${OUT}/run)
execute_process(COMMAND ${ARGUS} report ${OUT}/run RESULT_VARIABLE code OUTPUT_QUIET)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "argus report: exit ${code}")
endif()
execute_process(
  COMMAND ${CHROMIUM} --headless --disable-gpu --no-sandbox --no-first-run
          --user-data-dir=${OUT}/profile --virtual-time-budget=10000 --enable-logging=stderr
          --v=0 --dump-dom file://${OUT}/run/report.html
  RESULT_VARIABLE code OUTPUT_VARIABLE dom ERROR_VARIABLE log TIMEOUT 120)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "chromium: exit ${code}\n${log}")
endif()
string(REGEX MATCH "<p id=\"status\"[^>]*>" status "${dom}")
# plan.png and timeline.png, and the contact sheet of feeds/ where an EGL renderer drew it.
set(images 2)
if(EXISTS ${OUT}/run/feeds/contact_sheet.png)
  set(images 3)
  if(NOT dom MATCHES "feeds/contact_sheet\\.png")
    message(FATAL_ERROR "report.html in Chromium does not show feeds/contact_sheet.png")
  endif()
else()
  message(STATUS "no feeds/contact_sheet.png (no EGL renderer?): checking the other images")
endif()
foreach(wanted "data-ready=\"yes\"" "data-images=\"${images}\"" "data-broken=\"0\""
               "data-errors=\"0\"" "data-events=\"28\"")
  string(FIND "${status}" "${wanted}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "report.html in Chromium: #status is '${status}', lacks ${wanted}")
  endif()
endforeach()
if(NOT dom MATCHES "28 of 28 events")
  message(FATAL_ERROR "the event log table was not filled in")
endif()
string(REGEX MATCHALL "[^\n]*:CONSOLE[^\n]*" console "${log}")
if(console)
  message(FATAL_ERROR "console messages:\n${console}")
endif()
message(STATUS "report.html: ${status}")
