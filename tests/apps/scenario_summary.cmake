# Runs a scenario for 30 s and checks what its summary.json must say, not only that it ran:
#   cmake -DARGUS=argus -DSCENARIO=demo.yaml -DNAME=demo -DOUT=dir -DTICKS=450
#         "-DKINDS=node_up|task_created" -P scenario_summary.cmake
# - the run's name, its ticks (30 s at the scenario's 1/15 s) and that no participant died
#   unexpectedly;
# - events_total is the number of lines in events.jsonl and the sum of events_by_kind;
# - every kind in KINDS occurred (the camera protocol at work: tasks, joins, hand-overs);
# - the network's accounting: invariant_holds, and the totals balance when added up here
#   (sent + duplicated == delivered + lost + dropped + in flight), with messages delivered.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${ARGUS} run ${SCENARIO} --duration "30 s" --out ${OUT} --no-progress
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "argus run exited with ${code}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(NOT out MATCHES "events: +[^\n]*events\\.jsonl")
  message(FATAL_ERROR "stdout names no events.jsonl:\n${out}")
endif()
file(READ ${OUT}/summary.json summary)

function(expect_equal what actual expected)
  if(NOT "${actual}" STREQUAL "${expected}")
    message(FATAL_ERROR "summary.json: ${what} is '${actual}', expected '${expected}'")
  endif()
endfunction()

string(JSON name GET "${summary}" scenario)
expect_equal(scenario "${name}" "${NAME}")
string(JSON ticks GET "${summary}" ticks)
expect_equal(ticks "${ticks}" "${TICKS}")
string(JSON down LENGTH "${summary}" unexpected_down)
expect_equal("unexpected_down's length" "${down}" 0)

# Events: the log, the total and the per-kind counts agree.
string(JSON total GET "${summary}" events_total)
file(STRINGS ${OUT}/events.jsonl lines)
list(LENGTH lines lines)
expect_equal("events_total (lines in events.jsonl)" "${total}" "${lines}")
string(JSON kinds LENGTH "${summary}" events_by_kind)
set(sum 0)
if(kinds GREATER 0)
  math(EXPR last "${kinds} - 1")
  foreach(k RANGE ${last})
    string(JSON kind MEMBER "${summary}" events_by_kind ${k})
    string(JSON count GET "${summary}" events_by_kind ${kind})
    math(EXPR sum "${sum} + ${count}")
  endforeach()
endif()
expect_equal("the sum of events_by_kind" "${sum}" "${total}")
string(REPLACE "|" ";" KINDS "${KINDS}")
foreach(kind IN LISTS KINDS)
  string(JSON count ERROR_VARIABLE missing GET "${summary}" events_by_kind ${kind})
  if(missing OR NOT count GREATER 0)
    message(FATAL_ERROR "summary.json: no '${kind}' event in 30 s of ${NAME}")
  endif()
endforeach()

# The network's accounting invariant, as reported and as added up here.
string(JSON holds GET "${summary}" network invariant_holds)
expect_equal(network.invariant_holds "${holds}" ON)
foreach(field sent duplicated delivered lost dropped in_flight)
  string(JSON ${field} GET "${summary}" network totals ${field})
endforeach()
math(EXPR offered "${sent} + ${duplicated}")
math(EXPR accounted "${delivered} + ${lost} + ${dropped} + ${in_flight}")
expect_equal("network.totals: delivered + lost + dropped + in_flight (sent + duplicated = ${offered})"
             "${accounted}" "${offered}")
string(JSON links GET "${summary}" network links)
if(links GREATER 0 AND NOT delivered GREATER 0)
  message(FATAL_ERROR "summary.json: ${links} links but no message delivered")
endif()
message(STATUS "${NAME}: ${ticks} ticks, ${total} events, ${links} links, ${sent} sent, "
               "${delivered} delivered, ${lost} lost, ${in_flight} in flight")
