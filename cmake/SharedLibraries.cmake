# -DBUILD_SHARED_LIBS=ON: the installed libraries are shared objects made
# from the static archives the tree builds (and its tests link):
#   libm3g.so        m3g_render_vk + volk + m3g_scene + m3g_skin (m3g::m3g)
#   libm3g_scene.so  m3g_scene + m3g_skin, no Vulkan             (m3g::scene)
# A program links one of them, never both. libm3g.so holds scene too rather
# than loading libm3g_scene.so: a program that only calls the M3G classes
# names no symbol of the renderer, and a linker with --as-needed (Debian's
# default) would drop a renderer-only library, and with it the back end it
# registers (render-vk/Backend.cpp). Whole archives, so that nothing a
# program may reach is left out. Only M3G_API symbols are exported (hidden
# visibility, set in the top CMakeLists.txt).
find_package(PNG REQUIRED)
find_package(JPEG REQUIRED)
find_package(ZLIB REQUIRED)
find_package(Threads REQUIRED)
set(M3G_SHARED_STUB ${CMAKE_BINARY_DIR}/generated/m3g_shared_stub.cpp)
file(WRITE ${M3G_SHARED_STUB} "// A shared library needs one source of its own; the code comes from archives.\n")

add_library(m3g_scene_shared SHARED ${M3G_SHARED_STUB})
add_dependencies(m3g_scene_shared m3g_scene m3g_skin)
target_link_libraries(m3g_scene_shared
  PRIVATE -Wl,--whole-archive $<TARGET_FILE:m3g_scene> $<TARGET_FILE:m3g_skin> -Wl,--no-whole-archive
          PNG::PNG JPEG::JPEG ZLIB::ZLIB
  PUBLIC Threads::Threads)
target_include_directories(m3g_scene_shared INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/api> $<BUILD_INTERFACE:${CMAKE_BINARY_DIR}/generated>
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/skin/include> $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/frame/include>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
target_compile_features(m3g_scene_shared INTERFACE cxx_std_20)
set_target_properties(m3g_scene_shared PROPERTIES
  OUTPUT_NAME m3g_scene EXPORT_NAME scene
  VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}
  LINK_OPTIONS "LINKER:--no-undefined")

if(M3G_VULKAN)
  add_library(m3g_shared SHARED ${M3G_SHARED_STUB})
  add_dependencies(m3g_shared m3g_render_vk volk_static m3g_scene m3g_skin)
  target_link_libraries(m3g_shared
    PRIVATE -Wl,--whole-archive $<TARGET_FILE:m3g_render_vk> $<TARGET_FILE:m3g_scene> $<TARGET_FILE:m3g_skin>
            -Wl,--no-whole-archive $<TARGET_FILE:volk_static> PNG::PNG JPEG::JPEG ZLIB::ZLIB ${CMAKE_DL_LIBS}
    PUBLIC Threads::Threads)
  target_include_directories(m3g_shared INTERFACE
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/api> $<BUILD_INTERFACE:${CMAKE_BINARY_DIR}/generated>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/skin/include> $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/frame/include>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/render-vk/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(m3g_shared INTERFACE cxx_std_20)
  set_target_properties(m3g_shared PROPERTIES
    OUTPUT_NAME m3g EXPORT_NAME m3g
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}
    LINK_OPTIONS "LINKER:--no-undefined")
endif()
