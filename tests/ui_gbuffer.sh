#!/bin/sh
# Opening another program's G-buffer in the real editor under Xvfb at 1280x720 (issue 28). The
# G-buffer is written by `gbuffer-lab render --out`, the folder `render --gbuffer` also opens.
#  1. A UI test script drops the folder on the window (the drop path GLFW's callback feeds): the
#     viewport shows the re-lit frame at the G-buffer's size, a light edit changes it, bad inputs
#     (missing file, bad manifest, size mismatch, unreadable image) are each refused with one
#     sentence while what was shown stays, and Close G-buffer gives back the scene's frame.
#  2. `--gbuffer DIR` with real X input (xdotool): the frame log names the G-buffer and its size,
#     and a mouse drag over the viewport leaves the fixed camera where it was.
#  2b. A manifest that reads the export's albedo as biased normals: findings; real clicks on the
#     viewport's Checks button and its first finding mark that finding, a second click unmarks it.
#  2c. File > Open G-buffer... with real clicks, the folder's path typed and Enter: it is shown.
#  2d. A real X drag-and-drop (tests/support/xdnd_drop, XDND as a file manager does it) of a manifest
#      in a folder with a space in its name, then of the export's folder: each is shown in the
#      viewport and the viewers at its own size.
#  3. `--gbuffer` of a bad manifest: exit code 2 and one sentence.
# usage: ui_gbuffer.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"

ui_name=ui_gbuffer
log=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

# --- the G-buffers: one good export, and one of each bad kind --------------------------------
"$bin" render --out "$work/export" --size 480x270 --lights 6 > "$work/render.log" 2>&1 ||
    fail "render --out failed: $(tail -n 2 "$work/render.log")"
"$bin" render --out "$work/small" --size 240x135 --lights 6 >> "$work/render.log" 2>&1 ||
    fail "render --out (small) failed"
mkdir -p "$work/bad"
printf '{"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "learnopengl", "normal": {"encoding": "spherical"}}\n' \
    > "$work/bad/manifest.json"
cp -r "$work/export" "$work/mismatch"
cp "$work/small/albedo.png" "$work/mismatch/albedo.png"
cp -r "$work/export" "$work/unreadable"
echo "not an image" > "$work/unreadable/normal.exr"
lights=$(grep -o '"position"' "$work/export/lights.json" | wc -l)
[ "$lights" -ge 1 ] || fail "the export has no lights in lights.json"

# --- 1. the drop path and bad inputs, driven by a UI test script ------------------------------
cat > "$work/script.txt" <<SCRIPT
frames 3
expect-scene default
expect-gbuffer none
capture scene
# Bad inputs before anything is open: one sentence each, the scene stays.
open-gbuffer $work/nowhere/manifest.json
frames 2
expect-gbuffer none
expect-gbuffer-error cannot read the manifest
expect-log The scene stays shown.
drop-files $work/bad/manifest.json
frames 2
expect-gbuffer none
expect-gbuffer-error manifest.json: normal.encoding
# The folder dropped as GLFW hands it over: the re-lit G-buffer replaces the scene's frame.
drop-files $work/export
frames 4
expect-gbuffer $work/export
expect-lights $lights
expect-log re-lit from its own camera
expect-no-gl-errors
capture relit
expect-different scene relit 0.02
screenshot $work/gbuffer_open.png
# The lights stay editable over it: light 0 off changes the frame.
light 0 intensity 0
frames 3
capture dimmer
expect-different relit dimmer 0.0005
light 0 intensity 1
# A session saved while it is open stores the scene behind it (its 32 lights), not the G-buffer's.
save-session $work/while_open.json
# Bad inputs while it is open: refused, the G-buffer stays.
drop-files $work/mismatch
frames 2
expect-gbuffer $work/export
expect-gbuffer-error every attachment must have the frame's size
expect-log stays shown.
open-gbuffer $work/unreadable
frames 2
expect-gbuffer $work/export
expect-gbuffer-error normal.file
expect-no-gl-errors
# Close G-buffer: the scene's frame again, as it was.
close-gbuffer
frames 4
expect-gbuffer none
expect-lights 32
capture back
expect-same scene back 0.002
expect-no-gl-errors
SCRIPT
"$bin" --ui-test "$work/script.txt" --size 1280x720 --no-vsync --log-frames "$work/script.jsonl" \
    > "$work/script.log" 2>&1 || fail "the UI test script failed: $(grep -m 3 'FAIL' "$work/script.log")"
