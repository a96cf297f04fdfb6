# Renders a few shared-corpus files twice at the same size, through the same
# camera: `m3g render` from the .m3g, and f3d (Debian's f3d 1.3.1) from the
# `m3g export` of it through the glTF camera (`--camera-index 0`). Both clear
# to a key colour that no file uses, and `m3g compare --coverage --key`
# compares which pixels each covers. Colours are not compared: glTF is PBR and
# f3d lights the scene its own way. A wrong camera (fov, aspect, transform), a
# mirrored model or a wrong up axis moves or resizes the silhouettes and fails.
# docs/export.md ("Rendered by f3d") has the files, the figures and why the
# limits are what they are.
#
# Run under xvfb-run (f3d 1.3.1 needs an X display and has no offscreen mode);
# f3d then draws with Mesa's software rasterizer, as `m3g render` does on
# lavapipe. Prints "SKIPPED: ..." without f3d, a display or the corpus.
#   xvfb-run -a cmake -DM3G=... -DF3D=... -DCORPUS=../shared/corpus -DOUT=build/gltf-f3d -P render_compare.cmake
if(NOT F3D OR NOT EXISTS "${F3D}")
  message("SKIPPED: f3d not found (scripts/setup installs f3d)")
  return()
endif()
if("$ENV{DISPLAY}" STREQUAL "")
  message("SKIPPED: no X display for f3d (scripts/setup installs xvfb, whose xvfb-run the test uses)")
  return()
endif()
if(NOT EXISTS "${CORPUS}/models")
  message("SKIPPED: shared corpus not found at ${CORPUS}/models")
  return()
endif()

# Key colour of both backgrounds: magenta, which none of these files draws.
set(key FF00FF)
# Limits (docs/export.md): the renders agree to the pixel but for a few
# pixels of skinned silhouettes; a 1 degree error of the field of view
# already drops the teapot to an IoU of 0.93.
set(min_iou 0.99)
set(max_share 0.005)

# file (under models/) | size (the camera's aspect ratio: f3d ignores the
# glTF aspectRatio and fills the window, M3G stretches its camera's aspect
# over the viewport) | world time in ms
set(cases
  "BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/teapot.m3g|240x240|0"
  "BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/scene.m3g|240x240|0"
  "BaalNetbek__M3G-Viewer/com.wizzer.m3g.toolkit/test/memory.m3g|320x240|0"
  "j2me-preservation__midpath/demos/resources/org/thenesis/midpath/demo/m3g/data/robot.m3g|360x240|0"
  "jacques-gasselin__m3x/tools/test/data/nokia_on_ice.m3g|240x240|0"
  "jacques-gasselin__m3x/tools/test/data/otokka_jump2.m3g|216x240|4556"
  "vadosnaprimer__desktop-m3g/sample/sample-12-loader/test.m3g|360x240|0")

file(MAKE_DIRECTORY "${OUT}")
set(failures 0)
set(compared 0)
foreach(c ${cases})
  string(REPLACE "|" ";" fields "${c}")
  list(GET fields 0 rel)
  list(GET fields 1 size)
  list(GET fields 2 time)
  set(f "${CORPUS}/models/${rel}")
  if(NOT EXISTS "${f}")
    message("SKIPPED: ${rel} not in the corpus")
    return()
  endif()
  string(MAKE_C_IDENTIFIER "${rel}" name)
  string(REPLACE "x" "," resolution "${size}")
  execute_process(COMMAND "${M3G}" export "${f}" -o "${OUT}/${name}.glb" --time ${time} --quiet
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    math(EXPR failures "${failures} + 1")
    message("FAIL export ${rel}: ${err}")
    continue()
  endif()
  execute_process(COMMAND "${M3G}" render "${f}" -o "${OUT}/${name}.m3g.png" --size ${size} --time ${time}
                          --background ${key}FF
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR err MATCHES "m3g-vk validation")
    math(EXPR failures "${failures} + 1")
    message("FAIL m3g render ${rel}: exit ${rc} ${err}")
    continue()
  endif()
  # --dry-run: no user configuration file changes the render.
  execute_process(COMMAND "${F3D}" "${OUT}/${name}.glb" --camera-index 0 --output "${OUT}/${name}.f3d.png"
                          --resolution ${resolution} --bg-color 1,0,1 --dry-run
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  if(NOT rc EQUAL 0)
    math(EXPR failures "${failures} + 1")
    message("FAIL f3d ${rel}: exit ${rc} ${out}${err}")
    continue()
  endif()
  execute_process(COMMAND "${M3G}" compare "${OUT}/${name}.m3g.png" "${OUT}/${name}.f3d.png" --coverage --key ${key}
                          --min-iou ${min_iou} --max-share ${max_share} --diff "${OUT}/${name}.diff.png"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE report ERROR_VARIABLE err)
  string(REGEX MATCH "covered pixels[^\n]*: ([0-9]+) in A, ([0-9]+) in B" counts "${report}")
  set(covered "${CMAKE_MATCH_1} / ${CMAKE_MATCH_2}")
  string(REGEX MATCH "intersection over union: ([0-9.]+)" iou "${report}")
  set(iou "${CMAKE_MATCH_1}")
  string(REGEX MATCH "covered in one image only: ([0-9]+)" only "${report}")
  set(only "${CMAKE_MATCH_1}")
  if(NOT rc EQUAL 0)
    math(EXPR failures "${failures} + 1")
    message("FAIL ${rel} (${size}, t=${time}): covered ${covered} (m3g / f3d), ${only} in one only, IoU ${iou}; "
            "diff: ${OUT}/${name}.diff.png\n${report}${err}")
    continue()
  endif()
  math(EXPR compared "${compared} + 1")
  message("ok   ${rel} (${size}, t=${time}): covered ${covered} (m3g / f3d), ${only} in one only, IoU ${iou}")
endforeach()
if(failures GREATER 0)
  message(FATAL_ERROR "${failures} f3d renders disagree with m3g render or failed (${compared} agree)")
endif()
message("all ${compared} f3d renders of the exports cover what m3g render covers (IoU >= ${min_iou})")
