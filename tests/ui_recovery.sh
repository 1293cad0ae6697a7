#!/bin/sh
# Crash recovery end to end: an editor edits a light, autosaves, is killed with SIGKILL; the
# next editor offers the autosaved session and restoring it brings the edit back.
# usage: ui_recovery.sh GBUFFER_LAB WORK_DIR   (run under xvfb-run by ctest)
set -eu
bin="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work/recovery"
export GBL_RECOVERY_DIR="$work/recovery"

fail() { echo "ui_recovery: FAIL: $*"; exit 1; }

cat > "$work/edit.txt" <<'SCRIPT'
frames 3
light 0 intensity 7.25
set cull back
wait-autosave 30
# Keep running until killed.
frames 1000000
SCRIPT

cat > "$work/restore.txt" <<'SCRIPT'
frames 2
# A fresh editor starts with the default cull mode; the killed one had changed it.
expect-setting cull front
expect-recovery-offered
recover
frames 2
expect-light 0 intensity 7.25
expect-setting cull back
expect-no-gl-errors
SCRIPT

"$bin" --size 480x320 --ui-test "$work/edit.txt" > "$work/first.log" 2>&1 &
first=$!
# Wait (up to 120 s) for the autosave.
i=0
until grep -q "PASS .*wait-autosave" "$work/first.log"; do
    kill -0 "$first" 2>/dev/null || { cat "$work/first.log"; fail "the first editor ended before autosaving"; }
    i=$((i + 1))
    [ "$i" -le 240 ] || { kill -9 "$first"; fail "no autosave within 120 s"; }
    sleep 0.5
done
[ -f "$work/recovery/running-$first" ] || fail "no run marker for pid $first"
[ -f "$work/recovery/recovery-$first.json" ] || fail "no recovery session for pid $first"
kill -9 "$first"
wait "$first" 2>/dev/null || true
[ -f "$work/recovery/running-$first" ] || fail "the marker vanished although the editor was killed"

"$bin" --size 480x320 --ui-test "$work/restore.txt" > "$work/second.log" 2>&1 || { cat "$work/second.log"; fail "the second editor's checks failed"; }
cat "$work/second.log"
# The crash is answered and the second editor exited cleanly: nothing may be left behind.
left=$(ls -A "$work/recovery")
[ -z "$left" ] || fail "files left in the recovery folder: $left"
echo "ui_recovery: PASS"