grep -q "ui-test FAIL" "$work/script.log" && fail "$(grep -m 3 'ui-test FAIL' "$work/script.log")"
# The frame log of the script run: the G-buffer's frame size while open, the window's viewport after.
log="$work/script.jsonl"
grep -q "\"gbuffer\":\"$work/export\".*\"frameSize\":\[480,270\]" "$log" ||
    fail "no frame logged the G-buffer at 480x270"
[ "$(field gbuffer)" = '""' ] || fail "the last frame still shows G-buffer $(field gbuffer)"
saved=$(grep -o '"kq"' "$work/while_open.json" | wc -l)
[ "$saved" = 32 ] || fail "the session saved with the G-buffer open holds $saved lights, not the scene's 32"
grep -q '"source": *"default"' "$work/while_open.json" || fail "the session saved with the G-buffer open names no default scene"

# --- 2. --gbuffer and real X input: the camera stays fixed ------------------------------------
ui_start gbuffer --gbuffer "$work/export" --size 1280x720 --frame-sleep-ms 20
[ "$(field gbuffer)" = "\"$work/export\"" ] || fail "the frame log names G-buffer $(field gbuffer)"
[ "$(field frameSize)" = "[480,270]" ] || fail "the frame is $(field frameSize), not the G-buffer's 480x270"
set -- $(field viewport | tr -d '[]' | tr ',' ' ')
# Letterboxed at the G-buffer's aspect (16:9): width / height within a pixel of it.
awk -v w="$3" -v h="$4" 'BEGIN { exit !(w > 100 && h > 50 && (w / h - 480 / 270) ^ 2 < 0.01) }' ||
    fail "the viewport image is $3x$4, not letterboxed at 480:270"
camera=$(field camera)
set -- $(rect_point viewport 0.5 0.5)
xdotool mousemove --window "$wid" "$1" "$2" sleep 0.1 mousedown 1 mousemove_relative --sync 60 30 \
    sleep 0.1 mousemove_relative --sync 60 30 sleep 0.1 mouseup 1
wait_frames 4
[ "$(field camera)" = "$camera" ] || fail "a drag moved the fixed camera from $camera to $(field camera)"
[ "$(field gbuffer)" = "\"$work/export\"" ] || fail "the G-buffer closed during the drag"
shot gbuffer_live
# A lesson brings its own scene: a real click on the course's first row starts it, which closes the
# G-buffer, so the lesson shows on the scene and Leave returns to the scene.
set -- $(rect_point courseRows 0.5 0.5)
[ "${1:-0}" -gt 0 ] || fail "the course's first row is not wholly in view: $(field courseRows)"
click_at "$1" "$2"
wait_frames 6
[ "$(field gbuffer)" = '""' ] || fail "starting a lesson left G-buffer $(field gbuffer) shown"
[ "$(field lesson)" != '""' ] || fail "the click on the course's first row opened no lesson"
ui_quit "Ctrl+Q did not quit the editor showing a G-buffer"

# --- 2b. The checks with real clicks: a manifest over the export that reads the albedo as biased
# normals (a classic mislabelled attachment) has findings; the Checks button lists them and a
# click on the first marks its pixels, a second click unmarks them; the list ends with the precision notes.
printf '%s\n' '{"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "gbuffer-lab",' \
    ' "normal": {"file": "albedo.png", "channels": "rgb", "encoding": "biased", "space": "world"},' \
    ' "camera": {"position": [0, 5, 11.5], "target": [0, 4.716, 10.541], "fov_y_degrees": 60, "near": 0.1, "far": 200},' \
    ' "lights": {"positions": [[0, 2, 0]], "colors": [[1, 1, 1]], "linear": 0.7, "quadratic": 1.8}}' \
    > "$work/export/bad_normals.json"
