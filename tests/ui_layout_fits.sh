#!/bin/sh
# Nothing is cut off at 1280x720 and 1600x900 where ImGui can tell (ui/panels/clip_check.h): the
# editor runs a few frames with --log-frames and the last frame's "clipped" list must name no window
# (but the exempt ones below).
# usage: ui_layout_fits.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work"
# The G-buffer strip is being reworked with the viewer tools; its cuts are printed but do not fail
# this test until that work lands. Every other window must fit.
exempt='G-buffer'
status=0
for size in 1280x720 1600x900; do
    log="$work/frames-$size.jsonl"
    "$bin" --size "$size" --no-vsync --frames 8 --log-frames "$log" > "$work/editor-$size.log" 2>&1 ||
        { cat "$work/editor-$size.log"; echo "ui_layout_fits: FAIL: the editor failed at $size"; exit 1; }
    clipped=$(tail -n 1 "$log" | sed -n 's/.*"clipped":\[\([^]]*\)\].*/\1/p' | sed 's/","/"\n"/g' | grep -v '^$' || true)
    echo "$size: cut off: ${clipped:-nothing}"
    if printf '%s\n' "$clipped" | grep -v '^$' | grep -Evq "^\"($exempt):"; then
        echo "ui_layout_fits: FAIL: content cut off at $size"
        status=1
    fi
done
[ "$status" -eq 0 ] && echo "ui_layout_fits: PASS"
exit "$status"
