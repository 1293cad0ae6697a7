#!/bin/sh
# The Frame window (issue 24) driven by real X input (xdotool) on the real editor under Xvfb: the
# Stats window's "Frame diagram" button opens it; a click on the geometry pass's gbuffer.normal
# pin shows the normals in the viewport, one on the lighting pass's lights pin (no view) leaves the
# view alone; a click on the lighting box and "Stop here" makes the
# frame stop after it (the renderer's own record says so); the wheel scrolls the diagram to the
# display pass, whose pin shows the final image again; "M" to forward mode, which has no
# lighting pass, drops the stop with a log line. Nothing is cut off at 1280x720 or 1600x900 with
# the window open. Every check reads the editor's --log-frames lines; screenshots are for a person.
# usage: ui_frame_window.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"

ui_name=ui_frame_window
log=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

# target NAME: "x y" of the Frame window's click target NAME ("pass:geometry",
# "out:geometry:gbuffer.normal") in the last frame; empty when it was not drawn.
target() {
    last | sed -n 's/.*"frameTargets":\[\([^]]*\)\].*/\1/p' | sed 's/","/"\n"/g' | tr -d '"' |
        grep "^$1@" | head -n 1 | sed 's/.*@//' | tr ',' ' '
}
click_target() {
    set -- "$1" $(target "$1")
    [ "$#" -eq 3 ] || fail "no '$1' in the Frame window: $(field frameTargets)"
    click_at "$2" "$3"
    echo "clicked $1 at $2,$3"
}
# open_frame: clicks the Stats window's "Frame diagram" button; the Frame window must appear.
open_frame() {
    [ "$(field frameWindow)" = "[0.0000,0.0000,0.0000,0.0000]" ] || fail "the Frame window is open at start"
    set -- $(centre frameButton)
    [ "$1" -gt 0 ] || fail "no Frame diagram button in the Stats window ($(field frameButton))"
    click_at "$1" "$2"
    wait_frames 4
    [ "$(field frameWindow)" != "[0.0000,0.0000,0.0000,0.0000]" ] || fail "the button did not open the Frame window"
    echo "Frame window at $(field frameWindow)"
}

for size in 1280x720 1600x900; do
    log="$work/frames-$size.jsonl"
    export GBL_RECOVERY_DIR="$work/recovery-$size"
    mkdir -p "$GBL_RECOVERY_DIR"
    "$bin" --size "$size" --no-vsync --frame-sleep-ms 60 --log-frames "$log" > "$work/editor-$size.log" 2>&1 &
    pid=$!
    wait_frames 4
    ui_window
    open_frame
    wait_frames 2
    shot "frame-$size"
    clipped=$(clipped_list)
    [ -z "$clipped" ] || fail "cut off at $size with the Frame window open: $clipped"

    # A pin shows its resource in the viewport.
    [ "$(field view)" = '"final"' ] || fail "the view is $(field view) at start, not final"
    click_target out:geometry:gbuffer.normal
    wait_frames 4
    [ "$(field view)" = '"normal"' ] || fail "the gbuffer.normal pin showed view $(field view), not normal"
    shot "frame-$size-normal"
    # The light list has no view: its pin only says so (a tooltip) and leaves the view alone.
    click_target in:lighting:lights
    wait_frames 3
    [ "$(field view)" = '"normal"' ] || fail "the lights pin, which has no view, changed the view to $(field view)"

    # A pass box selects the pass; "Stop here" stops the frame after it.
    click_target pass:lighting
    wait_frames 3
    set -- $(centre stopButton)
    [ "$1" -gt 0 ] || fail "no Stop here button after selecting the lighting pass ($(field stopButton))"
    click_at "$1" "$2"
    wait_frames 6
    [ "$(field stopAfter)" = '"lighting"' ] || fail "Stop here did not set the stop: $(field stopAfter)"
    [ "$(field stoppedAfter)" = '"lighting"' ] || fail "the frame did not stop after lighting: $(field stoppedAfter)"
    # The diagram is wider than the window: the wheel scrolls it sideways to the display pass.
    set -- $(target pass:lighting)
    xdotool mousemove --window "$wid" "$1" "$2" sleep 0.1 click --repeat 30 --delay 20 5
    wait_frames 6
    click_target out:display:display
    wait_frames 4
    [ "$(field view)" = '"final"' ] || fail "the display pin showed view $(field view), not final"
    shot "frame-$size-stopped"
    clipped=$(clipped_list)
    [ -z "$clipped" ] || fail "cut off at $size with the frame stopped: $clipped"
    echo "$size: the frame stopped after lighting"

    if [ "$size" = 1280x720 ]; then
        # Quad -> volumes -> tiled -> forward: forward runs no lighting pass, so the stop goes.
        for step in 1 2 3; do
            xdotool key --delay 20 m
            wait_frames 4
            [ "$step" -eq 3 ] || [ "$(field stopAfter)" = '"lighting"' ] || fail "the stop went before forward mode"
        done
        wait_frames 3
        [ "$(field stopAfter)" = '""' ] || fail "forward mode kept the stop after lighting: $(field stopAfter)"
        [ "$(field stoppedAfter)" = '""' ] || fail "the forward frame stopped after $(field stoppedAfter)"
        grep -q "cannot stop after 'lighting'" "$work/editor-$size.log" || fail "no log line said why the stop went"
        echo "forward mode dropped the stop and said why"
        shot "frame-$size-forward"
    fi
    ui_stop
done
echo "ui_frame_window: PASS"
