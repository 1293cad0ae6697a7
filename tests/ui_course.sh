#!/bin/sh
# The course view of the Lessons window (issue 27) with real X input at 1280x720: every lesson is
# listed with its progress; a click on a row opens that lesson where the student left it; a task
# done with real input (position_from_depth:2, lock the inspector on the far galleries) and the
# steps seen are counted and written to the progress file in the config folder; after the editor
# quits and starts again with the same XDG_CONFIG_HOME the course shows the same progress and the
# lesson reopens at the step left; "Next lesson" at the last step opens the next lesson; Restart
# clears that lesson's progress only; a progress file that cannot be read gives no progress and is
# moved aside (.broken) at the first new progress. Every check reads --log-frames; screenshots stay in WORK_DIR.
# usage: ui_course.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"

ui_name=ui_course
log="$work/first.jsonl"
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work
progress_file="$XDG_CONFIG_HOME/gbuffer-lab/lesson_progress.json"

# button N: window coordinates of Lessons button N (as in ui_lessons.sh: 3 Next, 4 Leave).
button() {
    field lessonButtons | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d %d", $(2 * n - 1), $(2 * n) }'
}
click() {
    set -- $(button "$1")
    [ "${1:-0}" -gt 0 ] || fail "button not drawn: $(field lessonButtons)"
    click_at "$1" "$2"
    wait_frames 4
}
# rects_point NAME N FX FY: "x y" inside the Nth (from 1) rectangle of a flat [x, y, w, h, ...] array.
rects_point() {
    field "$1" | tr -d '[]' | awk -F, -v n="$2" -v fx="$3" -v fy="$4" \
        '{ b = 4 * (n - 1); printf "%d %d", $(b + 1) + $(b + 3) * fx, $(b + 2) + $(b + 4) * fy }'
}
# click_row NAME N: clicks the Nth course row (courseRows) or Restart button (courseRestart).
click_row() {
    set -- $(rects_point "$1" "$2" 0.5 0.5)
    [ "${1:-0}" -gt 0 ] || fail "$1 entry not wholly in view: $(field "$1")"
    click_at "$1" "$2"
    wait_frames 4
}
# progress ID: that lesson's "steps/steps tasks/tasks right/asked" from courseProgress.
progress() { field courseProgress | tr -d '"' | tr '|' '\n' | sed -n "s/^$1 //p"; }
start_editor() { ui_start "$1" --size 1280x720; }

