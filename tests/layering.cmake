# The include rules of the layers (docs/architecture.md, "What may include
# what"), checked on the sources: system headers (Vulkan, GLFW) live in
# /usr/include, so include paths alone cannot forbid them.
#   api/       std and api/ only (<m3g/Name.h>)
#   skin/      std and skin/ only
#   frame/     std, skin/ and frame/ only
#   scene/     no Vulkan, GLFW or volk
#   render-vk/ no scene/ header: it reaches scene only through frame/
set(violations "")

function(check_lines dir regex what)
  file(GLOB_RECURSE files "${SOURCE_DIR}/${dir}/*.h" "${SOURCE_DIR}/${dir}/*.cpp" "${SOURCE_DIR}/${dir}/*.in")
  foreach(f ${files})
    file(STRINGS "${f}" lines REGEX "${regex}")
    if(lines)
      set(violations "${violations}${f} (${what}): ${lines}\n")
    endif()
  endforeach()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

# No Vulkan or GLFW below render-vk.
foreach(dir api scene skin frame)
  check_lines(${dir} "^[ \t]*#[ \t]*include[ \t]*[<\"](vulkan/|GLFW/|volk)" "Vulkan or GLFW below render-vk")
endforeach()
# api/: only std headers and other api headers (no skin/, frame/ or quoted includes).
check_lines(api "^[ \t]*#[ \t]*include[ \t]*(\"|<m3g/[a-z]+/)" "api/ includes std and api only")
# frame/: std, skin/ and frame/ only.
check_lines(frame "^[ \t]*#[ \t]*include[ \t]*(\"|<m3g/[A-Z])" "frame/ includes std, skin and frame only")

# render-vk/: no header of scene/ (by name, as a quoted include).
file(GLOB_RECURSE scene_headers RELATIVE "${SOURCE_DIR}/scene" "${SOURCE_DIR}/scene/*.h")
file(GLOB_RECURSE vk_files "${SOURCE_DIR}/render-vk/*.h" "${SOURCE_DIR}/render-vk/*.cpp")
foreach(h ${scene_headers})
  get_filename_component(name "${h}" NAME)
  foreach(f ${vk_files})
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"(.*/)?${name}\"")
    if(lines)
      set(violations "${violations}${f} (render-vk reaches scene only through frame/): ${lines}\n")
    endif()
  endforeach()
endforeach()

if(violations)
  message(FATAL_ERROR "layering violations:\n${violations}")
endif()
message(STATUS "layering: api/ std+api; skin/, frame/ no M3G classes; no Vulkan below render-vk; render-vk includes no scene/ header")
