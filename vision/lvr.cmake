# Low-level visual routines (Section III-B, III-D): colour indexing, multiscale
# localisation, tracking, fixate/zoom control and relevance. Included by CMakeLists.txt.
list(APPEND argus_vision_sources
  ${CMAKE_CURRENT_LIST_DIR}/color_histogram.cpp
  ${CMAKE_CURRENT_LIST_DIR}/backprojection.cpp
  ${CMAKE_CURRENT_LIST_DIR}/kernel_scales.cpp
  ${CMAKE_CURRENT_LIST_DIR}/multiscale_localizer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/patch_search.cpp
  ${CMAKE_CURRENT_LIST_DIR}/tracker.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ego_motion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/signature_update.cpp
  ${CMAKE_CURRENT_LIST_DIR}/surround_match.cpp
  ${CMAKE_CURRENT_LIST_DIR}/signature_halves.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fixate_zoom.cpp
  ${CMAKE_CURRENT_LIST_DIR}/relevance.cpp)

# Emulated sensor (ground truth through an error model) and its YAML parameters.
list(APPEND argus_vision_sources
  ${CMAKE_CURRENT_LIST_DIR}/sensor_model.cpp
  ${CMAKE_CURRENT_LIST_DIR}/emulated_sensor.cpp
  ${CMAKE_CURRENT_LIST_DIR}/sensor_calibration.cpp)
list(APPEND argus_vision_private_libs yaml-cpp)
