#!/bin/sh
# Nothing is cut off at 1280x720 and 1600x900 where ImGui can tell (ui/panels/clip_check.h): the
# editor runs a few frames with --log-frames and the last frame's "clipped" list must be empty
# (every window, the G-buffer strip included), at start, with the viewer tools' rows open, and with
# a count heat map shown and the pixel inspector's exact-count line.
# The images are the point (issue 26): in every run the frame log's rectangles must show each
# G-buffer viewer's image at least 240 px wide at 1280x720 (280 px at 1600x900) and the viewport's
# image at least 40 % of the window's width and of its height, whatever tools are open.
# UI scale (issue 26): the same runs at 1600x900 with --ui-scale 1.5 (a projector) assert the same
# (280 px viewers: the side columns and the strip grow with the scale, the strip's cells keep a
# fifth of the width) and that the frame log reports scale 1.5.
# usage: ui_layout_fits.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
ui_name=ui_layout_fits
log=""
. "$(dirname "$0")/support/ui_common.sh"
ui_fresh_work
# The second run opens the G-buffer cells' longest rows: histograms with their fit buttons and
# statistics line, header counts, and a diff's threshold and statistics.
cat > "$work/tools.txt" <<'SCRIPT'
frames 3
viewer-tool position histogram on
viewer-tool depth histogram on
viewer-tool normal nan on
viewer-pin albedo
frames 2
viewer-tool albedo diff on
frames 4
# A pinned lit frame survives the viewport's toolbar: Tools off and on again, with a histogram,
# leave the frame its size, so the pin stays comparable (issue 26: it used to take three presses).
set view depth
pin-lit
frames 2
lit-diff on
viewport-tools off
frames 2
viewport-tools on
viewer-tool viewport histogram on
frames 3
expect-lit-diff pixels > 1000
SCRIPT
# The third shows the lights-per-cluster heat map with its labelled legend, the inspector locked
# on a surface pixel (its count line).
cat > "$work/heat.txt" <<'SCRIPT'
frames 3
set mode clustered
set view heatmap
inspect 300 250
frames 4
SCRIPT
# image_sizes LINE WxH: the viewers' image widths and the viewport image's size, with FAIL after
# each that is too small.
image_sizes() {
    viewers=$(field viewerImages "$1" | tr -d '[]')
    viewport=$(field viewport "$1" | tr -d '[]')
    echo "$2 $viewers $viewport" | awk -F'[ ,x]' '{
        w = $1; h = $2; least = w >= 1600 ? 280 : 240; out = "viewer widths"
        if (NF - 2 != 24) { print "FAIL: expected 5 viewer and 1 viewport rectangles"; exit }
        for (i = 0; i < 5; ++i) {
            vw = $(3 + 4 * i + 2); out = out " " int(vw) (vw < least ? " FAIL" : "")
        }
        ww = $(3 + 20 + 2); wh = $(3 + 20 + 3)
        out = out "; viewport " int(ww) "x" int(wh)
        if (ww < 0.4 * w || wh < 0.4 * h) out = out " FAIL"
        print out
    }'
}
status=0
for setting in 1280x720@1 1600x900@1 1600x900@1.5; do
    size=${setting%@*}
    scale=${setting#*@}
    where=$size
    [ "$scale" = 1 ] || where="$size at scale $scale"
    for run in start tools heat; do
        log="$work/frames-$setting-$run.jsonl"
        set -- --frames 8
        [ "$run" = tools ] && set -- --ui-test "$work/tools.txt"
        [ "$run" = heat ] && set -- --ui-test "$work/heat.txt"
        [ "$scale" = 1 ] || set -- "$@" --ui-scale "$scale"
        "$bin" --size "$size" --no-vsync "$@" --log-frames "$log" > "$work/editor-$setting-$run.log" 2>&1 ||
            { cat "$work/editor-$setting-$run.log"; echo "ui_layout_fits: FAIL: the editor failed at $where ($run)"; exit 1; }
        logged=$(field uiScale "$(tail -n 1 "$log")")
        echo "$where ($run): the log's uiScale: $logged"
        if ! awk -v a="$logged" -v b="$scale" 'BEGIN { exit !(a != "" && a + 0 == b + 0) }'; then
            echo "ui_layout_fits: FAIL: the frame log reports scale '$logged', not $scale ($run)"
            status=1
        fi
        sizes=$(image_sizes "$(tail -n 1 "$log")" "$size")
        echo "$where ($run): $sizes"
        case "$sizes" in *FAIL*) echo "ui_layout_fits: FAIL: images too small at $where ($run)"; status=1 ;; esac
        clipped=$(clipped_list "$(tail -n 1 "$log")")
        echo "$where ($run): cut off: ${clipped:-nothing}"
        if [ -n "$clipped" ]; then
            echo "ui_layout_fits: FAIL: content cut off at $where ($run)"
            status=1
        fi
    done
done
[ "$status" -eq 0 ] && echo "ui_layout_fits: PASS"
exit "$status"
