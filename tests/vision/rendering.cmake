# Tests of the camera model, renderer and imaging model; one executable and one ctest entry
# each. The renderer test needs an EGL device: Mesa llvmpipe (surfaceless) is enough.
foreach(test_name IN ITEMS ptz_camera_test floor_estimate_test imaging_model_test renderer_test)
  add_executable(vision_${test_name} ${CMAKE_CURRENT_LIST_DIR}/${test_name}.cpp)
  target_link_libraries(vision_${test_name} PRIVATE argus_vision argus_world opencv_imgcodecs
                                                    GTest::gtest_main)
  add_test(NAME vision.${test_name} COMMAND vision_${test_name})
  set_tests_properties(vision.${test_name} PROPERTIES TIMEOUT 300 LABELS "vision")
endforeach()
