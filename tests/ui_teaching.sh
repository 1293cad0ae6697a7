#!/bin/sh
# The light-by-light scrubber and the A/B divider driven by real X events (xdotool) at two window
# sizes: a click on the scrubber turns accumulation on at k = 0, Right/Left arrows step it, a click
# turns A/B on, and a drag moves the divider without moving the camera. Wireframes outline the
# selected light's volume alone, "all" every light's (issue 26). Checks read --log-frames;
# screenshots of each step are left in WORK_DIR to look at.
# usage: ui_teaching.sh GBUFFER_LAB WORK_DIR          (ctest: each size on an Xvfb of its own)
#        ui_teaching.sh GBUFFER_LAB WORK_DIR WxH      (one size, on the current $DISPLAY)
set -eu
bin="$1"
work="$2"
if [ $# -lt 3 ]; then
    # A second editor on the same Xvfb sees no pointer motion after the first one quit, so every
    # size gets a fresh server.
    rm -rf "$work"
    for size in 1280x720 1600x900; do
        xvfb-run -a -s "-screen 0 1920x1080x24" sh "$0" "$bin" "$work/$size" "$size" || exit 1
    done
    echo "ui_teaching: screenshots in $work/*/"
    echo "ui_teaching: PASS"
    exit 0
fi

ui_name=ui_teaching
log=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

run_size() {
    size="$1"
    log="$work/frames_$size.jsonl"
    "$bin" --size "$size" --no-vsync --frame-sleep-ms 40 --log-frames "$log" > "$work/editor_$size.log" 2>&1 &
    pid=$!
    wait_frames 4
    ui_window  # the newest window of that name: the one this run opened
    xdotool getwindowgeometry "$wid" | tr '\n' ' '
    echo
    # The pointer over the viewport first, so the window has seen it before the first press.
    set -- $(rect_point viewport 0.5 0.5)
    xdotool mousemove --window "$wid" "$1" "$2"
    wait_frames 6
    [ "$(field accumulate)" = "-1" ] || fail "accumulation is on at start"

    # --- wireframes: the selected light's volume alone, every light one click away ------------
    [ "$(field wireframes)" = "0" ] || fail "wireframes outlined at start: $(field wireframes)"
    echo "$size: camera inside the volumes of lights $(field cameraInside)"
    [ "$(field selectedLight)" -ge 0 ] || fail "no light selected at start"
    set -- $(rect_point wireframesToggle 0.1 0.5)
    click_at "$1" "$2"
    wait_frames 4
    [ "$(field wireframes)" = "1" ] || fail "Wireframes outlined $(field wireframes) volumes, not the selected one"
    set -- $(rect_point wireframesAll 0.1 0.5)
    click_at "$1" "$2"
    wait_frames 4
    [ "$(field wireframes)" -ge 16 ] || fail "all outlined $(field wireframes) volumes, not every light"
    echo "$size: wireframes: the selected light's, then all $(field wireframes)"
    shot "wireframes_all_$size"
    click_at "$1" "$2"
    wait_frames 4
    [ "$(field wireframes)" = "1" ] || fail "all off again outlined $(field wireframes) volumes"
    set -- $(rect_point wireframesToggle 0.1 0.5)
    click_at "$1" "$2"
    wait_frames 4
    [ "$(field wireframes)" = "0" ] || fail "Wireframes off still outlines $(field wireframes) volumes"

    # --- a click at the scrubber's left end: accumulation on, k = 0 -------------------------
    set -- $(rect_point scrubber 0.02 0.5)
    [ "$1" -gt 0 ] || fail "the scrubber was not drawn ($(field scrubber))"
    xdotool mousemove --window "$wid" "$1" "$2"
    wait_frames 3
    xdotool mousedown 1 sleep 0.05 mouseup 1
    wait_frames 4
    [ "$(field accumulate)" = "0" ] || fail "clicking the scrubber's left end gave k = $(field accumulate)"
    shot "k0_$size"
    # --- the arrow keys step it: 3 x Right, 1 x Left ------------------------------------------
    for _ in 1 2 3; do
        xdotool key --delay 30 Right
        wait_frames 2
    done
    xdotool key --delay 30 Left
    wait_frames 3
    [ "$(field accumulate)" = "2" ] || fail "Right x3, Left x1 from 0 gave k = $(field accumulate)"
    echo "$size: scrubber at k = 2 after the arrow keys"
    shot "k2_$size"

    # --- the A/B toggle, then a drag of the divider from the middle to 30 % ---------------------
    set -- $(rect_point abToggle 0.5 0.5)
    xdotool mousemove --window "$wid" "$1" "$2"
    wait_frames 3
    xdotool mousedown 1 sleep 0.05 mouseup 1
    wait_frames 4
    awk -v d="$(field abDivider)" 'BEGIN { exit !(d == 0.5) }' ||
        fail "the A/B toggle did not open the split (divider $(field abDivider))"
    camera=$(field camera)
    set -- $(rect_point viewport 0.5 0.5)
    x0="$1"
    y0="$2"
    set -- $(rect_point viewport 0.3 0.5)
    xdotool mousemove --window "$wid" "$x0" "$y0" sleep 0.1 mousedown 1
    wait_frames 2
    for f in 0.45 0.4 0.35 0.3; do
        set -- $(rect_point viewport "$f" 0.5)
        xdotool mousemove --window "$wid" "$1" "$2"
        wait_frames 1
    done
    xdotool mouseup 1
    wait_frames 4
    divider=$(field abDivider)
    awk -v d="$divider" 'BEGIN { exit !(d > 0.27 && d < 0.33) }' || fail "the divider went to $divider, not 0.3"
    [ "$(field camera)" = "$camera" ] || fail "dragging the divider moved the camera: $camera -> $(field camera)"
    echo "$size: divider dragged to $divider; camera stayed"
    wait_frames 3
    shot "split_$size"
    ui_stop
}

run_size "$3"
echo "ui_teaching: $3 passed"