ui_start checks --gbuffer "$work/export/bad_normals.json" --size 1280x720 --frame-sleep-ms 20
[ "$(field findings)" -gt 0 ] || fail "the mislabelled normals gave no finding"
[ "$(field markedFinding)" = -1 ] || fail "a finding is marked before any click"
set -- $(rect_point checksButton 0.5 0.5)
[ "${1:-0}" -gt 0 ] || fail "no Checks button with a G-buffer open: $(field checksButton)"
click_at "$1" "$2"
set -- $(rect_point firstFinding 0.1 0.5)
[ "${1:-0}" -gt 0 ] || fail "the Checks list did not open: $(field firstFinding)"
# Below the findings, a precision line per attachment of the manifest (normal, and the preset's others).
[ "$(field precisionLines)" -ge 2 ] || fail "the Checks list showed $(field precisionLines) precision lines"
click_at "$1" "$2"
[ "$(field markedFinding)" = 0 ] || fail "clicking the first finding marked $(field markedFinding), not 0"
shot checks_marked
click_at "$1" "$2"
[ "$(field markedFinding)" = -1 ] || fail "a second click left finding $(field markedFinding) marked"
xdotool key --delay 30 Escape
wait_frames 2
ui_quit "Ctrl+Q did not quit the editor showing the checks"

# wait_gbuffer PATH WHAT: waits (at most 200 frames) until the frame log names G-buffer PATH, then four
# frames more; fails naming WHAT (the action that should have opened it) and what is shown instead.
wait_gbuffer() {
    tries=0
    until [ "$(field gbuffer)" = "\"$1\"" ]; do
        tries=$((tries + 1))
        [ "$tries" -le 200 ] || fail "$2 opened G-buffer $(field gbuffer), not $1 (browser open: $(field gbufferBrowser))"
        wait_frames 1
    done
    wait_frames 4
}

# --- 2c. File > Open G-buffer... with real input: a click on File, a click on the item, the folder's
# path typed into the browser's Name field (focused as it opens), Enter: the export is shown.
ui_start menu --size 1280x720 --frame-sleep-ms 20
[ "$(field gbuffer)" = '""' ] || fail "the editor started with G-buffer $(field gbuffer) shown"
set -- $(rect_point fileMenu 0.5 0.5)
[ "${1:-0}" -gt 0 ] || fail "the menu bar's File was not logged: $(field fileMenu)"
click_at "$1" "$2"
set -- $(rect_point openGBufferItem 0.3 0.5)
[ "${1:-0}" -gt 0 ] || fail "clicking File at $1,$2 showed no Open G-buffer item: $(field openGBufferItem)"
click_at "$1" "$2"
[ "$(field gbufferBrowser)" = true ] || fail "clicking Open G-buffer... opened no file browser"
xdotool key --delay 30 ctrl+a
xdotool type --delay 30 "$work/export"
xdotool key --delay 30 Return
wait_gbuffer "$work/export" "typing $work/export and Enter"
[ "$(field gbufferBrowser)" = false ] || fail "the file browser stayed open after Enter"
[ "$(field frameSize)" = "[480,270]" ] || fail "the G-buffer opened from the menu is $(field frameSize), not 480x270"
shot menu_opened
ui_quit "Ctrl+Q did not quit the editor after File > Open G-buffer"

# --- 2d. A real drag-and-drop: tests/support/xdnd_drop.c drags as a file manager does (XDND), so the
# drop comes through X and GLFW's own handling of it rather than the UI script's drop-files. A manifest
# (preset gbuffer-lab) of a square export, in a folder with a space in its name (the URI carries it as
# %20), dropped on the viewport opens it; then the 480x270 export's folder: the viewport and all five
# viewers take each G-buffer's own size.
xdnd="${GBL_XDND_DROP:-}"
if [ -z "$xdnd" ]; then
    echo "$ui_name: part 2d skipped: no xdnd_drop (tests/CMakeLists.txt builds it where X11's headers are)"
