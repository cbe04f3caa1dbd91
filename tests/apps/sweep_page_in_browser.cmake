# sweep.html loads in headless Chromium with no console errors and every plot decoded, and
# leads with the compare metric paired by seed (tests/chromium_page.cmake).
#   cmake -DARGUS=... -DSCENARIO=... -DFAKE=fake_run.sh -DOUT=dir -P sweep_page_in_browser.cmake
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/../chromium_page.cmake)
require_chromium()
file(REMOVE_RECURSE "${OUT}")
set(ENV{FAKE_RUN_SECONDS} 0.05)
# fake_run.sh: coverage 0.9 - loss + 0.01 * seed, handoffs = seed, tasks 1, and a null ratio.
execute_process(COMMAND ${ARGUS} sweep ${SCENARIO} --seeds 3 --set network.loss_probability=0,0.2
                        --jobs 2 --argus ${FAKE} --out ${OUT}/sweep
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "sweep\\.html")
  message(FATAL_ERROR "argus sweep: exit ${code}\n${out}\n${err}")
endif()
# Coverage, handoffs and tasks, each pooled and paired (the null ratio has no plot).
load_in_chromium(${OUT}/sweep/sweep.html ${OUT}/profile dom "data-ready=\"yes\""
                 "data-images=\"6\"" "data-broken=\"0\"" "data-errors=\"0\"")
if(NOT dom MATCHES "<h2>mean_coverage by network.loss_probability</h2>"
   OR NOT dom MATCHES "<td class=\"number\">-0.2</td>")
  message(FATAL_ERROR "sweep.html does not lead with the paired coverage:\n${dom}")
endif()
