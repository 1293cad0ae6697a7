#!/bin/sh
# The real editor driven by real X events (xdotool) while each frame takes 150 ms or more: a click
# selects a light, a 20 ms F tap frames it, Ctrl+S over the viewport saves without flying, Home
# returns to the scene's view, a double click frames a light, an idle editor does not render, and
# a Shift+drag over the viewport's tools gives a region of the dragged size without moving the image.
# Every check reads the editor's --log-frames lines or the saved session file.
# usage: ui_real_input.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"

ui_name=ui_real_input
log="$work/frames.jsonl"
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

# --- a session file to start from, written by the editor's own save --------------------------
cat > "$work/make_session.txt" <<SCRIPT
frames 2
save-session $work/session.json
SCRIPT
"$bin" --size 1280x720 --no-vsync --ui-test "$work/make_session.txt" > "$work/make_session.log" 2>&1 ||
    { cat "$work/make_session.log"; fail "could not write the starting session"; }
cp "$work/session.json" "$work/start.json"

"$bin" --size 1280x720 --no-vsync --session "$work/session.json" --frame-sleep-ms 150 --log-frames "$log" \
    > "$work/editor.log" 2>&1 &
pid=$!
wait_frames 4
ui_window

# The pointer over the middle of the viewport image.
vp=$(field viewport | tr -d '[]')
cx=$(echo "$vp" | awk -F, '{ printf "%d", $1 + $3 / 2 }')
cy=$(echo "$vp" | awk -F, '{ printf "%d", $2 + $4 / 2 }')
xdotool mousemove --window "$wid" "$cx" "$cy"
wait_frames 4
[ "$(field viewportHovered)" = "true" ] || fail "the pointer at $cx,$cy is not over the viewport ($vp)"

# --- idle: no change, so at most one render over 40 frames ----------------------------------
wait_frames 3
start=$(lines)
wait_frames 40
renders=$(tail -n +"$(( start + 1 ))" "$log" | head -n 40 | grep -c '"rendered":true' || true)
echo "idle: $renders render(s) over 40 frames"
[ "$renders" -le 1 ] || fail "the idle editor rendered $renders times over 40 frames"
ms=$(field frameMs)
echo "frame time $ms ms"

# pick_other: a light cube in view that is not the selected one; sets light, lx, ly.
pick_other() {
    selected=$(field selectedLight)
    pick=$(last | sed -n 's/.*"pickable":\[\(.*\)\],"events".*/\1/p' | tr -d '[' | tr ']' '\n' | sed 's/^,//' | grep -v '^$' |
        awk -F, -v s="$selected" '$1 != s { print; exit }')
    [ -n "$pick" ] || fail "no light cube in view other than the selected one ($selected)"
    light=$(echo "$pick" | cut -d, -f1)
    lx=$(echo "$pick" | awk -F, '{ printf "%d", $2 }')
    ly=$(echo "$pick" | awk -F, '{ printf "%d", $3 }')
}

# --- a click with a 30 ms dwell selects the light under the pointer, and does not orbit -------
pick_other
before=$(field camera)
xdotool mousemove --window "$wid" "$lx" "$ly" mousedown 1 sleep 0.03 mouseup 1
wait_frames 5
[ "$(field selectedLight)" = "$light" ] || fail "clicking light $light at $lx,$ly selected $(field selectedLight)"
[ "$(field camera)" = "$before" ] || fail "the click moved the camera: $before -> $(field camera)"
echo "click at $lx,$ly selected light $light"

# --- a 20 ms F tap frames the selected light ---------------------------------------------------
before=$(field camera)
mark=$(lines)
xdotool keydown f sleep 0.02 keyup f
wait_frames 4
after=$(field camera)
[ "$after" != "$before" ] || fail "a 20 ms F tap did not move the camera ($before)"
events_since "$mark" | grep -q "frame-selection" || fail "no frame-selection action logged"
echo "F: camera $before -> $after"

# --- Ctrl+S over the viewport saves and does not fly back ------------------------------------
xdotool mousemove --window "$wid" "$cx" "$cy"
wait_frames 2
before=$(field camera)
mark=$(lines)
xdotool keydown ctrl keydown s sleep 0.02 keyup s keyup ctrl
wait_frames 4
after=$(field camera)
[ "$after" = "$before" ] || fail "Ctrl+S moved the camera: $before -> $after"
events_since "$mark" | grep -q "save-session" || fail "no save-session action logged"
cmp -s "$work/session.json" "$work/start.json" && fail "Ctrl+S did not write the session file"
echo "Ctrl+S saved $work/session.json; camera stayed at $after"

# --- Home returns to the scene's view; a double click frames a light ---------------------------
mark=$(lines)
xdotool key --delay 20 Home
wait_frames 4
events_since "$mark" | grep -q "home-view" || fail "no home-view action logged"
home=$(field camera)
[ "$home" != "$after" ] || fail "Home did not move the camera from the framed light"
pick_other
mark=$(lines)
xdotool mousemove --window "$wid" "$lx" "$ly" sleep 0.2 click --repeat 2 --delay 80 1
wait_frames 8
events_since "$mark" | grep -q "double-click-frame" || fail "no double click seen on light $light"
[ "$(field selectedLight)" = "$light" ] || fail "the double click did not select light $light"
[ "$(field camera)" != "$home" ] || fail "the double click on light $light did not frame it"
echo "double click framed light $light"

ui_stop

