# Camera model, headless EGL renderer and imaging model (issue 4). Included by
# vision/CMakeLists.txt, which builds argus_vision from argus_vision_sources.
# EGL and OpenGL ES come from the system (Mesa's libegl-mesa0/libgles-dev through glvnd, or
# the NVIDIA driver); nothing is vendored.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(argus_egl QUIET IMPORTED_TARGET egl)
  pkg_check_modules(argus_glesv2 QUIET IMPORTED_TARGET glesv2)
endif()
if(TARGET PkgConfig::argus_egl AND TARGET PkgConfig::argus_glesv2)
  set(argus_egl_libs PkgConfig::argus_egl PkgConfig::argus_glesv2)
else()
  find_library(argus_egl_library EGL REQUIRED)
  find_library(argus_glesv2_library GLESv2 REQUIRED)
  set(argus_egl_libs ${argus_egl_library} ${argus_glesv2_library})
endif()

list(APPEND argus_vision_sources
  ${CMAKE_CURRENT_LIST_DIR}/capture.cpp
  ${CMAKE_CURRENT_LIST_DIR}/egl_context.cpp
  ${CMAKE_CURRENT_LIST_DIR}/feed_mosaic.cpp
  ${CMAKE_CURRENT_LIST_DIR}/floor_estimate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/imaging_model.cpp
  ${CMAKE_CURRENT_LIST_DIR}/jpeg_codec.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pedestrian_mesh.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ptz_camera.cpp
  ${CMAKE_CURRENT_LIST_DIR}/renderer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/scene_mesh.cpp)
# libjpeg-turbo for the imaging model's JPEG (jpeg_codec.cpp; Debian's libjpeg-dev).
find_package(JPEG REQUIRED)
# argus_world: the renderer draws the station and a snapshot's pedestrians.
list(APPEND argus_vision_private_libs argus_world opencv_imgcodecs JPEG::JPEG ${argus_egl_libs})
