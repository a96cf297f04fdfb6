# Installation and the package files (included from the top CMakeLists.txt).
include(CMakePackageConfigHelpers)
set(M3G_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/m3g)

# Headers: the M3G classes (api/), the generated version, the skinning
# kernels and the frame interface that Graphics3D's public header names,
# and, with Vulkan, render-vk's public header (ImGuiOverlay.h belongs to the
# viewer's uninstalled m3g_vk_imgui).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/api/m3g DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(FILES ${CMAKE_BINARY_DIR}/generated/m3g/Version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/m3g)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/skin/include/m3g ${PROJECT_SOURCE_DIR}/frame/include/m3g
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Static: the archives and the umbrella target; shared: the two shared
# libraries (cmake/SharedLibraries.cmake), under the same m3g:: names.
if(BUILD_SHARED_LIBS)
  set(M3G_INSTALLED_TARGETS m3g_scene_shared)
else()
  set(M3G_INSTALLED_TARGETS m3g_skin m3g_frame m3g_scene m3g)
endif()
if(M3G_VULKAN)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/render-vk/include/m3g DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          PATTERN "ImGuiOverlay.h" EXCLUDE)
  if(BUILD_SHARED_LIBS)
    list(APPEND M3G_INSTALLED_TARGETS m3g_shared)
  else()
    list(APPEND M3G_INSTALLED_TARGETS m3g_render_vk volk_static)
  endif()
endif()
install(TARGETS ${M3G_INSTALLED_TARGETS} EXPORT m3gTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT m3gTargets NAMESPACE m3g:: DESTINATION ${M3G_CMAKE_DIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/m3gConfig.cmake.in ${CMAKE_BINARY_DIR}/m3gConfig.cmake
                              INSTALL_DESTINATION ${M3G_CMAKE_DIR})
# 0.x: SameMajorVersion accepts any 0.y, as the API has not been frozen.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/m3gConfigVersion.cmake COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/m3gConfig.cmake ${CMAKE_BINARY_DIR}/m3gConfigVersion.cmake
        DESTINATION ${M3G_CMAKE_DIR})

# pkg-config: m3g-scene (no Vulkan) and m3g (everything). The
# prefix is found from the .pc file's own place (${pcfiledir}), so the
# installed tree can move. Static libraries need their dependencies on
# every link line (Requires); shared ones only at run time (Requires.private).
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(M3G_PC_PREFIX "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH M3G_PC_UP "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
  set(M3G_PC_PREFIX "\${pcfiledir}/${M3G_PC_UP}")
endif()
# Shared: libm3g.so holds everything (cmake/SharedLibraries.cmake), so m3g
# does not require m3g-scene. Static: m3g is the renderer on top of
# m3g-scene, and the --undefined keeps the renderer's self-registration
# (render-vk/Backend.cpp), which nothing names, in the link.
if(BUILD_SHARED_LIBS)
  set(M3G_PC_REQUIRES "Requires.private: libpng libjpeg zlib")
  set(M3G_PC_SCENE_LIBS "-lm3g_scene")
  set(M3G_PC_M3G_REQUIRES "Requires.private: libpng libjpeg zlib")
  set(M3G_PC_VK_LIBS "-lm3g -pthread")
else()
  set(M3G_PC_REQUIRES "Requires: libpng libjpeg zlib")
  set(M3G_PC_SCENE_LIBS "-lm3g_scene -lm3g_skin")
  set(M3G_PC_M3G_REQUIRES "Requires: m3g-scene = ${PROJECT_VERSION}")
  set(M3G_PC_VK_LIBS "-Wl,--undefined=m3g_vk_backend_anchor -lm3g_render_vk -lm3g_volk")
  if(CMAKE_DL_LIBS)
    string(APPEND M3G_PC_VK_LIBS " -l${CMAKE_DL_LIBS}")
  endif()
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/m3g-scene.pc.in ${CMAKE_BINARY_DIR}/pkgconfig/m3g-scene.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/pkgconfig/m3g-scene.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
if(M3G_VULKAN)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/m3g.pc.in ${CMAKE_BINARY_DIR}/pkgconfig/m3g.pc @ONLY)
  install(FILES ${CMAKE_BINARY_DIR}/pkgconfig/m3g.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endif()
