#!/bin/sh
# The lesson region (issue 46) by real X input: a lesson opened from the course by a click gets a
# region (checklist, prediction, text, question, answer) of at least 12 text lines in view, at
# 1280x720 and 1600x900 (the frame log's lessonLines: the region's visible height over the line
# height); at 1280x720 the Lessons window keeps them after a task's 45-second hint shows (the hint
# goes below the region), and Leave gives the Lessons window back the height it had before.
# usage: ui_lesson_region.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_lesson_region
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

least=12
# button N: window coordinates of Lessons button N (3 Next, 4 Leave).
button() { field lessonButtons | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d %d", $(2 * n - 1), $(2 * n) }'; }
click_button() {
    set -- $(button "$1")
    [ "${1:-0}" -gt 0 ] || fail "Lessons button not drawn: $(field lessonButtons)"
    click_at "$1" "$2"
    wait_frames 6
}
# row N: the centre of the Nth course row.
row() { field courseRows | tr -d '[]' | awk -F, -v n="$1" '{ b = 4 * (n - 1); printf "%d %d", $(b + 1) + $(b + 3) / 2, $(b + 2) + $(b + 4) / 2 }'; }
height() { field lessonsWindow | tr -d '[]' | awk -F, '{ print $4 }'; }
lines_ok() { awk -v n="$(field lessonLines)" -v m="$least" 'BEGIN { exit !(n >= m) }'; }
check_lines() {
    lines_ok || fail "$1: the lesson region shows $(field lessonLines) lines (< $least), Lessons window $(field lessonsWindow)"
    echo "$1: $(field lesson) region $(field lessonLines) lines, Lessons window $(field lessonsWindow), hints $(field lessonHints)"
}

for size in 1280x720 1600x900; do
    export XDG_CONFIG_HOME="$work/config_$size"  # each size starts with the default layout
    mkdir -p "$XDG_CONFIG_HOME"
    ui_start "region_$size" --size "$size"
    before=$(height)
    echo "$size: Lessons window before a lesson $(field lessonsWindow)"
    set -- $(row 2)
    [ "${1:-0}" -gt 0 ] || fail "the second course row is not in view: $(field courseRows)"
    click_at "$1" "$2"
    wait_frames 8
    [ "$(field lesson)" = '"position_from_depth:1"' ] || fail "the row did not open position_from_depth:1 ($(field lesson))"
    check_lines "$size step 1"
    shot "region_${size}_step1"
    click_button 3
    [ "$(field lesson)" = '"position_from_depth:2"' ] || fail "Next did not go to step 2 ($(field lesson))"
    check_lines "$size step 2"
    if [ "$size" = 1280x720 ]; then
        # The step's task left undone: its hint shows after 45 s, below the region.
        i=0
        until [ "$(field lessonHints)" -ge 1 ]; do
            sleep 1
            wait_frames 1
            i=$((i + 1))
            [ "$i" -le 70 ] || fail "no hint after 70 s (tasks $(field lessonTasks))"
        done
        wait_frames 4
        check_lines "$size with the hint"
        shot "region_${size}_hint"
    fi
    click_button 4
    [ "$(field lesson)" = '""' ] || fail "Leave did not close the lesson ($(field lesson))"
    wait_frames 4
    after=$(height)
    awk -v a="$after" -v b="$before" 'BEGIN { d = a - b; exit !(d < 2 && d > -2) }' ||
        fail "$size: after Leave the Lessons window is $after px high, before the lesson $before"
    echo "$size: after Leave the Lessons window $(field lessonsWindow)"
    ui_quit
done
echo "ui_lesson_region: PASS"
