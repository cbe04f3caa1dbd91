# What the browser tests share (cmake -P scripts; include() this file).
#
# require_chromium(): sets CHROMIUM, or says the test is SKIPPED and returns from the script.
# load_in_chromium(PAGE PROFILE DOM_VARIABLE WANTED...): loads PAGE in headless Chromium, whose
# --dump-dom prints the page after its scripts ran and whose log carries console messages; sets
# DOM_VARIABLE to the page, and fails unless Chromium exits 0, the page's #status (its own
# check once loaded, report/html_report.hpp) holds every WANTED attribute, and nothing was
# logged to the console.
macro(require_chromium)
  find_program(CHROMIUM NAMES chromium chromium-browser)
  if(NOT CHROMIUM)
    message("SKIPPED: chromium is not installed (Debian package chromium; scripts/setup.sh "
            "installs it)")
    return()
  endif()
endmacro()

function(load_in_chromium page profile dom_variable)
  execute_process(
    COMMAND ${CHROMIUM} --headless --disable-gpu --no-sandbox --no-first-run
            --user-data-dir=${profile} --virtual-time-budget=10000 --enable-logging=stderr
            --v=0 --dump-dom file://${page}
    RESULT_VARIABLE code OUTPUT_VARIABLE dom ERROR_VARIABLE log TIMEOUT 120)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "chromium: exit ${code}\n${log}")
  endif()
  string(REGEX MATCH "<p id=\"status\"[^>]*>" status "${dom}")
  foreach(wanted IN LISTS ARGN)
    string(FIND "${status}" "${wanted}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${page} in Chromium: #status is '${status}', lacks ${wanted}")
    endif()
  endforeach()
  string(REGEX MATCHALL "[^\n]*:CONSOLE[^\n]*" console "${log}")
  if(console)
    message(FATAL_ERROR "console messages:\n${console}")
  endif()
  message(STATUS "${page}: ${status}")
  set(${dom_variable} "${dom}" PARENT_SCOPE)
endfunction()