# --- real clicks on "Pin lit" and "Diff"; the script in the same editor checks the diff --------
# The frame log says where the editor drew both (window pixels); "Diff" appears once pinned.
cat > "$work/lit_diff.txt" <<SCRIPT
frames 3
wait-lit-diff 60
expect-lit-pinned
expect-lit-diff max = 0
expect-lit-diff pixels > 1000
light 0 intensity 40
frames 45
expect-lit-diff max > 0
expect-lit-diff over > 0
lit-diff-threshold 1e9
frames 2
expect-lit-diff over = 0
SCRIPT
log="$work/lit_frames.jsonl"
# The editor above was killed: a recovery folder of its own, or its autosave would be offered in
# a modal dialog that takes the clicks.
export GBL_RECOVERY_DIR="$work/recovery-lit"
mkdir -p "$GBL_RECOVERY_DIR"
"$bin" --size 1280x720 --no-vsync --session "$work/start.json" --frame-sleep-ms 60 --log-frames "$log" \
    --ui-test "$work/lit_diff.txt" > "$work/lit_diff.log" 2>&1 &
pid=$!
wait_frames 3
ui_window
set -- $(centre pinLit)
pinx=$1 piny=$2
[ "$pinx" -gt 0 ] || fail "the Pin lit button was not drawn ($(field pinLit))"
xdotool mousemove --window "$wid" "$pinx" "$piny" sleep 0.1 mousedown 1 sleep 0.05 mouseup 1
wait_frames 4
set -- $(centre litDiff)
diffx=$1 diffy=$2
[ "$diffx" -gt 0 ] || fail "no Diff checkbox after the Pin lit click ($(field litDiff))"
xdotool mousemove --window "$wid" "$diffx" "$diffy" sleep 0.1 mousedown 1 sleep 0.05 mouseup 1
echo "clicked Pin lit at $pinx,$piny and Diff at $diffx,$diffy"
status=0
wait "$pid" || status=$?
pid=""
grep "ui-test" "$work/lit_diff.log" || true
[ "$status" -eq 0 ] || fail "the lit diff script failed (exit $status, see $work/lit_diff.log)"
grep -q "ui-test PASS .*expect-lit-diff" "$work/lit_diff.log" || fail "no lit diff check passed"
echo "Pin lit and Diff clicked for real; the diff statistics checked"

# --- a real Shift+drag over the viewport's tools (albedo) gives a region of the dragged size ----
# The region rows above the image once appeared with the region and pushed the image down under
# the mouse, so a 120x60 drag came out 121x9: the image must stay put for the whole drag.
cat > "$work/make_tools.txt" <<SCRIPT
frames 2
set view albedo
viewport-tools on
frames 2
save-session $work/tools.json
SCRIPT
"$bin" --size 1280x720 --no-vsync --session "$work/start.json" --ui-test "$work/make_tools.txt" \
    > "$work/make_tools.log" 2>&1 || { cat "$work/make_tools.log"; fail "could not write the tools session"; }
log="$work/tools_frames.jsonl"
export GBL_RECOVERY_DIR="$work/recovery-tools"
mkdir -p "$GBL_RECOVERY_DIR"
"$bin" --size 1280x720 --no-vsync --session "$work/tools.json" --frame-sleep-ms 60 --log-frames "$log" \
    > "$work/tools_editor.log" 2>&1 &
pid=$!
wait_frames 6
ui_window
[ "$(field toolsRegion)" = "[0,0,0,0]" ] || fail "the viewport's tools are not open without a region: $(field toolsRegion)"
before=$(field viewport)
set -- $(rect_point viewport 0.3 0.4)
sx=$1 sy=$2
dx=120 dy=60
xdotool mousemove --window "$wid" "$sx" "$sy"
wait_frames 3
mark=$(lines)
xdotool keydown shift sleep 0.1 mousedown 1
wait_frames 3
for step in 1 2 3 4; do
    xdotool mousemove --window "$wid" $((sx + dx * step / 4)) $((sy + dy * step / 4))
    wait_frames 3
done
end=$(lines)
xdotool mouseup 1 sleep 0.1 keyup shift
wait_frames 4
moved=$(tail -n +"$(( mark + 1 ))" "$log" | sed -n 's/.*"viewport":\(\[[^]]*\]\).*/\1/p' | grep -v -x -F "$before" | head -n 1)
[ -z "$moved" ] || fail "the viewport image moved during the drag: $before -> $moved"
region=$(field toolsRegion | tr -d '[]')
image=$(field toolsImage "$(sed -n "${end}p" "$log")" | tr -d '[]')
# The drag in window pixels scaled to the image's texels (1:1 unless the framebuffer is scaled),
# plus one: the texels under both ends are inside (rectFromCorners).
want=$(printf '%s %s\n' "$image" "$(printf '%s' "$before" | tr -d '[]')" | tr ',' ' ' |
    awk -v dx="$dx" -v dy="$dy" '{ printf "%d %d", dx * $1 / $5 + 1.5, dy * $2 / $6 + 1.5 }')
echo "Shift+drag ${dx}x${dy} px from $sx,$sy: region $region (x,y,w,h), expected size $want, image $before"
printf '%s %s\n' "$region" "$want" | tr ',' ' ' |
    awk '{ d1 = $3 - $5; d2 = $4 - $6; exit !(d1 <= 1 && d1 >= -1 && d2 <= 1 && d2 >= -1) }' ||
    fail "the ${dx}x${dy} px drag gave region $region, not $want (+-1 texel)"
shot region_drag
clipped=$(clipped_list)
[ -z "$clipped" ] || echo "clipped after the drag: $clipped"
ui_stop

echo "ui_real_input: PASS"
