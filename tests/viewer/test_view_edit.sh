#!/usr/bin/env bash
# The viewer's docked layout, editing, undo/redo, saving and numbered
# screenshots under Xvfb on lavapipe with validation, driven by a script:
# - with the panels shown the 3D view is the rectangle between the columns,
#   and the window's pixels at its corners are the sample's background;
# - a material colour edited (with undo/redo on the way) is saved, and the
#   saved file reloads (m3g info --json, and a second viewer run) with the
#   same objects and the edited values;
# - `screenshot` without a path and the S key write m3g-screenshot-NNNN.png,
#   never over an existing file.
# Usage: test_view_edit.sh M3G WORK_DIR. Exit 77 (CTest: skipped) without xvfb-run.
set -euo pipefail
m3g=$(realpath "$1") work=$2
if ! command -v xvfb-run >/dev/null; then
  echo "SKIP: xvfb-run is not installed (Debian: xvfb xauth)"
  exit 77
fi
rm -rf "$work" && mkdir -p "$work"
export VK_DRIVER_FILES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json M3G_VK_VALIDATION=1
export XDG_CONFIG_HOME="$work/config"  # default layout; settings of a test run stay in the test
view() { xvfb-run -a -s "-screen 0 1280x1024x24" "$m3g" view "$@"; }
fail() { echo "FAIL: $*"; exit 1; }

"$m3g" sample -o "$work/sample.m3g"
"$m3g" info --json "$work/sample.m3g" > "$work/sample.json"
# The sample's Material, by `m3g info` id (the viewer's script uses the same ids).
mat=$(awk '/^      "id": /{id=$2; sub(",", "", id)} /"class": "Material"/{print id; exit}' "$work/sample.json")
[ -n "$mat" ] || fail "no Material in the sample's m3g info --json"
echo "== the sample's Material is #$mat"

# A file already named m3g-screenshot-0001.png: the numbering goes on after it.
echo "not a screenshot" > "$work/m3g-screenshot-0001.png"

# 1000x600 window, default layout (left column 240, right 330, menu bar 19):
# the view is 1000 - 240 - 330 - 2*4 = 422 wide at x = 244.
cat > "$work/edit.txt" <<SCRIPT
time 500
pause
frames 2
expect-view 244 19 422 581
layout
screenshot view.png
screenshot-ui ui.png
# The view's top corners (inside it) in the whole window are the background.
expect-pixel ui.png 244 19 1E2838
expect-pixel ui.png 665 19 1E2838
# Edits, undo and redo.
select $mat
edit $mat diffuse 1 0 0 1
expect $mat diffuse 1 0 0 1
edit $mat shininess 50
expect $mat shininess 50
undo
expect $mat diffuse 1 0 0 1
redo
expect $mat shininess 50
undo
edit $mat emissive 0 0 1
undo
expect $mat emissive 0 0 0
save edited.m3g
frames 1
screenshot-ui edited-ui.png
screenshot edited-view.png
# Numbered screenshots (0001 exists): 0002, 0003, then the S key: 0004.
screenshot
screenshot
key s
# F1 / panels off: the view is the whole window.
panels off
expect-view 0 0 1000 600
panels on
expect-view 244 19 422 581
SCRIPT
(cd "$work" && view sample.m3g --size 1000x600 --no-headlight --script edit.txt)

echo "== numbered screenshots: 0001 untouched, 0002..0004 written"
[ "$(cat "$work/m3g-screenshot-0001.png")" = "not a screenshot" ] || fail "m3g-screenshot-0001.png was overwritten"
for n in 0002 0003 0004; do
  [ -s "$work/m3g-screenshot-$n.png" ] || fail "m3g-screenshot-$n.png missing"
done
[ ! -e "$work/m3g-screenshot-0005.png" ] || fail "one screenshot too many"
echo "== a numbered screenshot is the view rectangle's image"
"$m3g" compare "$work/edited-view.png" "$work/m3g-screenshot-0002.png" --threshold 8 --max-share 0.01 >/dev/null ||
  fail "numbered screenshot differs from the view screenshot"

echo "== the saved file reloads with the same objects and the edited values"
"$m3g" info --json "$work/edited.m3g" > "$work/edited.json"
count() { sed -n 's/^  "objectCount": \([0-9]*\).*/\1/p' "$1"; }
[ "$(count "$work/sample.json")" = "$(count "$work/edited.json")" ] ||
  fail "object count $(count "$work/sample.json") -> $(count "$work/edited.json")"
field() {  # field FILE ID NAME: the value of NAME in object ID
  awk -v id="$2" -v name="\"$3\":" '/^      "id": /{cur=$2; sub(",", "", cur)} cur==id && $1==name {v=$2; sub(",", "", v); print v; exit}' "$1"
}
[ -n "$(count "$work/sample.json")" ] || fail "no objectCount in m3g info --json"
[ -n "$(field "$work/sample.json" "$mat" shininess)" ] || fail "no shininess of #$mat in m3g info --json"
[ "$(field "$work/edited.json" "$mat" diffuseColor)" = '"0xFFFF0000"' ] || fail "diffuse is $(field "$work/edited.json" "$mat" diffuseColor)"
[ "$(field "$work/edited.json" "$mat" shininess)" = "$(field "$work/sample.json" "$mat" shininess)" ] || fail "the undone shininess was saved"
[ "$(field "$work/edited.json" "$mat" emissiveColor)" = "$(field "$work/sample.json" "$mat" emissiveColor)" ] || fail "the undone emissive was saved"
diff <(grep -c '"class"' "$work/sample.json") <(grep -c '"class"' "$work/edited.json") >/dev/null || fail "class count differs"

echo "== a second viewer run reads the edited value back"
cat > "$work/check.txt" <<SCRIPT
frames 1
expect $mat diffuse 1 0 0 1
SCRIPT
(cd "$work" && view edited.m3g --size 640x480 --script check.txt)
echo "viewer edit test: ok"
