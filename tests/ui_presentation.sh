#!/bin/sh
# The presentation layout (issue 46) by real X input at 1280x720: P enters it, and the viewport's
# frame fills at least 80 % of the window's width or height under a one-line caption; V changes the
# view there; P leaves it and every window is back in its dock node at the same place. View >
# Presentation by clicks does the same. With a lesson open, the lesson is drawn beside the image
# with at least 12 lines of its region in view, and leaving puts the Lessons window back as it was.
# usage: ui_presentation.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_presentation
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

row() { field courseRows | tr -d '[]' | awk -F, -v n="$1" '{ b = 4 * (n - 1); printf "%d %d", $(b + 1) + $(b + 3) / 2, $(b + 2) + $(b + 4) / 2 }'; }
# big: the image is at least 80 % of the window's width or height.
big() {
    field viewport | tr -d '[]' | awk -F, '{ exit !($3 >= 0.8 * 1280 || $4 >= 0.8 * 720) }'
}
# key_until K FIELD VALUE: press K until FIELD reads VALUE (a few frames).
key_until() {
    xdotool key --delay 30 "$1"
    i=0
    until [ "$(field "$2")" = "$3" ]; do
        wait_frames 1
        i=$((i + 1))
        [ "$i" -le 60 ] || fail "key $1 did not make $2 $3 ($(field "$2"))"
    done
    wait_frames 4
}
entered() {
    big || fail "$1: the image is $(field viewport), under 80 % of 1280x720"
    [ "$(field presentationCaption)" != "[0.0000,0.0000,0.0000,0.0000]" ] || fail "$1: no caption"
    echo "$1: image $(field viewport), caption $(field presentationCaption), view $(field view)"
}
layout() { echo "$(field docks) $(field windowTabs) $(field viewport)"; }

ui_start present --size 1280x720
wait_frames 4
docked=$(layout)
echo "docked: viewport $(field viewport)"
key_until p presentation true
entered "P"
shot presentation_final
view=$(field view)
key_until v presentation true
wait_frames 4
[ "$(field view)" != "$view" ] || fail "V did not change the view in the presentation layout ($view)"
entered "after V"
shot presentation_view
xdotool key --delay 30 shift+v
wait_frames 6
key_until p presentation false
[ "$(layout)" = "$docked" ] || fail "P did not restore the docked layout: $(layout), before $docked"
echo "P again: the docked layout is back (docks, tabs and viewport as before)"

# View > Presentation by clicks, and back by the same item.
click_at $(centre viewMenu)
[ "$(field presentationItem)" != "[0.0000,0.0000,0.0000,0.0000]" ] || fail "View > Presentation not drawn"
click_at $(centre presentationItem)
wait_frames 4
[ "$(field presentation)" = true ] || fail "View > Presentation did not enter it"
entered "View > Presentation"
click_at $(centre viewMenu)
click_at $(centre presentationItem)
wait_frames 6
[ "$(field presentation)" = false ] || fail "View > Presentation did not leave it"
[ "$(layout)" = "$docked" ] || fail "the menu did not restore the docked layout: $(layout), before $docked"

# A lesson beside the image.
set -- $(row 2)
click_at "$1" "$2"
wait_frames 8
[ "$(field lesson)" = '"position_from_depth:1"' ] || fail "the course row did not open position_from_depth:1 ($(field lesson))"
lessons=$(field lessonsWindow)
key_until p presentation true
entered "P with a lesson"
awk -v n="$(field lessonLines)" 'BEGIN { exit !(n >= 12) }' || fail "the lesson beside the image shows $(field lessonLines) lines"
echo "lesson beside: window $(field lessonsWindow), region $(field lessonLines) lines"
shot presentation_lesson
key_until p presentation false
[ "$(field lessonsWindow)" = "$lessons" ] || fail "the Lessons window is $(field lessonsWindow) after leaving, $lessons before"
ui_quit
echo "ui_presentation: PASS"
