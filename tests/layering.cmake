# Fails if a layer below render-vk includes Vulkan or GLFW (architecture guide §2).
# Vulkan and GLFW headers live in /usr/include, so include paths alone cannot
# forbid them; this check reads the sources.
set(violations "")
foreach(dir api scene skin)
  file(GLOB_RECURSE files "${SOURCE_DIR}/${dir}/*.h" "${SOURCE_DIR}/${dir}/*.cpp" "${SOURCE_DIR}/${dir}/*.in")
  foreach(f ${files})
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](vulkan/|GLFW/|volk)")
    if(lines)
      list(APPEND violations "${f}: ${lines}")
    endif()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "layering violation (Vulkan/GLFW below render-vk):\n${violations}")
endif()
message(STATUS "layering: api/, scene/ and skin/ include no Vulkan or GLFW header")
