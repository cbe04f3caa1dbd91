# report.html loads in headless Chromium with no console errors and every image decoded
# (tests/chromium_page.cmake).
#   cmake -DARGUS=... -DDATA=tests/report/data/run -DOUT=dir -P report_in_browser.cmake
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../chromium_page.cmake)
require_chromium()
file(REMOVE_RECURSE "${OUT}")
file(COPY ${DATA}/ DESTINATION ${OUT}/run)
execute_process(COMMAND ${ARGUS} report ${OUT}/run RESULT_VARIABLE code OUTPUT_QUIET)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "argus report: exit ${code}")
endif()
# plan.png and timeline.png, and the contact sheet of feeds/ where an EGL renderer drew it.
set(images 2)
if(EXISTS ${OUT}/run/feeds/contact_sheet.png)
  set(images 3)
else()
  message(STATUS "no feeds/contact_sheet.png (no EGL renderer?): checking the other images")
endif()
load_in_chromium(${OUT}/run/report.html ${OUT}/profile dom "data-ready=\"yes\""
                 "data-images=\"${images}\"" "data-broken=\"0\"" "data-errors=\"0\""
                 "data-events=\"28\"")
if(images EQUAL 3 AND NOT dom MATCHES "feeds/contact_sheet\\.png")
  message(FATAL_ERROR "report.html in Chromium does not show feeds/contact_sheet.png")
endif()
if(NOT dom MATCHES "28 of 28 events")
  message(FATAL_ERROR "the event log table was not filled in")
endif()
