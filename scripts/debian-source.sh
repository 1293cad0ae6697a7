#!/usr/bin/env bash
# Fetches and unpacks a Debian source package into a folder, with a private apt configuration (a
# deb-src entry for the archive and suite this machine's apt already uses; the system's sources lists
# are not touched), and prints the unpacked folder. Once unpacked, it is reused without the network.
#   scripts/debian-source.sh PACKAGE DEST
# scripts/build-web.sh compiles zlib for the browser from Debian's zlib source package this way.
set -euo pipefail
package="$1"
dest="$2"
mkdir -p "$dest"
dest="$(cd "$dest" && pwd)"
found() { ls -d "$dest/$package"-*/ 2>/dev/null | head -1 || true; }
dir="$(found)"
if [ -z "$dir" ]; then
  apt_dir="$dest/apt"
  mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/sources.list.d"
  # The archive and suite of the machine's own (deb822 or one-line) sources.
  uri="$(grep -hE '^URIs:' /etc/apt/sources.list.d/*.sources 2>/dev/null | head -1 | awk '{print $2}' || true)"
  suite="$(grep -hE '^Suites:' /etc/apt/sources.list.d/*.sources 2>/dev/null | head -1 | awk '{print $2}' || true)"
  if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
    read -r uri suite < <(awk '$1=="deb" {for (i=2;i<=NF;i++) if ($i ~ /^[a-z]+:\/\//) {print $i, $(i+1); exit}}' /etc/apt/sources.list)
  fi
  uri="${uri:-http://deb.debian.org/debian}"
  suite="${suite:-bookworm}"
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $uri $suite main" > "$apt_dir/sources.list"
  apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list" -o "Dir::Etc::SourceParts=$apt_dir/sources.list.d"
            -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache" -o "Debug::NoLocking=1")
  apt-get -qq "${apt_opts[@]}" update >&2
  (cd "$dest" && apt-get -qq "${apt_opts[@]}" source "$package" >&2)
  dir="$(found)"
  [ -n "$dir" ] || { echo "debian-source.sh: no $package-* folder in $dest after apt-get source" >&2; exit 1; }
fi
echo "${dir%/}"
