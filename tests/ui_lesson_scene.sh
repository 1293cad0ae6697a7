#!/bin/sh
# A lesson on a glTF scene in the real editor (issue 27), with real X clicks (xdotool): opening it
# from the course loads its scene (the shared Box model) with the lesson's camera, and Leave loads
# the default scene again with the camera it had. Every check reads --log-frames and the editor's
# Log lines on stderr. Skipped where the shared models are absent.
# usage: ui_lesson_scene.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest, GBL_SHARED_GLTF_DIR set)
set -eu
bin="$1"
work="$2"

ui_name=ui_lesson_scene
log="$work/frames.jsonl"
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
box="${GBL_SHARED_GLTF_DIR:-../shared/gltf}/Box/Box.gltf"
if [ ! -f "$box" ]; then
    echo "$ui_name skipped: needs the shared models ($box is absent)"
    exit 0
fi
ui_fresh_work

# A folder holding one lesson: the course's first row opens it.
mkdir -p "$work/lessons"
cat > "$work/lessons/box.json" << 'EOF'
{"format": "gbuffer-lab-lesson", "version": 2, "id": "box", "title": "Box", "scene": "Box/Box.gltf",
 "setup": {"lights": [{"position": [1.5, 2, 2], "color": [1, 1, 1], "intensity": 2,
                       "kc": 1, "kl": 0.35, "kq": 0.44, "threshold": 0.01953125}],
           "camera": {"position": [2, 1.5, 2.5], "look_at": [0, 0, 0]}},
 "steps": [{"title": "The box lit", "look": "The red box.", "equation": "{pixel.lit}", "question": "Why red?",
            "answer": "Its albedo is red.", "pixel": [0.5, 0.5]}]}
EOF
export GBL_LESSONS_DIR="$work/lessons"
# defaults: how many times the editor's Log said it made the default scene current.
defaults() { grep -c "scene default:" "$work/editor.log" || true; }

"$bin" --size 1280x720 --no-vsync --log-frames "$log" > "$work/editor.log" 2>&1 &
pid=$!
wait_frames 4
ui_window
wait_frames 2
camera0=$(field camera)
[ "$(defaults)" = 1 ] || fail "the editor did not start on the default scene: $(cat "$work/editor.log")"

set -- $(field lessonButtons | tr -d '[]' | awk -F, '{ printf "%d %d", $1, $2 }')
[ "${1:-0}" -gt 0 ] || fail "the course's first row is not drawn: $(field lessonButtons)"
click_at "$1" "$2"
wait_frames 6
[ "$(field lesson)" = '"box:1"' ] || fail "the course's row did not open box:1 (lesson $(field lesson))"
grep -q "Box/Box.gltf: 12 triangles" "$work/editor.log" ||
    fail "opening the lesson did not load Box.gltf: $(tail -n 3 "$work/editor.log")"
[ "$(field camera)" != "$camera0" ] || fail "the lesson's camera was not applied ($(field camera))"
echo "opened: $(field lesson) on Box.gltf, camera $(field camera)"
shot lesson-box

set -- $(field lessonButtons | tr -d '[]' | awk -F, '{ printf "%d %d", $7, $8 }')
[ "${1:-0}" -gt 0 ] || fail "Leave is not drawn: $(field lessonButtons)"
click_at "$1" "$2"
wait_frames 6
[ "$(field lesson)" = '""' ] || fail "Leave did not close the lesson ($(field lesson))"
[ "$(defaults)" = 2 ] || fail "Leave did not load the default scene again: $(tail -n 3 "$work/editor.log")"
[ "$(field camera)" = "$camera0" ] || fail "Leave did not restore the camera: $camera0 -> $(field camera)"
echo "left: the default scene again, camera $(field camera)"
ui_stop
echo "ui_lesson_scene: PASS"
