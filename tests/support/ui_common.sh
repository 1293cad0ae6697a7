# Shared set-up of the UI test scripts (tests/ui_*.sh): the work folder, failing, reading the
# editor's --log-frames lines (flat JSON written by ui/model/frame_log.cpp), waiting for frames,
# finding the editor's X window and placing real clicks (xdotool) on what the log says was drawn:
# scrolling a combo into view, opening it, picking a View > UI scale choice.
# Source it after setting ui_name (the test's name, for messages), work (the test's folder) and
# log (the frame log being read; may change later). POSIX sh.

pid=""

# ui_require_xdotool: the test is skipped (exit 0) where xdotool is missing.
ui_require_xdotool() {
    if ! command -v xdotool >/dev/null 2>&1; then
        echo "$ui_name skipped: xdotool not found (scripts/install-deps.sh installs it)"
        exit 0
    fi
}

# ui_fresh_work: an empty $work, with the editor's crash recovery files and layout file inside it.
ui_fresh_work() {
    rm -rf "$work"
    mkdir -p "$work"
    export GBL_RECOVERY_DIR="$work/recovery" XDG_CONFIG_HOME="$work/config"
    mkdir -p "$GBL_RECOVERY_DIR" "$XDG_CONFIG_HOME"
}

fail() {
    echo "$ui_name: FAIL: $*"
    [ -n "$log" ] && [ -f "$log" ] && tail -n 3 "$log"
    [ -n "$pid" ] && kill "$pid" 2>/dev/null
    exit 1
}

