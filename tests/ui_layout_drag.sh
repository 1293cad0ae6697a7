#!/bin/sh
# The tiled layout's boundaries can be dragged (issue 26; Debian's ImGui 1.86 has no docking), with
# real X input at 1280x720:
# - the strip's top dragged 120 px up: the viewport's image loses about as much height (the frame
#   follows the viewport's size, so the viewers' images keep their width-bound size);
# - the right column's edge dragged 80 px left: the Pixel inspector's column widens;
# - quitting keeps the boundaries in imgui.ini and the next start has them back;
# - a broken Splits line gets one message naming the file, and the default layout.
# Built with a docking ImGui the dock splitters do this and the test has nothing to check.
# usage: ui_layout_drag.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_layout_drag
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work
ini="$XDG_CONFIG_HOME/gbuffer-lab/imgui.ini"
mkdir -p "$(dirname "$ini")"

# run NAME: an editor at 1280x720 (ui_common.sh's ui_start).
run() { ui_start "$1" --size 1280x720; }
# handle N: "x y" of the centre of boundary N's handle (Split order: left column, right column,
# strip, Lights row, then the right column's rows).
handle() {
    field splitHandles | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d %d", $(4*n+1) + $(4*n+3)/2, $(4*n+2) + $(4*n+4)/2 }'
}
# drag_by X Y DX DY: press at (X, Y), move there in four steps with short dwells, release.
drag_by() {
    xdotool mousemove --window "$wid" "$1" "$2" sleep 0.15 mousedown 1 sleep 0.1
    for s in 1 2 3 4; do
        xdotool mousemove --window "$wid" $(($1 + $3 * s / 4)) $(($2 + $4 * s / 4)) sleep 0.08
    done
    wait_frames 2
    xdotool mouseup 1
    wait_frames 3
}
# image_h N: height of G-buffer viewer N's image; window_w: the logged Pixel inspector handle width.
image_h() { field viewerImages | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d", $(4*n+4) }'; }
handle_w() { field splitHandles | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d", $(4*n+3) }'; }

run first
[ -n "$(field splitHandles | tr -d '[]')" ] || { echo "$ui_name skipped: built with docking, the dock splitters move the windows"; ui_stop; exit 0; }
set -- $(handle 2)
strip_x=$1 strip_y=$2
image0=$(image_h 0)
[ "$image0" -gt 0 ] || fail "no G-buffer viewer image at the start"
view0=$(field viewport | tr -d '[]' | cut -d, -f4 | cut -d. -f1)
drag_by "$strip_x" "$strip_y" 0 -120
set -- $(handle 2)
[ $((strip_y - $2)) -ge 115 ] && [ $((strip_y - $2)) -le 125 ] ||
    fail "dragging the strip's top 120 px up moved it from y $strip_y to y $2"
view1=$(field viewport | tr -d '[]' | cut -d, -f4 | cut -d. -f1)
[ $((view0 - view1)) -ge 100 ] || fail "the viewport's image did not lose the strip's gain: $view0 -> $view1 px tall"
[ "$(image_h 0)" -gt 0 ] || fail "the position viewer lost its image when the strip grew"
echo "strip: its top from y $strip_y to $2; the viewport image $view0 -> $view1 px tall"
shot dragged_strip

set -- $(handle 1)
right_x=$1 right_y=$2
inspector_w=$(handle_w 4)
drag_by "$right_x" "$right_y" -80 0
set -- $(handle 1)
[ $((right_x - $1)) -ge 75 ] && [ $((right_x - $1)) -le 85 ] ||
    fail "dragging the right column's edge 80 px left moved it from x $right_x to x $1"
[ $(( $(handle_w 4) - inspector_w )) -ge 75 ] || fail "the right column did not widen: $inspector_w -> $(handle_w 4) px"
echo "right column: its edge from x $right_x to $1, $inspector_w -> $(handle_w 4) px wide"
kept=$(field splitHandles)
ui_quit
grep -q '^Splits=' "$ini" || fail "imgui.ini did not keep the boundaries: $(cat "$ini")"

run second
[ "$(field splitHandles)" = "$kept" ] || fail "the boundaries did not come back after a restart: $kept -> $(field splitHandles)"
echo "restart: $(grep '^Splits=' "$ini")"
ui_quit

printf '[gbuffer-lab][View]\nUiScale=1\nSplits=0.9,0.9,0.3,0.5,0.3,0.7,0.9\n\n' > "$ini"
run bad
grep -c 'imgui.ini: Splits must be seven shares' "$work/bad.log" | grep -qx 1 ||
    fail "no single message about the bad Splits line: $(cat "$work/bad.log")"
set -- $(handle 2)
[ "$2" -eq "$strip_y" ] || fail "a bad Splits line did not leave the default layout: the strip's top at y $2, not $strip_y"
ui_quit
echo "bad: $(grep 'Splits must' "$work/bad.log")"
echo "ui_layout_drag: PASS"
