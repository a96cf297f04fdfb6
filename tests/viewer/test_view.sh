#!/usr/bin/env bash
# The viewer under Xvfb on lavapipe with validation: its 3D view equals the
# headless renderer's image and the golden one; scripted input orbits,
# resets and picks. Usage: test_view.sh M3G GOLDEN_DIR WORK_DIR
# Exit 77 (CTest: skipped) when there is no xvfb-run.
set -euo pipefail
m3g=$(realpath "$1") golden=$(realpath "$2") work=$3
if ! command -v xvfb-run >/dev/null; then
  echo "SKIP: xvfb-run is not installed (Debian: xvfb xauth)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
export VK_DRIVER_FILES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json M3G_VK_VALIDATION=1
export XDG_CONFIG_HOME="$work/config"  # settings of a test run stay in the test
view() { xvfb-run -a -s "-screen 0 800x600x24" "$m3g" view "$@"; }

"$m3g" sample -o "$work/sample.m3g"
"$m3g" render "$work/sample.m3g" --size 320x240 --time 500 -o "$work/render.png"

# 1. Unattended: three frames, then the screenshot of the 3D view.
view "$work/sample.m3g" --size 320x240 --time 500 --no-ui --no-headlight --frames 3 --screenshot "$work/view.png"
echo "== window frame vs headless render (must be identical)"
"$m3g" compare "$work/view.png" "$work/render.png" --threshold 0 --max-share 0
echo "== window frame vs golden image"
"$m3g" compare "$work/view.png" "$golden/viewer_sample.png" --threshold 8 --max-share 0.01

# 2. Scripted input, with the UI drawn (the screenshot is the 3D view only).
cat > "$work/script.txt" <<'SCRIPT'
time 500
frames 2
screenshot file-camera.png
camera -1
screenshot framed.png
scroll 6
screenshot zoomed.png
drag left 100 100 160 130
screenshot orbited.png
key r
screenshot reset.png
click 160 120
expect-pick Mesh
click 2 2
expect-pick none
SCRIPT
(cd "$work" && view sample.m3g --size 320x240 --no-headlight --script script.txt)
differs() {  # more than 5% of the pixels change
  if "$m3g" compare "$1" "$2" --threshold 8 --max-share 0.05; then
    echo "FAIL: $1 and $2 should differ"; exit 1
  fi
}
echo "== file camera = headless render"
"$m3g" compare "$work/file-camera.png" "$work/render.png" --threshold 0 --max-share 0
echo "== zooming (the sample's fog hides the scene at the framing distance) and a drag move the view"
differs "$work/zoomed.png" "$work/framed.png"
differs "$work/orbited.png" "$work/zoomed.png"
echo "== reset returns to the framed view"
# (framed on the animated pose: the sample's cube has moved since the load)
"$m3g" compare "$work/reset.png" "$work/framed.png" --threshold 8 --max-share 0.01
echo "viewer test: ok"
