#!/usr/bin/env bash
# Checks the project's C and C++ files against .clang-format without changing them; lists each offender.
#
#   scripts/check-format.sh              every tracked C and C++ file in app/ renderer/ ui/ tests/ tools/
#   scripts/check-format.sh FILE...      only the files named (for a quick check of an edit)
#   scripts/check-format.sh --fix [FILE...]  reformats them in place instead
#
# Environment: CLANG_FORMAT (default clang-format; 14 is Debian bookworm's and the oldest accepted).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
clang_format="${CLANG_FORMAT:-clang-format}"
command -v "$clang_format" >/dev/null ||
    { echo "check-format: $clang_format not found; install Debian's clang-format (scripts/install-deps.sh)" >&2; exit 1; }

fix=0
if [[ "${1:-}" == "--fix" ]]; then fix=1; shift; fi
if [[ $# -gt 0 ]]; then
    files=("$@")  # as given, relative to the caller's folder
else
    cd "$root"
    # Tracked and new (not ignored) files in a checkout, every file in an unpacked source archive. Seed corpora and test data
    # are inputs, not sources.
    if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
        list() { git ls-files --cached --others --exclude-standard -- app renderer ui tests tools; }
    else
        list() { find app renderer ui tests tools -type f | sort; }
    fi
    mapfile -t files < <(list | grep -E '\.(cpp|c|h|hpp|cc|inl)$' | grep -v -E '^tests/(fuzz/corpus|data)/')
fi

if [[ $fix -eq 1 ]]; then
    "$clang_format" --style="file:$root/.clang-format" -i "${files[@]}"
    echo "check-format: reformatted ${#files[@]} files"
    exit 0
fi

# One clang-format run over all files (fast); each violation is reported as "FILE:LINE:COL: error: ...".
# The project's .clang-format is named by path, so a file outside the tree (/tmp) is checked against it too.
status=0
out=$("$clang_format" --style="file:$root/.clang-format" --dry-run --Werror "${files[@]}" 2>&1) || status=$?
mapfile -t bad < <(grep -- '-Wclang-format-violations' <<<"$out" | sed 's/:[0-9]*:[0-9]*: error: .*//' | uniq)
if [[ $status -ne 0 && ${#bad[@]} -eq 0 ]]; then
    # A bad config or a missing file is not "badly formatted": show clang-format's own words.
    echo "$out" >&2
    echo "check-format: $clang_format failed (exit $status) without naming a misformatted file" >&2
    exit 2
fi
for f in "${bad[@]}"; do echo "check-format: $f is not formatted"; done

if [[ ${#bad[@]} -gt 0 ]]; then
    echo "check-format: ${#bad[@]} of ${#files[@]} files differ from .clang-format; fix with:"
    echo "  scripts/check-format.sh --fix${*:+ ${bad[*]}}"
    exit 1
fi
echo "check-format: ${#files[@]} files formatted"