# --- a first run: no progress yet; open position_from_depth by its row, do its task ---------------
start_editor first
[ "$(field lesson)" = '""' ] || fail "a lesson is shown at start: $(field lesson)"
[ "$(progress position_from_depth)" = "0/4 0/1 0/0" ] || fail "fresh progress is not empty: $(field courseProgress)"
[ "$(progress camera_inside)" = "0/5 0/1 0/0" ] || fail "fresh progress is not empty: $(field courseProgress)"
[ ! -e "$progress_file" ] || fail "a progress file was written before any progress"
shot course-fresh
click_row courseRows 2
[ "$(field lesson)" = '"position_from_depth:1"' ] || fail "the second row did not open position_from_depth:1 ($(field lesson))"
click 3
[ "$(field lesson)" = '"position_from_depth:2"' ] || fail "Next did not go to step 2 ($(field lesson))"
[ "$(field lessonTasks)" = '"0"' ] || fail "the pixel task is not unticked at the step's start: $(field lessonTasks)"
[ "$(progress position_from_depth)" = "2/4 0/1 0/0" ] || fail "two steps seen, counted $(progress position_from_depth)"
# The checklist is in view at 1280x720 without scrolling: the step's Show answer button, drawn after
# it, is wholly in view at the step's start.
[ "$(button 5)" != "0 0" ] || fail "Show answer (after the checklist) is not in view at 1280x720"
shot task-step
lock_at 0.5 0.12
[ "$(field lessonTasks)" = '"1"' ] || fail "locking a pixel of the far galleries did not tick the task: $(field lessonTasks)"
[ "$(progress position_from_depth)" = "2/4 1/1 0/0" ] || fail "the task done is not counted: $(progress position_from_depth)"
[ -f "$progress_file" ] || fail "no progress file at $progress_file after progress"
grep -q '"position_from_depth"' "$progress_file" || fail "the progress file does not name the lesson: $(cat "$progress_file")"
echo "first run: $(progress position_from_depth) counted and written to $progress_file"
ui_stop
rm -f "$GBL_RECOVERY_DIR"/*

# --- a second run with the same config folder: the progress is shown, the lesson reopens there ----
start_editor second
[ "$(progress position_from_depth)" = "2/4 1/1 0/0" ] || fail "after a restart the course shows $(progress position_from_depth)"
[ "$(progress camera_inside)" = "0/5 0/1 0/0" ] || fail "another lesson gained progress: $(progress camera_inside)"
shot course-after-restart
click_row courseRows 2
[ "$(field lesson)" = '"position_from_depth:2"' ] || fail "the row did not reopen the lesson where it was left ($(field lesson))"
echo "second run: the course shows $(progress position_from_depth); the lesson reopened at $(field lesson)"
# At the last step, "Next lesson" opens the next lesson.
click 3
click 3
[ "$(field lesson)" = '"position_from_depth:4"' ] || fail "Next did not reach the last step ($(field lesson))"
[ "$(field nextLesson)" != "[0.0000,0.0000,0.0000,0.0000]" ] || fail "no Next lesson button at the last step"
shot next-lesson
set -- $(rect_point nextLesson 0.5 0.5)
click_at "$1" "$2"
wait_frames 4
[ "$(field lesson)" = '"fullscreen_pass:1"' ] || fail "Next lesson did not open fullscreen_pass:1 ($(field lesson))"
[ "$(progress position_from_depth)" = "4/4 1/1 0/0" ] || fail "the steps seen are not counted: $(progress position_from_depth)"
click 4
[ "$(field lesson)" = '""' ] || fail "Leave did not return to the course ($(field lesson))"
# Restart clears that lesson's progress only.
click_row courseRestart 2
[ "$(progress position_from_depth)" = "0/4 0/1 0/0" ] || fail "Restart left $(progress position_from_depth)"
[ "$(progress fullscreen_pass)" = "1/3 0/1 0/0" ] || fail "Restart of another lesson changed fullscreen_pass: $(progress fullscreen_pass)"
grep -q '"position_from_depth"' "$progress_file" && fail "the progress file still names the restarted lesson"
grep -q '"fullscreen_pass"' "$progress_file" || fail "the progress file lost another lesson's progress"
shot course-restarted
echo "Restart: position_from_depth $(progress position_from_depth), fullscreen_pass $(progress fullscreen_pass)"
ui_stop
rm -f "$GBL_RECOVERY_DIR"/*

# --- a progress file that cannot be read: no progress, and the file is kept until new progress ----
printf 'not json' > "$progress_file"
start_editor broken
[ "$(progress fullscreen_pass)" = "0/3 0/1 0/0" ] || fail "a broken progress file gave progress: $(field courseProgress)"
[ "$(cat "$progress_file")" = "not json" ] || fail "the broken progress file was written over before any progress"
[ "$(grep -c "progress file not read" "$work/broken.log")" = 1 ] ||
    fail "not one message about the broken progress file: $(cat "$work/broken.log")"
click_row courseRows 3
[ "$(field lesson)" = '"fullscreen_pass:1"' ] || fail "the third row did not open fullscreen_pass:1 ($(field lesson))"
[ "$(cat "$progress_file.broken" 2>/dev/null)" = "not json" ] || fail "the broken file was not moved aside to .broken"
grep -q '"fullscreen_pass"' "$progress_file" || fail "no new progress file after the broken one"
echo "broken file: no progress at start, kept as $progress_file.broken at the first progress"
ui_stop
rm -f "$GBL_RECOVERY_DIR"/*
echo "ui_course: PASS"
