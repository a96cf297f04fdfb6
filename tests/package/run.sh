#!/usr/bin/env bash
# The installed package as its users meet it (docs/library.md): installs the
# build tree into a fresh prefix, moves the prefix (the package must be
# relocatable), and builds three programs outside the tree against it:
#   1. render/  find_package(m3g) + m3g::m3g: renders the sample scene and
#               compares it with the tree's own `m3g render` of it; the same
#               for docs/library.md's example program, which writes a PNG;
#               and examples/byod, an application with its own Vulkan device;
#   2. the same source through pkg-config (m3g.pc), with g++ alone;
#   3. scene/   find_package(m3g) + m3g::scene only: load, animate, save,
#               reload, save again; the program must not contain the renderer.
# Usage: run.sh BUILD_DIR SOURCE_DIR M3G_TOOL
set -euo pipefail
build="$1" src="$2" tool="$3"
work="$build/package-test"
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/installed" >"$work/install.log"
mv "$work/installed" "$work/moved"
prefix="$work/moved"
echo "== installed into a prefix, then moved to $prefix"

"$tool" sample -o "$work/sample.m3g" >/dev/null
"$tool" render "$work/sample.m3g" -o "$work/reference.png" --size 96x72 >/dev/null

echo "== 1. find_package(m3g) + m3g::m3g"
cmake -S "$src/tests/package/render" -B "$work/render" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >"$work/render.log"
cmake --build "$work/render" >>"$work/render.log"
"$work/render/render_check" "$work/sample.m3g" "$work/reference.png"
echo "   docs/library.md's program (render_png), compared with m3g render at 320x240:"
# The page and the file must hold the same program.
if ! diff <(awk '/^```cpp$/ && !done { grab = 1; next } grab && /^```$/ { grab = 0; done = 1 } grab' "$src/docs/library.md" | sed -n '/^#include <cstdio>/,$p') \
          <(sed -n '/^#include <cstdio>/,$p' "$src/tests/package/render/render_png.cpp"); then
  echo "docs/library.md's example differs from tests/package/render/render_png.cpp" >&2
  exit 1
fi
"$work/render/render_png" "$work/sample.m3g" "$work/docs-program.png"
"$tool" render "$work/sample.m3g" -o "$work/reference-320.png" --size 320x240 >/dev/null
"$tool" compare "$work/docs-program.png" "$work/reference-320.png" --threshold 2 --max-share 0
echo "   examples/byod (the application's own device and libvulkan):"
"$work/render/byod_example" "$work/sample.m3g" "$work/byod.png"

if [ -n "$(find "$prefix" -name 'libm3g.so*' -print -quit)" ]; then
  echo "== shared libraries: sonames and exported symbols"
  lib="$(dirname "$(find "$prefix" -name 'libm3g.so' | head -1)")"
  # Output captured first: `objdump | grep -q` fails under pipefail when
  # grep stops reading early.
  for so in libm3g libm3g_scene; do
    headers="$(objdump -p "$lib/$so.so")"
    grep -q "SONAME *$so.so.0$" <<<"$headers" || { echo "$so.so has no SONAME $so.so.0" >&2; exit 1; }
  done
  for so in libm3g.so libm3g_scene.so; do
    exported="$(nm -D -C --defined-only "$lib/$so")"
    grep -q "m3g::Graphics3D::getInstance()" <<<"$exported" || { echo "$so does not export Graphics3D::getInstance" >&2; exit 1; }
    internals="MeshDeformer\|KeyframeSampler\|m3g::detail::\|m3g::vk::Renderer\|m3g::vk::Context"
    if grep -q "$internals" <<<"$exported"; then
      echo "$so exports internals:" >&2
      grep "$internals" <<<"$exported" | head >&2
      exit 1
    fi
    echo "   $so exports $(grep -c " m3g::" <<<"$exported") m3g:: symbols and no internals"
  done
  # One library: libm3g.so alone (scene's state must exist once).
  needed="$(objdump -p "$work/render/render_check" | awk '/NEEDED/ {print $2}' | grep m3g | tr '\n' ' ')"
  [ "$needed" = "libm3g.so.0 " ] || { echo "render_check needs [$needed], not libm3g.so.0 alone" >&2; exit 1; }
  export LD_LIBRARY_PATH="$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
fi

echo "== 2. pkg-config m3g"
pcdir="$(dirname "$(find "$prefix" -name m3g.pc | head -1)")"
flags="$(PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs m3g)"
echo "   pkg-config --cflags --libs m3g: $flags"
# shellcheck disable=SC2086
g++ -std=c++20 -O1 "$src/tests/package/render/render_check.cpp" -o "$work/render_check_pc" $flags
"$work/render_check_pc" "$work/sample.m3g" "$work/reference.png"

echo "== 3. find_package(m3g) + m3g::scene (no Vulkan)"
cmake -S "$src/tests/package/scene" -B "$work/scene" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >"$work/scene.log"
cmake --build "$work/scene" >>"$work/scene.log"
"$work/scene/scene_check" "$work/sample.m3g"
if nm -C "$work/scene/scene_check" | grep -q "m3g_vk_backend_anchor\|vkCreateInstance"; then
  echo "scene_check contains the Vulkan renderer" >&2
  exit 1
fi
echo "== package: all three consumers built and passed"
