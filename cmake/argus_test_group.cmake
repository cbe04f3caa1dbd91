# argus_test_group(GROUP TESTS file... LIBS lib... [INCLUDES dir...] [SYSTEM_INCLUDES dir...]
#                  [DEFINITIONS def...] [ALONE file...]
#                  [TIMEOUT s] [LABELS label...])
#
# The GoogleTest files of one folder built as one executable, GROUP_tests, and still one ctest
# entry per file (GROUP.FILE), which runs the executable with a filter on that file's suites.
# Why one executable: a test file's compile time goes mostly to what every file of its folder
# shares (GoogleTest, CAF, OpenCV, our headers' templates); with ARGUS_UNITY the folder's files
# compile together in a few translation units, so that shared part is compiled a few times
# instead of once per file. That was the largest part of a cold `scripts/test.sh`, three trees
# over (bench/RESULTS.md, "A newcomer's first half hour").
#
# ALONE names files (of TESTS) that stay out of the unity batches: they define file-local
# helpers under the same names as their neighbours' (data_dir, penn(), colours).
#
# Each file's suites are read from its TEST/TEST_F/TEST_P lines; a suite named in two files of a
# group is refused at configure time, so that no ctest entry runs another file's tests.
function(argus_test_group group)
  cmake_parse_arguments(arg "" "TIMEOUT" "TESTS;ALONE;LIBS;INCLUDES;SYSTEM_INCLUDES;DEFINITIONS;LABELS" ${ARGN})
  if(NOT arg_TIMEOUT)
    set(arg_TIMEOUT 600)
  endif()
  set(exe ${group}_tests)
  set(sources)
  foreach(name IN LISTS arg_TESTS)
    list(APPEND sources ${CMAKE_CURRENT_SOURCE_DIR}/${name}.cpp)
  endforeach()
  add_executable(${exe} ${sources})
  target_link_libraries(${exe} PRIVATE ${arg_LIBS} GTest::gtest_main)
  if(arg_INCLUDES)
    target_include_directories(${exe} PRIVATE ${arg_INCLUDES})
  endif()
  if(arg_SYSTEM_INCLUDES)
    target_include_directories(${exe} SYSTEM PRIVATE ${arg_SYSTEM_INCLUDES})
  endif()
  if(arg_DEFINITIONS)
    target_compile_definitions(${exe} PRIVATE ${arg_DEFINITIONS})
  endif()
  if(ARGUS_UNITY)
    set_target_properties(${exe} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${ARGUS_UNITY_BATCH})
    foreach(name IN LISTS arg_ALONE)
      set_source_files_properties(${CMAKE_CURRENT_SOURCE_DIR}/${name}.cpp
                                  PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endforeach()
  endif()

  set(owner_of_suite)
  foreach(name IN LISTS arg_TESTS)
    set(file ${CMAKE_CURRENT_SOURCE_DIR}/${name}.cpp)
    file(READ ${file} text)
    string(REGEX MATCHALL "\n[ \t]*TEST(_F|_P)?\\([ \t\r\n]*[A-Za-z0-9_]+" hits "${text}")
    set(patterns)
    set(seen)
    foreach(hit IN LISTS hits)
      string(REGEX REPLACE ".*\\([ \t\r\n]*" "" suite "${hit}")
      if(suite IN_LIST seen)
        continue()
      endif()
      list(APPEND seen ${suite})
      # Shared suites would make two entries run the same tests (or one miss its own).
      string(REGEX MATCH ";${suite}=[^;]*" clash ";${owner_of_suite}")
      if(clash)
        string(REGEX REPLACE ".*=" "" other "${clash}")
        message(FATAL_ERROR "${file}: test suite '${suite}' is also used in ${other}.cpp; "
                            "suites of one test group (${group}) must be unique per file")
      endif()
      list(APPEND owner_of_suite "${suite}=${name}")
      # A parameterised suite runs as PREFIX/suite.name/N.
      list(APPEND patterns "${suite}.*" "*/${suite}.*")
    endforeach()
    if(NOT patterns)
      message(FATAL_ERROR "${file}: no TEST, TEST_F or TEST_P found for group ${group}")
    endif()
    list(JOIN patterns ":" filter)
    add_test(NAME ${group}.${name} COMMAND ${exe} --gtest_filter=${filter})
    set_tests_properties(${group}.${name} PROPERTIES TIMEOUT ${arg_TIMEOUT})
    if(arg_LABELS)
      set_tests_properties(${group}.${name} PROPERTIES LABELS "${arg_LABELS}")
    endif()
  endforeach()
endfunction()
