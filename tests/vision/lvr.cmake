# Tests of the low-level visual routines: one executable and one ctest entry per test file,
# each with a timeout and the label "vision".
set(argus_vision_lvr_tests
  color_histogram_test
  backprojection_test
  multiscale_localizer_test
  multiscale_localizer_equivalence_test
  kernel_scales_test
  real_video_localization_test
  tracker_test
  fixate_zoom_test
  ego_motion_test
  signature_update_test
  reacquisition_test
  surround_match_test
  signature_halves_test
  relevance_test
  emulated_sensor_test
  emulated_sensor_fidelity_test
  rendered_localization_test)

foreach(test_name IN LISTS argus_vision_lvr_tests)
  add_executable(vision_${test_name} ${CMAKE_CURRENT_LIST_DIR}/${test_name}.cpp)
  target_link_libraries(vision_${test_name} PRIVATE argus_vision argus_world opencv_imgcodecs GTest::gtest_main)
  add_test(NAME vision.${test_name} COMMAND vision_${test_name})
  set_tests_properties(vision.${test_name} PROPERTIES TIMEOUT 600 LABELS "vision")
endforeach()
