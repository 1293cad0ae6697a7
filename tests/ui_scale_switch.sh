#!/bin/sh
# View > UI scale changed while the editor runs, by real clicks (issue 46: 1.5x from the menu once
# blanked the window for good, GL_INVALID_VALUE in glBufferSubData on every frame). At 1280x720 the
# scale goes 1 -> 1.5 -> 1 -> 2 -> 1 -> 1.25 -> 1 through the menu; after each switch the frame log
# says the new scale, the viewport's pixels are lit (mean colour from an xwd dump of the window), the
# menu bar is drawn, and the editor's output holds no GL error.
# usage: ui_scale_switch.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_scale_switch
log=""
pid=""
here="$(dirname "$0")"
. "$here/support/ui_common.sh"
ui_require_xdotool
command -v xwd >/dev/null 2>&1 || { echo "$ui_name skipped: xwd not found (x11-apps)"; exit 0; }
ui_fresh_work

# lit NAME: the mean colour of the viewport's image, from a dump of the window.
lit() {
    xwd -id "$wid" -out "$work/$1.xwd"
    set -- "$work/$1.xwd" $(field viewport | tr -d '[]' | tr ',' ' ')
    python3 "$here/support/window_mean.py" "$@"
}
gl_errors() { grep -c 'GL_INVALID\|GL error\|GL_OUT_OF' "$out" || true; }

# pick N SCALE: View > UI scale > choice N, by clicks where the frame log says each is drawn.
pick() {
    pick_ui_scale "$1" "$2"
    wait_frames 3
}

ui_start switch --size 1280x720
before=$(lit start)
echo "start: viewport mean $before"
for step in "2 1.5000" "0 1.0000" "3 2.0000" "0 1.0000" "1 1.2500" "0 1.0000"; do
    set -- $step
    pick "$1" "$2"
    mean=$(lit "scale_$2")
    echo "scale $2: viewport $(field viewport) mean $mean, GL errors $(gl_errors)"
    [ "$(gl_errors)" = 0 ] || fail "GL errors after switching to $2: $(grep -m 3 'GL_' "$out")"
    # Lit as at the start (the same view, at another size), not the window's clear colour.
    awk -v m="${mean%% *}" -v b="${before%% *}" 'BEGIN { exit !(m > 0.6 * b && m > 0.03) }' ||
        fail "the viewport is dark after switching to $2 (mean $mean, at the start $before)"
    [ "$(field viewMenu)" != "[0.0000,0.0000,0.0000,0.0000]" ] || fail "no menu bar drawn at $2"
done
ui_quit
echo "ui_scale_switch: PASS"
