#!/bin/sh
# The editor opened without --size, as the README's first command does: on a 1280x720 screen the
# window takes the screen (1600x900 would leave the right column and the bottom strip off it); on a
# 1920x1080 screen it keeps 1600x900. Either way the viewport, every G-buffer viewer's image and the
# Lights window lie inside the window, and no text is cut off. A screenshot of each is left in WORK_DIR.
# usage: ui_first_window.sh GBUFFER_LAB WORK_DIR            (ctest: each screen an Xvfb of its own)
#        ui_first_window.sh GBUFFER_LAB WORK_DIR SCREEN WxH (one screen, on the current $DISPLAY:
#                                                           SCREEN its size, WxH the window expected)
set -eu
bin="$1"
work="$2"
if [ $# -lt 4 ]; then
    rm -rf "$work"
    for pair in 1280x720:1280x720 1920x1080:1600x900; do
        screen=${pair%%:*}
        xvfb-run -a -s "-screen 0 ${screen}x24" sh "$0" "$bin" "$work/$screen" "$screen" "${pair#*:}" || exit 1
    done
    echo "ui_first_window: PASS"
    exit 0
fi
screen="$3"
expected="$4"
ui_name=ui_first_window
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

ui_start first --frame-sleep-ms 20
eval "$(xdotool getwindowgeometry --shell "$wid")"
[ "${WIDTH}x${HEIGHT}" = "$expected" ] || fail "on a $screen screen the window is ${WIDTH}x${HEIGHT}, not $expected"
# inside NAME X Y W H: the rectangle ends within the window.
inside() {
    awk -v n="$1" -v x="$2" -v y="$3" -v w="$4" -v h="$5" -v W="$WIDTH" -v H="$HEIGHT" 'BEGIN {
        if (w <= 0 || h <= 0) { print n " is not drawn"; exit }
        if (x < 0 || y < 0 || x + w > W + 0.5 || y + h > H + 0.5) print n " at " x "," y " " w "x" h " leaves the " W "x" H " window"
    }'
}
problems=$(
    inside viewport $(field viewport | tr -d '[]' | tr ',' ' ')
    inside "Lights window" $(field lightsWindow | tr -d '[]' | tr ',' ' ')
    field viewerImages | tr -d '[]' | tr ',' '\n' | paste -d' ' - - - - | {
        i=0
        while read -r x y w h; do
            i=$((i + 1))
            inside "viewer $i" "$x" "$y" "$w" "$h"
        done
    }
)
[ -z "$problems" ] || fail "on a $screen screen: $problems"
clipped=$(clipped_list)
[ -z "$clipped" ] || fail "text cut off on a $screen screen: $clipped"
shot "first_$screen"
ui_quit
echo "$screen: window ${WIDTH}x${HEIGHT}; viewport $(field viewport), $(field viewerImages | tr -d '[]' | tr ',' '\n' | paste -d' ' - - - - | wc -l) viewers and the Lights window inside it"
