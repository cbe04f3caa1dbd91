# An interrupted sweep resumes without redoing finished runs, and writes its CSV, JSON and plots.
#   cmake -DARGUS=... -DSCENARIO=... -DFAKE=fake_run.sh -DOUT=dir -P sweep_resume.cmake
# The runs are fake_run.sh (each logs its start), so the test knows which runs started in which
# session. In the first session the seed-3 runs hang: two at a time, the sweep finishes the four
# runs of seeds 1 and 2 of the first two grid points, then both job slots hold a hanging run
# until the interruption, which must stop them.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE "${OUT}")
set(ENV{FAKE_RUN_SECONDS} 0.1)
set(sweep ${ARGUS} sweep ${SCENARIO} --seeds 3 --set network.loss_probability=0,0.2
    --set controller.solver=best_solv,all_solv --jobs 2 --argus ${FAKE} --out ${OUT})

set(ENV{FAKE_SLOW_SEED} 3)
string(TIMESTAMP before "%s")
execute_process(COMMAND timeout --preserve-status -s INT 3 ${sweep}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(TIMESTAMP after "%s")
math(EXPR took "${after} - ${before}")
if(NOT code EQUAL 130)
  message(FATAL_ERROR "interrupted sweep: exit ${code}, expected 130\n${out}\n${err}")
endif()
if(took GREATER 20)
  message(FATAL_ERROR "the interrupted sweep took ${took} s: it waited for its runs")
endif()
file(GLOB done_first RELATIVE ${OUT}/runs ${OUT}/runs/*/metrics.json)
list(LENGTH done_first count_first)
if(NOT count_first EQUAL 4)
  message(FATAL_ERROR "after the interruption ${count_first} of 12 runs are done; expected 4")
endif()
file(STRINGS ${OUT}/invocations.log first_log)
list(LENGTH first_log first_lines)
unset(ENV{FAKE_SLOW_SEED})

# Second session: finishes, starting none of the finished runs again.
execute_process(COMMAND ${sweep} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "resumed sweep: exit ${code}\n${out}\n${err}")
endif()
if(NOT err MATCHES "${count_first} of 12 runs already done")
  message(FATAL_ERROR "resumed sweep does not say what it skips:\n${err}")
endif()
file(STRINGS ${OUT}/invocations.log log)
list(SUBLIST log ${first_lines} -1 second_log)
foreach(done IN LISTS done_first)
  get_filename_component(id ${done} DIRECTORY)
  if("start ${id}" IN_LIST second_log)
    message(FATAL_ERROR "run ${id} was finished before the interruption but ran again")
  endif()
endforeach()
file(GLOB done_all ${OUT}/runs/*/metrics.json)
list(LENGTH done_all count_all)
if(NOT count_all EQUAL 12)
  message(FATAL_ERROR "${count_all} of 12 runs done after resuming")
endif()

# Runs draw no key frames unless the sweep is asked for them (--feeds).
file(READ ${OUT}/runs/loss_probability=0__solver=best_solv__seed=1/arguments run_arguments)
if(NOT run_arguments MATCHES " --no-feeds")
  message(FATAL_ERROR "the sweep started a run without --no-feeds: ${run_arguments}")
endif()

file(STRINGS ${OUT}/sweep.csv rows)
list(LENGTH rows row_count)
list(GET rows 0 header)
if(NOT row_count EQUAL 13 OR NOT header STREQUAL
   "run,network.loss_probability,controller.solver,seed,exit_status,wall_s,handoffs,mean_coverage,mean_coverage_of_oracle,tasks")
  message(FATAL_ERROR "sweep.csv: ${row_count} rows, header '${header}'")
endif()
list(GET rows 1 first)
if(NOT first MATCHES "^loss_probability=0__solver=best_solv__seed=1,0,best_solv,1,0,[0-9.]+,1,0.91,,1$")
  message(FATAL_ERROR "sweep.csv first row: '${first}'")
endif()
foreach(file sweep.json plots/mean_coverage_vs_network.loss_probability.png
             plots/mean_coverage_vs_controller.solver.png plots/handoffs_vs_controller.solver.png)
  if(NOT EXISTS ${OUT}/${file})
    message(FATAL_ERROR "missing ${OUT}/${file}")
  endif()
endforeach()
file(READ ${OUT}/sweep.json json)
string(JSON mean GET "${json}" statistics mean_coverage network.loss_probability 1 mean)
string(JSON n GET "${json}" statistics mean_coverage network.loss_probability 1 n)
# loss 0.2: coverage 0.7 + 0.01 * seed, both solvers, seeds 1-3: mean 0.72 over 6 runs.
if(NOT n EQUAL 6 OR NOT mean MATCHES "^0\\.72")
  message(FATAL_ERROR "sweep.json: mean_coverage at loss 0.2 is ${mean} over ${n} runs")
endif()
# Paired by seed and solver, loss 0.2 is 0.2 below loss 0 in each of the 6 pairs: sign test
# p = 2 / 2^6; the solvers give the same coverage, so they differ in no pair.
file(STRINGS ${OUT}/paired.csv paired REGEX "^mean_coverage,")
if(NOT paired MATCHES "^mean_coverage,network.loss_probability,0.2,0,6,-0.2[0-9]*,[0-9.e-]+,[-0-9.e]+,[-0-9.e]+,0,6,0,0,0.03125[0-9]*;mean_coverage,controller.solver,all_solv,best_solv,6,0,0,0,0,0,0,6,0,1$")
  message(FATAL_ERROR "paired.csv, mean_coverage: '${paired}'")
endif()
if(NOT out MATCHES "mean_coverage by network.loss_probability, each value paired by seed with 0:"
   OR NOT out MATCHES "difference -0.2000 over 6 pairs")
  message(FATAL_ERROR "the sweep does not print its paired comparison:\n${out}")
endif()
if(NOT EXISTS ${OUT}/plots/mean_coverage_vs_network.loss_probability_paired.png)
  message(FATAL_ERROR "missing the paired plot")
endif()
# One point of the grid: the sweep prints its runs' mean of the compare metric instead.
# Coverage 0.71, 0.72, 0.73: sd 0.01, half width t(0.975, 2) 4.303 * 0.01 / sqrt(3) = 0.0248.
execute_process(COMMAND ${ARGUS} sweep ${SCENARIO} --seeds 3 --set network.loss_probability=0.2
                        --jobs 2 --argus ${FAKE} --out ${OUT}_one_point
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "mean_coverage: n=3 mean 0.7200 \\(95% CI 0.6952 to 0.7448\\)")
  message(FATAL_ERROR "one-point sweep: exit ${code}\n${out}\n${err}")
endif()
