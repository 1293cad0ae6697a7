#!/bin/sh
# The docked layout at every UI scale of the View menu (issue 46), by real clicks: one editor at
# 1280x720 and one at 1600x900, each switched 1 -> 1.5 -> 2 -> 1.25 through View > UI scale.
# After each switch, with the course shown and again with a lesson open (the course's first row
# clicked), the frame log says:
# - the layout kind chosen for that scale and size (two columns at 1, one column where two would
#   leave the viewport less than half the width);
# - the viewport's image at least half the window's width;
# - above scale 1, each G-buffer viewer's image fills its cell's width or height, with at most a
#   tenth (and 6 px) of the other left empty (the strip's height fitted to its images; at scale 1
#   the strip keeps its share, and at 1600x900 its images are narrower than their cells);
# - nothing cut off (the frame log's "clipped" list, ui/panels/clip_check.h);
# - with the lesson open, the lesson region's visible lines (lessonLines) at least 12 up to scale
#   1.5; at 2 the docked column holds 6 at 1280x720 and 10 at 1600x900 (a lesson at 2x reads in
#   the presentation layout, P).
# A screenshot of each state stays in WORK_DIR; the table of sizes is printed.
# usage: ui_scale_layouts.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_scale_layouts
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

# pick N SCALE: View > UI scale > choice N by clicks, then frames until the layout settled.
pick() {
    pick_ui_scale "$1" "$2"
    xdotool mousemove --window "$wid" 5 5  # no tooltip over what is measured
    wait_frames 12
}
button() { field lessonButtons | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d %d", $(2 * n - 1), $(2 * n) }'; }
row1() { field courseRows | tr -d '[]' | awk -F, '{ printf "%d %d", $1 + $3 / 2, $2 + $4 / 2 }'; }

# check WHERE KIND: the current frame against the rules above; prints a row of the table.
check() {
    line=$(last)
    kind=$(field dockLayout "$line" | tr -d '"')
    [ "$kind" = "$2" ] || fail "$1: the layout is '$kind', not '$2'"
    sizes=$(echo "$(field viewport "$line") $(field viewerArea "$line") $(field viewerImages "$line")" | tr -d '[]' |
        awk -F'[ ,]' -v W="$width" -v fitted="$fitted" '{
            out = sprintf("viewport %dx%d", $3, $4)
            if ($3 < W / 2) out = out " FAIL(less than half the width)"
            ax = $5; ay = $6
            out = out sprintf(", viewer area %dx%d image %dx%d", ax, ay, $9, $10)
            for (i = 0; i < 5; ++i) {
                w = $(7 + 4 * i + 2); h = $(7 + 4 * i + 3)
                sx = ax - w; sy = ay - h
                if (fitted && (sx > 6 && sx > 0.1 * w || sy > 6 && sy > 0.1 * h)) {
                    out = out sprintf(" FAIL(viewer %d: %dx%d in %dx%d)", i + 1, w, h, ax, ay); break
                }
            }
            print out
        }')
    lines=$(field lessonLines "$line")
    echo "$1: $kind, $sizes, lesson lines $lines"
    case "$sizes" in *FAIL*) fail "$1: $sizes" ;; esac
    clipped=$(clipped_list "$line")
    [ -z "$clipped" ] || fail "$1: cut off: $(echo "$clipped" | tr '\n' ' ')"
}

# One start per size; the scales by the menu. "choice scale kind least-lines-1280 least-lines-1600".
for size in 1280x720 1600x900; do
    width=${size%x*}
    ui_start "s$size" --size "$size"
    xdotool mousemove --window "$wid" 5 5
    wait_frames 12
    for step in "0 1.0000 two 12 12" "2 1.5000 one 12 12" "3 2.0000 one 6 10" "1 1.2500 x 12 12"; do
        set -- $step
        least=$4
        [ "$width" = 1600 ] && least=$5
        [ "$2" = 1.0000 ] && [ "$(field uiScale)" = 1.0000 ] || pick "$1" "$2"
        kind="$3 columns"
        [ "$3" = one ] && kind="one column"
        # 1.25: two columns at 1600 wide (375 + 400 px leave the viewport 825), one at 1280.
        [ "$3" = x ] && { kind="one column"; [ "$width" = 1600 ] && kind="two columns"; }
        scale=${2%00}
        fitted=1
        [ "$2" = 1.0000 ] && fitted=0
        check "$size at $scale, the course" "$kind"
        shot "$size-$scale-course"
        set -- $(row1)
        [ "${1:-0}" -gt 0 ] || fail "$size at $scale: the course's first row is not in view: $(field courseRows)"
        click_at "$1" "$2"
        wait_frames 12
        [ "$(field lesson)" = '"gbuffer:1"' ] || fail "$size at $scale: the first row did not open gbuffer:1 ($(field lesson))"
        check "$size at $scale, a lesson" "$kind"
        awk -v n="$(field lessonLines)" -v least="$least" 'BEGIN { exit !(n >= least) }' ||
            fail "$size at $scale: the lesson region shows $(field lessonLines) lines (< $least)"
        shot "$size-$scale-lesson"
        set -- $(button 4)
        click_at "$1" "$2"  # Leave
        wait_frames 4
        [ "$(field lesson)" = '""' ] || fail "Leave did not close the lesson ($(field lesson))"
    done
    ui_quit
done
echo "ui_scale_layouts: PASS"
