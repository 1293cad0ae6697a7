#!/bin/sh
# The G-buffer layout changed through the Pipeline window's combo with real X clicks (xdotool):
# a click opens the combo where the frame log says it is drawn, a click on "packed" picks it; the
# frame log then names the new layout and a frame is rendered with it, and a UI script in the same
# editor checks that the setting changed, no GL error happened and the lit HDR frame (the lighting
# view's tools) holds light; then in prepass mode the viewers show its thin G-buffer (normal,
# exponent, lit depth). Screenshots of both are left in WORK_DIR to look at.
# usage: ui_layout_combo.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"

ui_name=ui_layout_combo
log="$work/frames.jsonl"
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

# The script waits for the real clicks to change the layout, then checks the frame.
cat > "$work/layout.txt" <<SCRIPT
frames 3
expect-setting layout classic
wait-setting layout packed 120
frames 4
expect-setting layout packed
expect-no-gl-errors
# Without the light cubes (drawn unlit at 1.5) the values are the lit surfaces alone.
set light_cubes 0
set view lighting
viewport-tools on
viewer-tool viewport histogram on
frames 6
expect-viewer-stat viewport nan 0
expect-viewer-stat viewport max-above 0.05
screenshot $work/layout_packed_lighting.png
# prepass (issue 48): the G-buffer viewers read its thin G-buffer: the normal viewer its normals
# (the ground's +Y among them), the specular viewer its exponent (shininess, 32), the depth viewer the
# lit depth. The viewers' read-backs refresh every 30 frames: 40 frames see the prepass frame's.
set mode prepass
set view final
viewer-tool normal histogram on
viewer-tool specular histogram on
viewer-tool depth histogram on
frames 40
expect-setting mode prepass
expect-viewer-stat normal max-above 0.99
expect-viewer-stat normal min-below -0.5
expect-viewer-stat specular max-equals 32
expect-viewer-stat depth max-above 1
expect-no-gl-errors
screenshot $work/prepass_viewers.png
SCRIPT
"$bin" --size 1280x720 --no-vsync --frame-sleep-ms 60 --log-frames "$log" --ui-test "$work/layout.txt" \
    > "$work/editor.log" 2>&1 &
pid=$!
wait_frames 4
ui_window
[ "$(field layout)" = '"classic"' ] || fail "the editor starts with layout $(field layout), not classic"

# --- the wheel over the Pipeline window scrolls the combo into view (below the fold at 1280x720) --
scroll_into_view layoutCombo pipelineWindow 30
echo "the combo is in view after $wheel_steps wheel step(s): $(field layoutCombo)"

# --- a click on the combo opens its list; a click on the second entry ("packed") picks it ------
open_combo layoutCombo layoutItems 2
set -- "$item_x" "$item_y"
# The UI script (above) checks the frame and quits about ten frames after the layout changes, and a
# loaded machine's shell can count frames well after the editor logged them: from this click on, the
# editor's exit ends a wait instead of failing it (the checks below read the log it left).
click_from=$(lines)
xdotool mousemove --window "$wid" "$1" "$2" sleep 0.1 mousedown 1 sleep 0.05 mouseup 1
tries=0
until [ "$(field layout)" = '"packed"' ] || ! kill -0 "$pid" 2>/dev/null; do
    tries=$((tries + 1))
    [ "$tries" -le 200 ] || fail "200 frames after the click on packed, the layout is $(field layout)"
    wait_frames_or_exit 1
done
wait_frames_or_exit 2
[ "$(field layout)" = '"packed"' ] || fail "clicking packed at $1,$2 left layout $(field layout)"
[ "$(field layoutItems)" = "[]" ] || fail "the combo's list stayed open"
tail -n +"$(( click_from + 1 ))" "$log" | grep '"layout":"packed"' | grep -q '"rendered":true' ||
    fail "no frame was rendered with the packed layout"
echo "clicked the combo and packed at $1,$2: layout $(field layout)"

status=0
wait "$pid" || status=$?
pid=""
grep "ui-test" "$work/editor.log" || true
[ "$status" -eq 0 ] || fail "the layout script failed (exit $status, see $work/editor.log)"
grep -q "ui-test PASS .*expect-viewer-stat viewport max-above" "$work/editor.log" ||
    fail "the lit frame was not checked"
grep -q "ui-test PASS .*expect-viewer-stat specular max-equals 32" "$work/editor.log" ||
    fail "prepass's thin G-buffer in the viewers was not checked"
echo "ui_layout_combo: PASS"
