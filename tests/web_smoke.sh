#!/usr/bin/env bash
# The browser build's smoke test (issue 29): serves build-web/ (scripts/build-web.sh makes it; this
# script builds nothing), loads the page in Debian's chromium headless with WebGL2 in software
# (SwiftShader), and checks that the first frame was drawn, that the console shows no error, and
# that the default scene in the screenshot is lit (not black). Not part of .ci/run or ctest yet.
#   tests/web_smoke.sh [build-web folder]      WEB_SMOKE_OUT=dir keeps the screenshot and the log there
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
site="${1:-$root/build-web}"
for f in index.html gbuffer-lab.js gbuffer-lab.wasm; do
  if [ ! -f "$site/$f" ]; then
    echo "web_smoke: $site/$f is missing: run scripts/build-web.sh first" >&2
    exit 1
  fi
done
command -v chromium > /dev/null || { echo "web_smoke: chromium is not installed (scripts/build-web.sh installs it)" >&2; exit 1; }

out="${WEB_SMOKE_OUT:-$(mktemp -d)}"
mkdir -p "$out"
port="$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
python3 -m http.server --bind 127.0.0.1 -d "$site" "$port" > "$out/http.log" 2>&1 &
server=$!
trap 'kill "$server" 2> /dev/null || true' EXIT
for _ in $(seq 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/index.html')" 2> /dev/null && break
  sleep 0.1
done

# Console messages reach stderr through --enable-logging. Virtual time lets the page run its frames
# without waiting for them in real time.
args=(--headless=new --use-angle=swiftshader --enable-unsafe-swiftshader --enable-logging=stderr --v=0
      --virtual-time-budget=3000 --window-size=1280,720 --screenshot="$out/screenshot.png"
      --user-data-dir="$out/profile")
[ "$(id -u)" -eq 0 ] && args+=(--no-sandbox)
timeout 120 chromium "${args[@]}" "http://127.0.0.1:$port/" > "$out/chromium.log" 2>&1 || true
grep -a 'CONSOLE' "$out/chromium.log" > "$out/console.log" || true
echo "web_smoke: console:"
sed 's/^/  /' "$out/console.log"

fail=0
if ! grep -q 'first frame drawn' "$out/console.log"; then
  echo "web_smoke: FAIL: the page never drew its first frame" >&2
  fail=1
fi
if grep -a -i -E 'error|uncaught|abort|GL_INVALID' "$out/console.log" > "$out/errors.log"; then
  echo "web_smoke: FAIL: the console shows errors:" >&2
  cat "$out/errors.log" >&2
  fail=1
fi
if [ ! -s "$out/screenshot.png" ]; then
  echo "web_smoke: FAIL: no screenshot" >&2
  exit 1
fi
# The scene part of the screenshot (right of and below the ImGui window) must be lit: a pure-Python
# PNG decode (8-bit RGB or RGBA, as Chromium writes), then the mean and the share of non-dark pixels.
python3 - "$out/screenshot.png" << 'PY' || fail=1
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, hdr = 8, b"", None
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR": hdr = struct.unpack(">IIBBBBB", body)
    elif kind == b"IDAT": idat += body
    pos += 12 + n
w, h, depth, ctype, _, _, interlace = hdr
assert depth == 8 and ctype in (2, 6) and interlace == 0, f"unexpected PNG format {hdr}"
bpp = 3 if ctype == 2 else 4
raw, stride = zlib.decompress(idat), w * bpp
rows, prev, i = [], bytearray(stride), 0
for _ in range(h):
    f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride]); i += 1 + stride
    for x in range(stride):
        a = line[x - bpp] if x >= bpp else 0; b = prev[x]; c = prev[x - bpp] if x >= bpp else 0
        if f == 1: line[x] = (line[x] + a) & 255
        elif f == 2: line[x] = (line[x] + b) & 255
        elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line); prev = line
total = lit = 0
for y in range(h * 2 // 5, h):
    r = rows[y]
    for x in range(w * 2 // 5, w, 2):
        l = (2126 * r[x * bpp] + 7152 * r[x * bpp + 1] + 722 * r[x * bpp + 2]) / 2550000.0
        total += l; lit += l > 0.08
count = (h - h * 2 // 5) * len(range(w * 2 // 5, w, 2))
mean, share = total / count, lit / count
print(f"web_smoke: screenshot {w}x{h}, scene region mean luminance {mean:.3f}, {100 * share:.0f}% of pixels lit")
if mean < 0.05 or share < 0.25:
    print("web_smoke: FAIL: the scene looks black", file=sys.stderr); sys.exit(1)
PY
echo "web_smoke: screenshot $out/screenshot.png"
[ "$fail" -eq 0 ] && echo "web_smoke: PASS"
exit "$fail"
