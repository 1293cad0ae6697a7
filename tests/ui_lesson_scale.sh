#!/bin/sh
# A whole lesson at UI scale 1.5 at 1280x720 by real input (issue 46): the lesson opened from the
# course by a click (the first row: the docked Lessons window is short at 1.5x), the presentation layout entered by P (the docked layout's right column cannot
# hold 12 lines at 1.5x beside a readable G-buffer strip), then every step by clicks on Next and
# back by clicks on Back; on each step the frame log's lessonLines (the lesson region's visible
# height over the line height) is at least 12. A screenshot of every step stays in WORK_DIR.
# usage: ui_lesson_scale.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_lesson_scale
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

button() { field lessonButtons | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d %d", $(2 * n - 1), $(2 * n) }'; }
click_button() {
    set -- $(button "$1")
    [ "${1:-0}" -gt 0 ] || fail "Lessons button $1 not drawn: $(field lessonButtons)"
    click_at "$1" "$2"
    wait_frames 6
}
row() { field courseRows | tr -d '[]' | awk -F, -v n="$1" '{ b = 4 * (n - 1); printf "%d %d", $(b + 1) + $(b + 3) / 2, $(b + 2) + $(b + 4) / 2 }'; }
check_lines() {
    awk -v n="$(field lessonLines)" 'BEGIN { exit !(n >= 12) }' ||
        fail "$1: the lesson region shows $(field lessonLines) lines (< 12), window $(field lessonsWindow)"
    [ -z "$(clipped_list)" ] || fail "$1: cut off: $(clipped_list | tr '\n' ' ')"
    echo "$1: $(field lesson) region $(field lessonLines) lines, window $(field lessonsWindow), image $(field viewport)"
}

ui_start scale --size 1280x720 --ui-scale 1.5
[ "$(field uiScale)" = 1.5000 ] || fail "the frame log says scale $(field uiScale)"
set -- $(row 1)
[ "${1:-0}" -gt 0 ] || fail "the first course row is not in view at 1.5x: $(field courseRows)"
click_at "$1" "$2"
wait_frames 8
[ "$(field lesson)" = '"gbuffer:1"' ] || fail "the row did not open gbuffer:1 ($(field lesson))"
echo "docked at 1.5x: region $(field lessonLines) lines, Lessons window $(field lessonsWindow)"
xdotool key --delay 30 p
i=0
until [ "$(field presentation)" = true ]; do
    wait_frames 1
    i=$((i + 1))
    [ "$i" -le 60 ] || fail "P did not enter the presentation layout"
done
wait_frames 6
steps=5  # the gbuffer lesson (assets/lessons/01_gbuffer.json)
n=1
check_lines "step $n"
shot "step$n"
while [ "$n" -lt "$steps" ]; do
    click_button 3
    n=$((n + 1))
    [ "$(field lesson)" = "\"gbuffer:$n\"" ] || fail "Next did not show step $n ($(field lesson))"
    check_lines "step $n"
    shot "step$n"
done
while [ "$n" -gt 1 ]; do
    click_button 2
    n=$((n - 1))
    [ "$(field lesson)" = "\"gbuffer:$n\"" ] || fail "Back did not show step $n ($(field lesson))"
    check_lines "back to step $n"
done
ui_quit
echo "ui_lesson_scale: PASS"
