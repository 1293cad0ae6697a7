#!/bin/sh
# File > Capture a program... in the real editor under Xvfb at 1280x720, with real X input (xdotool):
#  1. A click on File, a click on "Capture a program...": the dialog opens with its command field
#     focused. A program that does not exist is typed, EGL chosen, Capture clicked: the dialog shows the
#     capture's one sentence, no G-buffer opens and the editor keeps drawing frames.
#  2. tests/capture_target's deferred_demo typed instead (frame 1 of 3), Capture clicked: while apitrace
#     runs the frames go on, then the frame log names the captured manifest as the G-buffer shown, at the
#     demo's size, and the editor's log says it was captured.
# usage: ui_capture.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest; GBL_DEFERRED_DEMO names the demo)
set -eu
bin="$1"
work="$2"

ui_name=ui_capture
log=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
demo="${GBL_DEFERRED_DEMO:-}"
if [ -z "$demo" ] || ! command -v apitrace >/dev/null 2>&1 || ! command -v eglretrace >/dev/null 2>&1; then
    echo "$ui_name skipped: needs tests/capture_target's deferred_demo (EGL builds) and apitrace, eglretrace (Debian: apitrace apitrace-tracers)"
    exit 0
fi
ui_fresh_work
# The dialog's folder is ./capture of the editor's working folder.
cd "$work"

# type_into NAME FX TEXT: a click in the logged field NAME at FX of its width, everything in it
# selected, TEXT typed.
type_into() {
    set -- "$(rect_point "$1" "$2" 0.5)" "$3"
    # shellcheck disable=SC2086
    click_at $1
    # Ctrl held across frames: the editor reads the modifiers as GLFW has them when the frame handles
    # the key, and a quick ctrl+a can be over by then.
    xdotool keydown ctrl
    wait_frames 2
    xdotool key a
    wait_frames 2
    xdotool keyup ctrl
    xdotool type --delay 20 "$2"
    wait_frames 2
}
# wait_capture: until the frame log says no capture runs (at most 600 frames), then two frames more.
wait_capture() {
    tries=0
    until [ "$(field capturing)" = false ]; do
        tries=$((tries + 1))
        [ "$tries" -le 600 ] || fail "the capture ran for 600 frames"
        wait_frames 1
    done
    wait_frames 2
}

ui_start capture --size 1280x720 --frame-sleep-ms 20
[ "$(field gbuffer)" = '""' ] || fail "the editor started with G-buffer $(field gbuffer) shown"
set -- $(rect_point fileMenu 0.5 0.5)
[ "${1:-0}" -gt 0 ] || fail "the menu bar's File was not logged: $(field fileMenu)"
click_at "$1" "$2"
set -- $(rect_point captureItem 0.3 0.5)
[ "${1:-0}" -gt 0 ] || fail "clicking File showed no Capture a program item: $(field captureItem)"
click_at "$1" "$2"
[ "$(field captureDialog)" = true ] || fail "clicking Capture a program... opened no dialog"
[ "$(field captureOut)" != "[0,0,0,0]" ] || fail "the dialog drew no folder field"

# --- 1. a program that does not exist: one sentence, the editor goes on ---------------------------
xdotool type --delay 20 "$work/no_such_program --frames 3"
wait_frames 2
set -- $(rect_point captureEgl 0.2 0.5)
click_at "$1" "$2"
shot capture_dialog
set -- $(rect_point captureButton 0.5 0.5)
[ "${1:-0}" -gt 0 ] || fail "no Capture button in the dialog: $(field captureButton)"
click_at "$1" "$2"
wait_capture
error=$(field captureError)
case "$error" in
    *no_such_program*"not a program that can be run"*) ;;
    *) fail "the missing program gave $error, not the capture's sentence" ;;
esac
# One sentence: a single full stop, at its end.
[ "$(printf '%s' "$error" | tr -cd '.' | wc -c)" = 1 ] || fail "not one sentence: $error"
[ "$(field gbuffer)" = '""' ] || fail "the failed capture opened G-buffer $(field gbuffer)"
[ "$(field captureDialog)" = true ] || fail "the failed capture closed its dialog"
before=$(lines)
wait_frames 10
[ "$(lines)" -ge $((before + 10)) ] || fail "the editor stopped drawing after the failed capture"
shot capture_refused

# --- 2. deferred_demo: captured and opened ------------------------------------------------------
type_into captureCommand 0.5 "$demo --size 320x180 --frames 3"
type_into captureFrame 0.1 1
set -- $(rect_point captureButton 0.5 0.5)
started=$(lines)
click_at "$1" "$2"
[ "$(field capturing)" = true ] && shot capture_running
wait_capture
# Frames were drawn while the capture ran.
[ "$(lines)" -gt $((started + 5)) ] || fail "the editor drew $(( $(lines) - started )) frames during the capture"
grep -q '"capturing":true' "$log" || fail "no frame was logged while the capture ran"
manifest="$work/capture/manifest.json"
[ -f "$manifest" ] || fail "no manifest at $manifest: $(field captureError)"
tries=0
until [ "$(field gbuffer)" = "\"$manifest\"" ]; do
    tries=$((tries + 1))
    [ "$tries" -le 200 ] || fail "the capture opened G-buffer $(field gbuffer), not $manifest ($(field captureError))"
    wait_frames 1
done
wait_frames 4
[ "$(field frameSize)" = "[320,180]" ] || fail "the captured G-buffer is shown at $(field frameSize), not 320x180"
[ "$(field captureDialog)" = false ] || fail "the dialog stayed open after a good capture"
[ "$(field captureError)" = '""' ] || fail "a good capture left the error $(field captureError)"
grep -qF "Captured $manifest" "$work/capture.log" || fail "the editor did not log the capture"
grep -qF "G-buffer $manifest: 320x180" "$work/capture.log" || fail "the editor did not log opening the capture at 320x180"
shot capture_opened
ui_quit "Ctrl+Q did not quit the editor after the capture"
echo "$ui_name: PASS"
