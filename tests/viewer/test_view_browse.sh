#!/usr/bin/env bash
# The viewer's file browser and texture inspector under Xvfb on lavapipe
# with validation, driven by a script:
# - a folder holding an M3G file named .res, a PNG, a text file and a
#   sub-folder lists the folder, the .res (by its identifier bytes) and
#   nothing else; entries enter folders and open files; the opened file
#   heads the recent files;
# - a dropped text file gets a message in the Messages panel (no crash, the
#   scene stays), a dropped folder opens the browser there;
# - the inspector reports the sample's checkerboard texels (32x32 RGB, 8x8
#   squares of (240,200,60) and (40,90,160): tools/m3g/SampleScene.cpp) at
#   given coordinates and under given window points at zoom 8, and draws
#   them nearest-neighbour (texel edges sharp in the window's image).
# Usage: test_view_browse.sh M3G WORK_DIR. Exit 77 (CTest: skipped) without xvfb-run.
set -euo pipefail
m3g=$(realpath "$1") work=$2
if ! command -v xvfb-run >/dev/null; then
  echo "SKIP: xvfb-run is not installed (Debian: xvfb xauth)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
work=$(realpath "$work")
export VK_DRIVER_FILES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json M3G_VK_VALIDATION=1
export XDG_CONFIG_HOME="$work/config"  # default layout; settings of a test run stay in the test
view() { xvfb-run -a -s "-screen 0 1280x1024x24" "$m3g" view "$@"; }
fail() { echo "FAIL: $*"; exit 1; }

# The folder: an M3G file named as games name them, a PNG, a text file, a sub-folder.
dir="$work/game"
mkdir -p "$dir/sub"
"$m3g" sample -o "$work/sample.m3g"
cp "$work/sample.m3g" "$dir/model.res"
cp "$work/sample.m3g" "$dir/sub/inner.mod"
"$m3g" render "$dir/model.res" -o "$dir/picture.png" --size 64x48 >/dev/null
echo "not a model" > "$dir/notes.txt"

cat > "$work/browse.txt" <<SCRIPT
frames 1
# The folder given as FILE: the browser is open there.
browse-list listing.txt
# A dropped text file: a message, no scene, no crash.
drop $dir/notes.txt
frames 1
expect-error not M3G data
screenshot-ui drop-error.png
# Entry 1 is the sub-folder: enter, list, back up.
browse $dir
browse-open 1
browse-list sub-listing.txt
browse-open 0
# Entry 2 is model.res.
browse-open 2
expect-error none
expect-scene model.res
recent recent.txt
# A dropped folder opens the browser there.
drop $dir/sub
browse-list dropped-listing.txt
browse-close
# The checkerboard is the first Image2D of the sample (the Textures tab's 0).
inspect 0 8
frames 2
layout
texel 0 0 texels.txt
texel 8 0 texels.txt
texel 31 31 texels.txt
texel 15 16 texels.txt
screenshot-ui inspector.png
SCRIPT
(cd "$work" && view "$dir" --size 1000x700 --script browse.txt 2> stderr.txt) || { cat "$work/stderr.txt"; fail "viewer run failed"; }
cat "$work/stderr.txt"

echo "== the listing: parent, folder, the .res; the PNG and the text file not listed"
cat > "$work/expected-listing.txt" <<EXPECTED
# $dir
0 parent ..
1 folder sub
2 m3g model.res
# other files: 2
EXPECTED
diff "$work/expected-listing.txt" "$work/listing.txt" || fail "folder listing"
printf '# %s\n0 parent ..\n1 m3g inner.mod\n# other files: 0\n' "$dir/sub" > "$work/expected-sub.txt"
diff "$work/expected-sub.txt" "$work/sub-listing.txt" || fail "sub-folder listing"
diff "$work/expected-sub.txt" "$work/dropped-listing.txt" || fail "dropped folder listing"
grep -q "not M3G data .*an unrecognised file" "$work/stderr.txt" || fail "no message for the dropped text file"
[ "$(head -n 1 "$work/recent.txt")" = "$dir/model.res" ] || fail "recent files: $(cat "$work/recent.txt")"

echo "== texels by coordinates"
cat > "$work/expected-texels.txt" <<EXPECTED
texel (0, 0) RGB 240 200 60
texel (8, 0) RGB 40 90 160
texel (31, 31) RGB 240 200 60
texel (15, 16) RGB 40 90 160
EXPECTED
diff "$work/expected-texels.txt" "$work/texels.txt" || fail "texel values"

echo "== texels under window points at zoom 8"
read -r ix iy iw ih < <(sed -n 's/.*layout inspector-image \([-0-9.]*\) \([-0-9.]*\) \([-0-9.]*\) \([-0-9.]*\)$/\1 \2 \3 \4/p' "$work/stderr.txt")
[ -n "${ix:-}" ] || fail "no inspector rectangle in the layout"
[ "$iw" = 256 ] && [ "$ih" = 256 ] || fail "a 32x32 image at zoom 8 is drawn ${iw}x${ih}, not 256x256"
# Texel (9, 9) is a (240,200,60) square, (8, 7) a (40,90,160) one; window
# points inside them, and one just left of the image.
px=$((ix + 9 * 8 + 3)) py=$((iy + 9 * 8 + 5))
qx=$((ix + 8 * 8)) qy=$((iy + 7 * 8 + 7))
ox=$((ix - 1))
cat > "$work/hover.txt" <<SCRIPT
inspect 0 8
frames 2
hover $px $py hover-out.txt
hover $qx $qy hover-out.txt
hover $ox $py hover-out.txt
# Nearest-neighbour: the last window pixel of texel (7, 7) and the first of
# (8, 7) have their texels' colours, not a blend.
screenshot-ui hover-ui.png
expect-pixel hover-ui.png $((ix + 7 * 8 + 7)) $((iy + 7 * 8 + 4)) F0C83C
expect-pixel hover-ui.png $((ix + 8 * 8)) $((iy + 7 * 8 + 4)) 285AA0
SCRIPT
(cd "$work" && view "$dir/model.res" --size 1000x700 --script hover.txt)
cat > "$work/expected-hover.txt" <<EXPECTED
hover $px $py: (9, 9) RGB 240 200 60
hover $qx $qy: (8, 7) RGB 40 90 160
hover $ox $py: none
EXPECTED
diff "$work/expected-hover.txt" "$work/hover-out.txt" || fail "texels under the cursor"
echo "viewer browse test: ok"
