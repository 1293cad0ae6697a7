#!/bin/sh
# The UI scale is kept with the window layout (issue 26). Interactive editors (no --frames, so they
# read and write imgui.ini in $XDG_CONFIG_HOME/gbuffer-lab) are started over a layout file and quit
# with Ctrl+Q; the frame log says the scale in use:
# - a saved UiScale=1.25 comes back, and is written back on quitting;
# - --ui-scale 2 wins over it for that run and leaves the saved value alone;
# - a bad saved value (UiScale=abc) gets one message naming the file, and the editor runs at 1;
# - the scale the dock tree was built for is saved beside it (LayoutScale=1.23: the drawn text's scale, issue 46: a tree
#   saved at another scale is built again); a bad one (LayoutScale=abc) gets one message.
# usage: ui_scale_saved.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_scale_saved
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work
ini="$XDG_CONFIG_HOME/gbuffer-lab/imgui.ini"
mkdir -p "$(dirname "$ini")"

# run NAME [ARGS...]: an editor at 800x600 (ui_common.sh's ui_start).
run() {
    name=$1
    shift
    ui_start "$name" --size 800x600 "$@"
}

printf '[gbuffer-lab][View]\nUiScale=1.25\n\n' > "$ini"
run saved
[ "$(field uiScale)" = 1.2500 ] || fail "the saved scale 1.25 did not come back: uiScale $(field uiScale)"
ui_quit
grep -qx 'UiScale=1.25' "$ini" || fail "imgui.ini lost the scale on quitting: $(cat "$ini")"
# The layout's scale is the drawn text's (ui/panels/fonts.h, uiScaleFactor): 16 px over 13 at 1.25.
grep -qx 'LayoutScale=1.2[0-9]*' "$ini" || fail "imgui.ini does not say the layout's scale: $(cat "$ini")"
echo "saved: uiScale 1.25 read and written back, with $(grep LayoutScale "$ini")"

run override --ui-scale 2
[ "$(field uiScale)" = 2.0000 ] || fail "--ui-scale 2 did not win over the saved 1.25: uiScale $(field uiScale)"
ui_quit
grep -qx 'UiScale=1.25' "$ini" || fail "--ui-scale 2 replaced the saved scale: $(cat "$ini")"
echo "override: uiScale 2 for the run, 1.25 still saved"

printf '[gbuffer-lab][View]\nUiScale=abc\n\n' > "$ini"
run bad
[ "$(field uiScale)" = 1.0000 ] || fail "a bad saved scale did not leave scale 1: uiScale $(field uiScale)"
grep -c "UiScale must be a number between 0.75 and 3" "$work/bad.log" | grep -qx 1 ||
    fail "no single message about the bad saved scale: $(cat "$work/bad.log")"
ui_quit
echo "bad: $(grep 'UiScale must' "$work/bad.log")"

printf '[gbuffer-lab][View]\nUiScale=1\nLayoutScale=abc\n\n' > "$ini"
run badlayout
[ "$(field uiScale)" = 1.0000 ] || fail "a bad LayoutScale changed the scale: uiScale $(field uiScale)"
grep -c 'LayoutScale "abc" is not a positive number' "$work/badlayout.log" | grep -qx 1 ||
    fail "no single message about the bad LayoutScale: $(cat "$work/badlayout.log")"
ui_quit
echo "bad layout scale: $(grep 'LayoutScale "abc"' "$work/badlayout.log")"
echo "ui_scale_saved: PASS"
