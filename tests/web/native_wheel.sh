#!/bin/sh
# The desktop's wheel, for tests/web/browser_test.py's wheel case (issue 50): one notch away from
# the user (X button 4) over the viewport and one towards the user (button 5) over the Lessons
# window's course, with real X events, in the native editor at 1280x720 on the default scene.
# Prints one JSON line: the notch up as the frame log's event, the camera before and after it, and the course's rows (x, y, width,
# height each, 0 while not wholly in view) before and after the notch down, as the frame log gives them.
# usage: xvfb-run -a -s '-screen 0 1280x800x24' tests/web/native_wheel.sh GBUFFER_LAB WORK_DIR
set -eu
bin="$1"
work="$2"

ui_name=native_wheel
log="$work/frames.jsonl"
. "$(dirname "$0")/../support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

"$bin" --size 1280x720 --no-vsync --log-frames "$log" > "$work/editor.log" 2>&1 &
pid=$!
wait_frames 4
ui_window
wait_frames 3

set -- $(field viewport | tr -d '[]' | tr ',' ' ')
xdotool mousemove --window "$wid" "$(echo "$1 + $3 / 2" | bc)" "$(echo "$2 + $4 / 2" | bc)"
wait_frames 3
camera0=$(field camera)
from=$(lines)
xdotool click 4
i=0
while [ "$(field camera)" = "$camera0" ]; do
    wait_frames 1
    i=$((i + 1))
    [ "$i" -le 100 ] || fail "the wheel did not move the camera"
done
wait_frames 3
camera1=$(field camera)
scroll=$(tail -n +"$((from + 1))" "$log" | grep -o '"scroll [^"]*"' | head -n 1)

set -- $(field courseRows | tr -d '[]' | tr ',' ' ')
xdotool mousemove --window "$wid" "$(echo "$1 + $3 / 2" | bc)" "$(echo "$2 + $4 / 2" | bc)"
wait_frames 3
rows0=$(field courseRows)
xdotool click 5
i=0
while [ "$(field courseRows)" = "$rows0" ]; do
    wait_frames 1
    i=$((i + 1))
    [ "$i" -le 100 ] || fail "the wheel did not scroll the course"
done
wait_frames 3
rows1=$(field courseRows)
kill "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
printf '{"scroll":%s,"camera0":%s,"camera1":%s,"rows0":%s,"rows1":%s}\n' "${scroll:-null}" "$camera0" "$camera1" \
    "$rows0" "$rows1"