else
    [ -x "$xdnd" ] || fail "xdnd_drop is not built at $xdnd (make xdnd_drop)"
    "$bin" render --out "$work/drop here" --size 320x320 --lights 6 >> "$work/render.log" 2>&1 ||
        fail "render --out into a folder with a space in its name failed"
    # The preset names the folder's files; the camera (render's default view) and lights are the manifest's.
    printf '%s\n' '{"format": "gbuffer-lab-gbuffer", "version": 1, "preset": "gbuffer-lab",' \
        ' "camera": {"position": [0, 5, 11.5], "target": [0, 4.716, 10.541], "fov_y_degrees": 60, "near": 0.1, "far": 200},' \
        ' "lights": {"positions": [[0, 2, 0], [-4, 2, 3], [4, 2, 3]], "colors": [[1, 1, 1], [1, 0.3, 0.2], [0.2, 0.4, 1]],' \
        '            "linear": 0.14, "quadratic": 0.07}}' > "$work/drop here/manifest.json"
    # drag_drop PATH: a real drag of PATH onto the viewport's centre, which the editor's window must take.
    drag_drop() {
        eval "$(xdotool getwindowgeometry --shell "$wid")"
        at=$(rect_point viewport 0.5 0.5 | awk -v x="$X" -v y="$Y" '{ print $1 + x, $2 + y }')
        # $at unquoted: "X Y" is two arguments. Its output goes to .out: a crash report names the newest .log.
        "$xdnd" --timeout 60 $at "$1" > "$work/xdnd.out" 2>&1 ||
            fail "the drag of $1 to $at failed: $(cat "$work/xdnd.out")"
        grep -qF "($wid)" "$work/xdnd.out" || fail "the drop did not reach the editor's window $wid: $(cat "$work/xdnd.out")"
    }
    # shows PATH W H: the frame log names G-buffer PATH (within 200 frames of the drop) at WxH, and the
    # five viewers each draw a W:H image (a viewer fits the frame's own size into its cell).
    shows() {
        wait_gbuffer "$1" "the drop of $1"
        [ "$(field frameSize)" = "[$2,$3]" ] || fail "the dropped $1 is shown at $(field frameSize), not $2x$3"
        grep -qF "G-buffer $1: $2x$3" "$work/drop.log" || fail "the editor did not log opening $1 at $2x$3"
        viewers=$(field viewerImages | tr -d '[]' | tr ',' '\n' | paste -d' ' - - - - |
            awk -v w="$2" -v h="$3" '$3 > 20 && $4 > 20 && ($3 * h / ($4 * w) - 1) ^ 2 < 1e-4 { n++ } END { print n + 0 }')
        [ "$viewers" = 5 ] || fail "$viewers of the 5 viewers show a $2:$3 image: $(field viewerImages)"
    }
    ui_start drop --size 1280x720 --frame-sleep-ms 20
    [ "$(field gbuffer)" = '""' ] || fail "the editor started with G-buffer $(field gbuffer) shown"
    [ "$(field frameSize)" != "[320,320]" ] || fail "the scene's frame is square already: the square drop would prove nothing"
    drag_drop "$work/drop here/manifest.json"
    shows "$work/drop here/manifest.json" 320 320
    shot drop_manifest
    drag_drop "$work/export"
    shows "$work/export" 480 270
    shot drop_folder
    ui_quit "Ctrl+Q did not quit the editor after the drops"
fi

# --- 3. --gbuffer of a bad manifest: one sentence, exit code 2 --------------------------------
set +e
"$bin" --gbuffer "$work/bad/manifest.json" --frames 3 --size 320x200 > "$work/bad.log" 2>&1
rc=$?
set -e
[ "$rc" = 2 ] || fail "--gbuffer of a bad manifest exited with $rc, not 2"
[ "$(grep -c 'normal.encoding' "$work/bad.log")" = 1 ] || fail "not one sentence: $(cat "$work/bad.log")"

echo "$ui_name: PASS (screenshot $work/gbuffer_open.png)"
