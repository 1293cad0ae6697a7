#!/bin/sh
# The Lights window's attenuation plot in view without scrolling (issue 46) at 1280x720 and 1600x900:
# with a light selected (the editor starts with one), the plot the frame log reports (its rectangle
# is logged only when wholly in view) lies inside the Lights window, which was never scrolled.
# usage: ui_plot_visible.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_plot_visible
log=""
pid=""
. "$(dirname "$0")/support/ui_common.sh"
ui_require_xdotool
ui_fresh_work

for size in 1280x720 1600x900; do
    export XDG_CONFIG_HOME="$work/config_$size"  # each size starts with the default layout
    mkdir -p "$XDG_CONFIG_HOME"
    ui_start "plot_$size" --size "$size"
    wait_frames 8
    [ "$(field selectedLight)" -ge 0 ] || fail "$size: no light selected at start"
    echo "$size: Lights window $(field lightsWindow), plot $(field plotRect), Pipeline $(field pipelineWindow)"
    echo "$(field plotRect) $(field lightsWindow)" | tr -d '[]' | tr ',' ' ' | awk '{
        px = $1; py = $2; pw = $3; ph = $4; wx = $5; wy = $6; ww = $7; wh = $8
        exit !(pw > 0 && ph >= 100 && px >= wx && py >= wy && px + pw <= wx + ww + 0.5 && py + ph <= wy + wh + 0.5) }' ||
        fail "$size: the plot $(field plotRect) is not wholly inside the Lights window $(field lightsWindow)"
    shot "plot_$size"
    ui_quit
done
echo "ui_plot_visible: PASS"
