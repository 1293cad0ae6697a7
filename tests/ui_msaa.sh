#!/bin/sh
# MSAA in the editor with real X clicks (xdotool, issue 47): the Pipeline window's msaa combo is
# opened where the frame log says it is drawn; the editor runs with GBL_MAX_SAMPLES=4 (a driver
# that cannot do 8, gl/sample_limit.h), so "8" is greyed out: hovered (its reason as tooltip, in
# the screenshot msaa_8_greyed.png) and clicked, it stays unpicked; then "4" is clicked (msaa_lighting is edges by
# default); the viewport's "Complex" checkbox is clicked; a UI script in the same editor checks
# that 4 samples ran, the overlay is drawn, selects sample 1 in the position viewer and checks its
# values, and that the pixel inspector lists 4 samples. Screenshots are left in WORK_DIR to look at.
# usage: ui_msaa.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"

ui_name=ui_msaa
log="$work/frames.jsonl"
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

cat > "$work/msaa.txt" <<SCRIPT
frames 3
expect-setting msaa off
expect-setting msaa_lighting edges
wait-setting msaa 4 120
frames 3
expect-msaa-samples 4
expect-no-gl-errors
wait-msaa-view complex 120
# The shell moves the mouse off the checkbox after its click: no tooltip over the screenshots.
frames 6
viewer-sample position 1
viewer-tool position histogram on
inspect 320 200
frames 4
expect-viewer-stat position nan 0
expect-viewer-stat position max-above 0.5
expect-inspector-samples 4
screenshot $work/msaa_complex.png
msaa-view complex off
msaa-view samples on
frames 3
screenshot $work/msaa_samples.png
expect-no-gl-errors
SCRIPT
GBL_MAX_SAMPLES=4 "$bin" --size 1280x720 --no-vsync --frame-sleep-ms 60 --log-frames "$log" --ui-test "$work/msaa.txt" \
    > "$work/editor.log" 2>&1 &
pid=$!
wait_frames 4
ui_window
[ "$(field msaaSamples)" = 0 ] || fail "the editor starts with msaa samples $(field msaaSamples), not 0"

# --- the wheel over the Pipeline window scrolls the msaa combo into view -----------------------
scroll_into_view msaaCombo pipelineWindow 40
echo "the msaa combo is in view after $wheel_steps wheel step(s): $(field msaaCombo)"

# --- a click opens the combo; "8" is greyed and a click on it picks nothing ---------------------
open_combo msaaCombo msaaItems 4
[ "$(field msaaGreyed)" = "[0,0,0,1]" ] ||
    fail "with GBL_MAX_SAMPLES=4 the msaa entries greyed are $(field msaaGreyed), not 8 alone ([0,0,0,1])"
set -- "$item_x" "$item_y"
xdotool mousemove --window "$wid" "$1" "$2"
wait_frames 8
shot msaa_8_greyed
click_at "$1" "$2"
wait_frames 6
[ "$(field msaaSamples)" = 0 ] || fail "a click on the greyed 8 ran $(field msaaSamples) samples"
echo "8 is greyed at $1,$2 and a click there picked nothing"

# --- a click on the third entry ("4") picks it -------------------------------------------------
if [ "$(field msaaItems)" = "[]" ]; then  # a click on a greyed entry may close the list
    open_combo msaaCombo msaaItems 3
else
    combo_items=$(field msaaItems)
    item_x=$(echo "$combo_items" | tr -d '[]' | awk -F, '{ printf "%d", $5 }')
    item_y=$(echo "$combo_items" | tr -d '[]' | awk -F, '{ printf "%d", $6 }')
fi
set -- "$item_x" "$item_y"
click_at "$1" "$2"
wait_field msaaSamples = 4 200 "200 frames after the click on 4, msaa samples are not 4"
echo "clicked 4 at $1,$2: the frame ran $(field msaaSamples) samples"

# --- the viewport's Complex checkbox -------------------------------------------------------------
set -- $(centre msaaComplexBox)
[ "$1" -gt 0 ] || fail "the Complex checkbox was not drawn ($(field msaaComplexBox))"
click_from=$(lines)
xdotool mousemove --window "$wid" "$1" "$2" sleep 0.1 mousedown 1 sleep 0.05 mouseup 1
xdotool mousemove --window "$wid" 1100 490
echo "clicked Complex at $1,$2"

status=0
wait "$pid" || status=$?
pid=""
grep "ui-test" "$work/editor.log" || true
[ "$status" -eq 0 ] || fail "the msaa script failed (exit $status, see $work/editor.log)"
grep -q "ui-test PASS .*expect-inspector-samples" "$work/editor.log" || fail "the inspector's samples were not checked"
tail -n +"$(( click_from + 1 ))" "$log" | grep -q '"positionSample":1' || fail "the position viewer never showed sample 1"
echo "ui_msaa: PASS"
