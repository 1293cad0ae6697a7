#!/bin/sh
# The docked layout (issue 45) with real X input at 1280x720:
# - the default layout gives every editor window a dock node of its own;
# - the Log window's tab dragged into the Stats window's tab bar: both then share one dock node
#   (the frame log's "docks"), Stats and Log are tabs of it;
# - the Pixel inspector's tab dragged over the viewport, away from its dock targets: it floats;
# - quitting keeps the layout in imgui.ini (the config folder) and the next start has it back;
# - View > Reset layout puts every window back in a node of its own.
# usage: ui_dock_drag.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_dock_drag
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work
ini="$XDG_CONFIG_HOME/gbuffer-lab/imgui.ini"

# dock NAME: the dock node ID the frame log gives the window NAME (0: floating).
dock() { field docks | tr -d '[]"' | tr ',' '\n' | sed -n "s/^$1=//p"; }
# tab N: "x y w h" of editor window N's tab (EditorWindow order: Viewport, G-buffer, Pixel inspector,
# Lights, Pipeline, Stats, Log, Lessons).
tab() { field windowTabs | tr -d '[]' | awk -F, -v n="$1" '{ printf "%d %d %d %d", $(4*n+1), $(4*n+2), $(4*n+3), $(4*n+4) }'; }
# drag X0 Y0 X1 Y1: press at (X0, Y0), move to (X1, Y1) in eight steps with short dwells (ImGui
# undocks a tab once it is dragged a few pixels, and shows the drop targets while hovering), release.
drag() {
    xdotool mousemove --window "$wid" "$1" "$2" sleep 0.2 mousedown 1 sleep 0.15
    wait_frames 2
    for s in 1 2 3 4 5 6 7 8; do
        xdotool mousemove --window "$wid" $(($1 + ($3 - $1) * s / 8)) $(($2 + ($4 - $2) * s / 8)) sleep 0.1
        wait_frames 1
    done
    wait_frames 3
    xdotool mouseup 1
    wait_frames 4
}
# distinct: every editor window has a dock node and no two share one.
distinct() {
    ids=$(field docks | tr -d '[]"' | tr ',' '\n' | sed 's/.*=//')
    [ "$(printf '%s\n' "$ids" | grep -cvx 0)" -eq 8 ] && [ "$(printf '%s\n' "$ids" | sort -u | wc -l)" -eq 8 ]
}

ui_start first --size 1280x720 --frame-sleep-ms 20
distinct || fail "the default layout does not give each window a dock node of its own: $(field docks)"
echo "default: $(field docks)"

set -- $(tab 6)
log_x=$(($1 + $3 / 2)) log_y=$(($2 + $4 / 2))
set -- $(tab 5)
# Into Stats's tab bar, to the right of its one tab.
drag "$log_x" "$log_y" $(($1 + $3 + 30)) $(($2 + $4 / 2))
[ "$(dock Log)" = "$(dock Stats)" ] && [ "$(dock Log)" != 0 ] ||
    fail "the Log window dragged into the Stats tab bar is not docked with it: $(field docks)"
set -- $(tab 5)
stats_y=$2
set -- $(tab 6)
[ "$2" -eq "$stats_y" ] || fail "the Log and Stats tabs are not in one tab bar: Stats at y $stats_y, Log at y $2"
echo "tabbed: Stats=$(dock Stats) Log=$(dock Log)"
shot tabbed

set -- $(tab 2)
set -- $(($1 + $3 / 2)) $(($2 + $4 / 2)) $(rect_point viewport 0.25 0.8)
drag "$@"
[ "$(dock 'Pixel inspector')" = 0 ] || fail "the Pixel inspector dragged over the viewport is still docked: $(field docks)"
echo "floating: Pixel inspector=$(dock 'Pixel inspector')"
shot floating
kept=$(field docks)
ui_quit
grep -q '^\[Docking\]' "$ini" || fail "imgui.ini keeps no dock layout: $(cat "$ini")"

ui_start second --size 1280x720 --frame-sleep-ms 20
[ "$(dock Log)" = "$(dock Stats)" ] && [ "$(dock 'Pixel inspector')" = 0 ] ||
    fail "the layout did not come back after a restart: $kept -> $(field docks)"
echo "restart: $(field docks)"

# View > Reset layout, clicked where the frame log says the menu and its item are drawn.
click_at $(centre viewMenu)
[ "$(field resetLayoutItem)" != "[0.0000,0.0000,0.0000,0.0000]" ] || fail "the View menu did not open"
click_at $(centre resetLayoutItem)
distinct || fail "View > Reset layout left: $(field docks)"
echo "reset: $(field docks)"
shot reset
ui_quit
echo "ui_dock_drag: PASS"
