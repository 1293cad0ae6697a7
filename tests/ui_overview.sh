#!/bin/sh
# The viewport's attachment overview (issue 26) driven by real X input (xdotool) on the real editor
# under Xvfb at 1280x720: a short tap of G shows every attachment of the G-buffer layout and the lit
# frame in a labelled grid inside the viewport's image; a click on the "normal" cell shows the
# normals full size and leaves the overview; two more taps turn it on and off again. Checks read
# --log-frames; the screenshot of the overview is for a person.
# usage: ui_overview.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"

ui_name=ui_overview
log=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

# cells: the overview's cells of the last frame, "VIEW X Y W H" one a line.
cells() {
    last | sed -n 's/.*"overviewCells":\[\([^]]*\)\].*/\1/p' | sed 's/","/"\n"/g' | tr -d '"' | grep -v '^$' |
        sed 's/@/ /; s/,/ /g' || true
}
# tap_g: one short tap of G (press and release 30 ms apart), then a few frames.
tap_g() {
    xdotool key --delay 30 g
    wait_frames 4
}

size=1280x720
log="$work/frames.jsonl"
"$bin" --size "$size" --no-vsync --frame-sleep-ms 40 --log-frames "$log" > "$work/editor.log" 2>&1 &
pid=$!
wait_frames 4
ui_window
set -- $(rect_point viewport 0.5 0.5)
xdotool mousemove --window "$wid" "$1" "$2"
wait_frames 4
[ "$(field overview)" = "false" ] || fail "the overview is on at start"
[ "$(field view)" = '"final"' ] || fail "the view is $(field view) at start, not final"
[ -z "$(cells)" ] || fail "overview cells logged while it is off: $(field overviewCells)"
set -- $(centre overviewButton)
[ "$1" -gt 0 ] || fail "no Overview button in the viewport's toolbar ($(field overviewButton))"

# --- G: the overview with one labelled cell per attachment and the lit frame ------------------
tap_g
[ "$(field overview)" = "true" ] || fail "a tap of G did not turn the overview on"
n=$(cells | wc -l)
[ "$n" -ge 6 ] || fail "the overview has $n cells, not at least 6: $(field overviewCells)"
for view in final position normal albedo specular depth_linear; do
    cells | grep -q "^$view " || fail "no $view cell in the overview: $(field overviewCells)"
done
# Every cell a picture of some size inside the viewport's image, none overlapping the next.
set -- $(field viewport | tr -d '[]' | tr ',' ' ')
vx="$1" vy="$2" vw="$3" vh="$4"
cells | awk -v vx="$vx" -v vy="$vy" -v vw="$vw" -v vh="$vh" '
    { if ($4 < 40 || $5 < 20) { print "cell " $1 " is only " $4 "x" $5; bad = 1 }
      if ($2 < vx - 1 || $3 < vy - 1 || $2 + $4 > vx + vw + 1 || $3 + $5 > vy + vh + 1) {
          print "cell " $1 " at " $2 "," $3 " " $4 "x" $5 " leaves the viewport"; bad = 1 }
      x[NR] = $2; y[NR] = $3; w[NR] = $4; h[NR] = $5 }
    END { for (i = 1; i <= NR; i++) for (j = i + 1; j <= NR; j++)
              if (x[i] < x[j] + w[j] && x[j] < x[i] + w[i] && y[i] < y[j] + h[j] && y[j] < y[i] + h[i]) {
                  print "cells " i " and " j " overlap"; bad = 1 }
          exit bad }' || fail "the overview's cells do not tile the viewport"
# Together the pictures take most of the image area: the overview fills the viewport.
share=$(cells | awk -v a="$vw" -v b="$vh" '{ s += $4 * $5 } END { printf "%d", 100 * s / (a * b) }')
[ "$share" -ge 40 ] || fail "the cells cover $share % of the viewport's image, not at least 40 %"
echo "overview on: $n cells covering $share % of the viewport: $(field overviewCells)"
clipped=$(clipped_list)
[ -z "$clipped" ] || fail "cut off at $size with the overview on: $clipped"
wait_frames 6
shot "overview_$size"

# --- a click on the normal cell: the viewport shows the normals, the overview goes ------------
set -- $(cells | awk '$1 == "normal" { printf "%d %d", $2 + $4 / 2, $3 + $5 / 2 }')
[ "$#" -eq 2 ] || fail "no normal cell to click"
click_at "$1" "$2"
wait_frames 4
[ "$(field view)" = '"normal"' ] || fail "a click on the normal cell showed view $(field view), not normal"
[ "$(field overview)" = "false" ] || fail "the overview stayed on after a click on a cell"
[ -z "$(cells)" ] || fail "cells logged after leaving the overview: $(field overviewCells)"
echo "clicked the normal cell at $1,$2: view normal, overview off"
shot "normal_$size"

# --- G twice more: on, then off, the view kept ------------------------------------------------
tap_g
[ "$(field overview)" = "true" ] || fail "the second tap of G did not turn the overview on"
tap_g
[ "$(field overview)" = "false" ] || fail "the third tap of G did not turn the overview off"
[ "$(field view)" = '"normal"' ] || fail "toggling the overview changed the view to $(field view)"
echo "G: on, off; the view stayed normal"
ui_stop
echo "ui_overview: PASS"
