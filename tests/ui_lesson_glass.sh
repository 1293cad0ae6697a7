#!/bin/sh
# A lesson step on the default scene with its glass panes ("scene": {"glass": true}, issue 47) in the
# real editor, with real X clicks (xdotool): opening it from the course stands the panes (the Log's
# triangle count grows by the panes' 6), Next to a step without glass takes them away, Back brings
# them again, and Leave returns to the editor's own scene and camera. Every check reads
# --log-frames and the editor's Log lines on stderr.
# usage: ui_lesson_glass.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"

ui_name=ui_lesson_glass
log="$work/frames.jsonl"
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

mkdir -p "$work/lessons"
cat > "$work/lessons/glass.json" << 'EOF'
{"format": "gbuffer-lab-lesson", "version": 2, "id": "glass", "title": "Glass", "size": [160, 90],
 "setup": {"scene": {"lights": 4, "glass": true}, "pipeline": {"glass_outline": true}},
 "steps": [{"title": "The panes", "look": "Hatched.", "equation": "alpha 0.4", "question": "Where?",
            "answer": "In the courtyard, hatched.", "camera": {"position": [0, 2, 9], "look_at": [0, 1.4, 0]}},
           {"title": "No panes", "look": "Gone.", "equation": "alpha 0", "question": "Where?",
            "answer": "Nowhere: this step has none.", "scene": {"glass": false}}]}
EOF
export GBL_LESSONS_DIR="$work/lessons"
# scenes N: the editor's Log lines saying it made the default scene current, with (N = 129248
# triangles) or without (129242) the glass.
scenes() { grep -c "scene default: $1 triangles" "$work/editor.log" || true; }
button() { field lessonButtons | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d %d", $(2 * n - 1), $(2 * n) }'; }
press() {
    set -- $(button "$1")
    [ "${1:-0}" -gt 0 ] || fail "lesson button not drawn: $(field lessonButtons)"
    click_at "$1" "$2"
    wait_frames 6
}

"$bin" --size 1280x720 --no-vsync --log-frames "$log" > "$work/editor.log" 2>&1 &
pid=$!
wait_frames 4
ui_window
wait_frames 2
camera0=$(field camera)
[ "$(scenes 129242)" = 1 ] && [ "$(scenes 129248)" = 0 ] || fail "the editor did not start without glass: $(cat "$work/editor.log")"

press 1
[ "$(field lesson)" = '"glass:1"' ] || fail "the course's row did not open glass:1 (lesson $(field lesson))"
[ "$(scenes 129248)" = 1 ] || fail "glass:1 did not stand the panes: $(tail -n 3 "$work/editor.log")"
shot glass-1
press 3
[ "$(field lesson)" = '"glass:2"' ] || fail "Next did not go to glass:2 (lesson $(field lesson))"
[ "$(scenes 129242)" = 2 ] || fail "glass:2 did not take the panes away: $(tail -n 3 "$work/editor.log")"
press 2
[ "$(field lesson)" = '"glass:1"' ] || fail "Back did not go to glass:1 (lesson $(field lesson))"
[ "$(scenes 129248)" = 2 ] || fail "Back to glass:1 did not stand the panes again: $(tail -n 3 "$work/editor.log")"
echo "steps: glass, none, glass again"
press 4
[ "$(field lesson)" = '""' ] || fail "Leave did not close the lesson ($(field lesson))"
[ "$(scenes 129242)" = 3 ] || fail "Leave did not load the scene without glass: $(tail -n 3 "$work/editor.log")"
[ "$(field camera)" = "$camera0" ] || fail "Leave did not restore the camera: $camera0 -> $(field camera)"
echo "left: the default scene without glass, camera $(field camera)"
ui_stop
echo "ui_lesson_glass: PASS"
