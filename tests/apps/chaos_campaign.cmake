# `argus chaos` end to end: a small campaign must pass and say so in chaos.json, cover every
# nemesis across its seeds, write each seed's scenario the same way twice, and a bound broken on
# purpose must fail the campaign and print the command that reproduces the failing seed.
#   cmake -DARGUS=... -DSCENARIO=... -DOUT=dir [-DSEEDS=n] [-DEVERY=k] -P chaos_campaign.cmake
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED SEEDS)
  set(SEEDS 12)
endif()
if(NOT DEFINED EVERY)
  set(EVERY 0)
endif()
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND ${ARGUS} chaos ${SCENARIO} --seeds ${SEEDS} --jobs 2
                        --scenario-sensing-every ${EVERY} --out ${OUT}/campaign
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "chaos: exit ${code}\n${out}\n${err}")
endif()
file(READ ${OUT}/campaign/chaos.json summary)
string(JSON passed GET "${summary}" passed)
string(JSON checked GET "${summary}" runs_checked)
if(NOT passed STREQUAL "ON" AND NOT passed STREQUAL "true")
  message(FATAL_ERROR "chaos.json: passed is ${passed}")
endif()
if(NOT checked EQUAL SEEDS)
  message(FATAL_ERROR "chaos.json: ${checked} runs checked of ${SEEDS}")
endif()
# Every nemesis shows up somewhere in the campaign.
set(all "")
foreach(seed RANGE 1 ${SEEDS})
  file(READ ${OUT}/campaign/seed-${seed}/verdict.json verdict)
  string(APPEND all "${verdict}")
endforeach()
foreach(nemesis loss_burst delay_spike partition crash_and_recover duplicates reorder cancel)
  if(NOT all MATCHES "\"${nemesis}\"")
    message(FATAL_ERROR "no seed of ${SEEDS} drew a ${nemesis}")
  endif()
endforeach()
# A seed's schedule is a function of its number: made again, its scenario is the same.
execute_process(COMMAND ${ARGUS} chaos ${SCENARIO} --first-seed 3 --seeds 1
                        --scenario-sensing-every ${EVERY} --out ${OUT}/again
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
file(READ ${OUT}/campaign/seed-3/scenario.yaml first)
file(READ ${OUT}/again/seed-3/scenario.yaml second)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "seed 3's scenario differs when made again")
endif()
if(NOT first MATCHES "faults:\n  - {at:")
  message(FATAL_ERROR "seed 3's scenario has no faults")
endif()
# A bound no run can meet: every seed fails, and each failure says how to make it again.
execute_process(COMMAND ${ARGUS} chaos ${SCENARIO} --seeds 2 --jobs 2 --max-messages 1
                        --scenario-sensing-every 0 --out ${OUT}/tight
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_QUIET)
if(NOT code EQUAL 1)
  message(FATAL_ERROR "a broken bound: exit ${code}, expected 1\n${out}")
endif()
if(NOT out MATCHES "seed 1 failed:.*messages for one task in one second \\(bound 1\\).*reproduce: argus run [^ ]*seed-1/scenario.yaml")
  message(FATAL_ERROR "the failure does not say what broke and how to reproduce it:\n${out}")
endif()
if(NOT EXISTS ${OUT}/tight/seed-1/run/events.jsonl)
  message(FATAL_ERROR "a failing seed's run folder was not kept")
endif()
# A campaign resumes only what the same argus, scenario and settings made.
set(again ${ARGUS} chaos ${SCENARIO} --first-seed 3 --seeds 1 --scenario-sensing-every ${EVERY}
    --out ${OUT}/again)
execute_process(COMMAND ${again} RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT err MATCHES "1 of 1 runs already done")
  message(FATAL_ERROR "the same campaign again: exit ${code}, expected seed 3 reused\n${err}")
endif()
execute_process(COMMAND ${again} --duration "2 min" RESULT_VARIABLE code OUTPUT_QUIET
                ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "holds runs made with different settings")
  message(FATAL_ERROR "another --duration: exit ${code}, expected 2\n${err}")
endif()
execute_process(COMMAND ${again} --duration "2 min" --fresh RESULT_VARIABLE code OUTPUT_QUIET
                ERROR_QUIET)
file(READ ${OUT}/again/seed-3/scenario.yaml shorter)
if(NOT code EQUAL 0 OR shorter STREQUAL second)
  message(FATAL_ERROR "--fresh with another --duration: exit ${code}; seed 3 not made again")
endif()