# --- reading the frame log --------------------------------------------------------------------
lines() { [ -f "$log" ] && wc -l < "$log" || echo 0; }
# last: the newest complete line. The editor may be writing a line while it is read, so a last
# line without its newline is left for the next read.
nl='
'
last() {
    t=$(tail -n 2 "$log"; printf x)
    t=${t%x}
    case "$t" in
        *"$nl") t=${t%"$nl"} ;;
        *) t=${t%"$nl"*} ;;
    esac
    printf '%s\n' "${t##*"$nl"}"
}
# field NAME [LINE]: the raw value of a number, boolean, "string" or [..] array field.
field() {
    line="${2:-$(last)}"
    printf '%s\n' "$line" | sed -n "s/.*\"$1\":\(\[[^]]*\]\|\"[^\"]*\"\|[^,}]*\).*/\1/p"
}
# wait_frames N: until N more frames are logged (at most 60 s); fails when the editor ($pid) exits.
wait_frames() {
    target=$(( $(lines) + $1 ))
    i=0
    while [ "$(lines)" -lt "$target" ]; do
        kill -0 "$pid" 2>/dev/null || editor_exited
        i=$((i + 1))
        [ "$i" -le 600 ] || fail "no frame logged for 60 s"
        sleep 0.1
    done
}
# wait_frames_or_exit N: as wait_frames, but the editor exiting ends the wait instead of failing it.
# For the wait after a test's last click, where the editor's UI script may reach its end (and the
# editor quit) while a loaded machine's shell is still counting frames; the log keeps every frame,
# and the test's own checks and its wait for the exit status follow.
wait_frames_or_exit() {
    target=$(( $(lines) + $1 ))
    i=0
    while [ "$(lines)" -lt "$target" ] && kill -0 "$pid" 2>/dev/null; do
        i=$((i + 1))
        [ "$i" -le 600 ] || fail "no frame logged for 60 s"
        sleep 0.1
    done
}
# editor_exited: fails with the editor's exit status and the end of its output (the newest .log in
# $work: each script sends the editor's stdout and stderr there), so that a crash on a CI machine,
# whose work folder is gone, says what happened (a sanitizer's report, a GLFW error, a script FAIL).
editor_exited() {
    exit_status=0
    wait "$pid" 2>/dev/null || exit_status=$?
    pid=""
    out_file=$(ls -t "$work"/*.log 2>/dev/null | head -n 1)
    [ -n "$out_file" ] && { echo "--- the last 40 lines of $out_file:"; tail -n 40 "$out_file"; echo "---"; }
    fail "the editor exited with status $exit_status"
}
# events_since N: the events and actions logged after line N.
events_since() { tail -n +"$(( $1 + 1 ))" "$log" | sed -n 's/.*"events":\(\[[^]]*\]\).*"actions":\(\[[^]]*\]\).*/\1 \2/p'; }
# rect_point NAME FX FY: "x y" of a point inside a logged [x, y, w, h] rectangle, at fractions of its size.
rect_point() { field "$1" | tr -d '[]' | awk -F, -v fx="$2" -v fy="$3" '{ printf "%d %d", $1 + $3 * fx, $2 + $4 * fy }'; }
# centre NAME: "x y" of the centre of a logged rectangle.
centre() { rect_point "$1" 0.5 0.5; }
# clipped_list [LINE]: the "clipped" entries of a frame log line, one a line.
clipped_list() {
    line="${1:-$(last)}"
    printf '%s\n' "$line" | sed -n 's/.*"clipped":\[\([^]]*\)\].*/\1/p' | sed 's/","/"\n"/g' | grep -v '^$' || true
}

# --- the editor's window ----------------------------------------------------------------------
# ui_window: sets wid to the newest visible gbuffer-lab window and focuses it.
ui_window() {
    wid=$(xdotool search --sync --onlyvisible --name '^gbuffer-lab$' | tail -n 1)
    [ -n "$wid" ] || fail "no gbuffer-lab window"
    xdotool windowactivate --sync "$wid" 2>/dev/null || xdotool windowfocus --sync "$wid"
}
# settle_click N: after a click placed when the log had N lines, waits until a frame has logged the
# button's release, then two frames more. A widget logs its rectangle as it is drawn, so the frame
# that acts on a click may still show a button the click takes away (a loaded machine can log frames
# between xdotool's return and the editor reading the events); the frames after it show the result.
settle_click() {
    settle_tries=0
    until events_since "$1" | grep -q 'button 0 release'; do
        wait_frames 1
        settle_tries=$((settle_tries + 1))
        [ "$settle_tries" -le 200 ] || fail "a click's release was never logged"
    done
    wait_frames 2
}
# click_at X Y: move there, wait 0.1 s, press and release with a 50 ms dwell; returns once a frame
# has shown what the click did (settle_click).
click_at() {
    click_from=$(lines)
    xdotool mousemove --window "$wid" "$1" "$2" sleep 0.1 mousedown 1 sleep 0.05 mouseup 1
    settle_click "$click_from"
}
# lock_at FX FY: the Pixel inspector locked on that point of the viewport: unlock (L), hover, lock (L).
lock_at() {
    set -- $(rect_point viewport "$1" "$2")
    xdotool key --delay 30 l
    wait_frames 2
    xdotool mousemove --window "$wid" "$1" "$2"
    wait_frames 4
    xdotool key --delay 30 l
    wait_frames 4
}
# shot NAME: a screenshot of the window into $work/NAME.png (ImageMagick) or .xwd; where neither
# tool is installed it says so and the test goes on (a screenshot is for a person, not a check).
shot() {
    import -window "$wid" "$work/$1.png" 2>/dev/null || xwd -id "$wid" -out "$work/$1.xwd" 2>/dev/null ||
        echo "$ui_name: no screenshot of $1: neither import (ImageMagick) nor xwd works here"
}
# ui_start NAME [ARGS...]: an interactive editor (it reads and writes imgui.ini) with its frames
# logged to $work/NAME.jsonl and its output in $work/NAME.log; waits for its window and frames.
ui_start() {
    log="$work/$1.jsonl"
    out="$work/$1.log"
    shift
    "$bin" --no-vsync --log-frames "$log" "$@" > "$out" 2>&1 &
    pid=$!
    wait_frames 4
    ui_window
    wait_frames 2
}
# ui_quit [WHY]: Ctrl+Q, and the editor ($pid) ends within 10 s (saving imgui.ini on the way);
# WHY names what a hang would mean.
ui_quit() {
    xdotool key --delay 30 ctrl+q
    i=0
    while kill -0 "$pid" 2>/dev/null; do
        i=$((i + 1))
        [ "$i" -le 100 ] || fail "${1:-Ctrl+Q did not quit}"
        sleep 0.1
    done
    pid=""
}
# ui_stop: ends the editor this script started, if it still runs.
ui_stop() {
    [ -n "$pid" ] && kill "$pid" 2>/dev/null || true
    [ -n "$pid" ] && wait "$pid" 2>/dev/null || true
    pid=""
}

# wait_field NAME OP VALUE N WHY: frames until the log's field NAME is (OP =) or is not (OP !=)
# VALUE, at most N; else fails with WHY and the field's last value.
wait_field() {
    wait_field_frames=0
    until [ "$(field "$1")" "$2" "$3" ]; do
        wait_frames 1
        wait_field_frames=$((wait_field_frames + 1))
        [ "$wait_field_frames" -le "$4" ] || fail "$5 ($1 $(field "$1"))"
    done
}

# --- combos and menus -------------------------------------------------------------------------
# scroll_into_view NAME WINDOW MAX: the mouse over the logged window rectangle WINDOW, the wheel
# turned down until the logged rectangle NAME is drawn with its whole box above WINDOW's bottom
# edge, at most MAX steps; wheel_steps says how many it took.
scroll_into_view() {
    set -- "$1" "$2" "$3" $(centre "$2")
    [ "$4" -gt 0 ] || fail "$2 was not drawn ($(field "$2"))"
    xdotool mousemove --window "$wid" "$4" "$5"
    wait_frames 2
    wheel_steps=0
    until printf '%s %s\n' "$(field "$1" | tr -d '[]')" "$(field "$2" | tr -d '[]')" | tr ',' ' ' |
        awk '{ exit !($3 > 0 && $2 + $4 < $6 + $8 - 4) }'; do
        wheel_steps=$((wheel_steps + 1))
        [ "$wheel_steps" -le "$3" ] || fail "$3 wheel steps did not bring $1 into view"
        xdotool click 5
        wait_frames 2
    done
}
# open_combo NAME ITEMS N: a click on the logged combo rectangle NAME opens its list; the frame log's
# ITEMS field ("x y" centres, one pair an entry) must then list its entries. Sets item_x and
# item_y to the centre of entry N (from 1); the caller clicks it (click_at, or by hand where the
# editor may quit after that click).
open_combo() {
    set -- "$1" "$2" "$3" $(centre "$1")
    [ "$4" -gt 0 ] || fail "$1 was not drawn ($(field "$1"))"
    click_at "$4" "$5"
    wait_frames 4
    combo_items=$(field "$2")
    [ "$combo_items" != "[]" ] || fail "clicking $1 at $4,$5 did not open its list"
    item_x=$(echo "$combo_items" | tr -d '[]' | awk -F, -v n="$3" '{ printf "%d", $(2 * n - 1) }')
    item_y=$(echo "$combo_items" | tr -d '[]' | awk -F, -v n="$3" '{ printf "%d", $(2 * n) }')
}
# pick_ui_scale N SCALE: View > UI scale > choice N (model/ui_scale.h order) by clicks where the
# frame log says each is drawn, then frames until the log's uiScale is SCALE ("1.5000").
pick_ui_scale() {
    click_at $(centre viewMenu)
    [ "$(field uiScaleMenu)" != "[0.0000,0.0000,0.0000,0.0000]" ] || fail "the View menu did not open"
    xdotool mousemove --window "$wid" $(centre uiScaleMenu)
    wait_field uiScaleItems != "[]" 40 "View > UI scale did not open its choices"
    # uiScaleItems: an [x, y, w, h] rectangle a choice, from choice 0.
    click_at $(field uiScaleItems | tr -d '[]' |
        awk -F, -v n="$1" '{ i = 4 * n; printf "%d %d", $(i + 1) + $(i + 3) / 2, $(i + 2) + $(i + 4) / 2 }')
    wait_field uiScale = "$2" 40 "choice $1 did not set the scale to $2"
}
