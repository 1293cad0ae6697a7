"""Browser cases of the page a class opens (issue 50), run by tests/web/browser_test.py with its
Page, Skip and helpers (register() hands them over):

  site       the published folder holds only the page's files (index.html, gbuffer-lab.js, .wasm,
             .data), and the server gives nothing else (no build files, no listings);
  loading    `chromium --headless --screenshot URL`, as a teacher takes one, shows the loading line or
             the complete editor; the editor is shown only after its first complete frame (the
             scene rendered and 3 frames more), with the loading line over the canvas until then;
  recovery   two reloads with no input offer nothing; an edit, then a reload without saving: the next
             page offers the changes in words ("your unsaved changes from a moment ago"), with no
             crash wording and no path;
  wheel      one wheel notch in pixels (Input.dispatchMouseEvent), lines and pages (WheelEvent's
             deltaMode) dollies the camera and scrolls the course as the desktop's notch does (the
             native editor's frame log, tests/web/native_wheel.sh, under --native or as recorded);
  limits     the tiled lesson says on screen and in the course that this browser cannot run it and
             leaves the mode alone; the menu bar keeps the scene's line; Help > About this browser
             holds the limits.
"""
import gzip
import json
import os
import shutil
import subprocess
import tempfile
import urllib.error
import urllib.request

bt = None  # tests/web/browser_test.py, set by register()
SETTINGS = {"site": None, "native": None}

# The page's files: all that scripts/build-web.sh publishes.
SITE_FILES = {"index.html", "gbuffer-lab.js", "gbuffer-lab.wasm", "gbuffer-lab.data"}

# The desktop's notch, as tests/web/native_wheel.sh measured it (the native editor, Debian's ImGui
# 1.86, 1280x720 under Xvfb): the camera before and after one notch up (X button 4) over the
# viewport, and the course rows before and after one notch down (button 5) over the Lessons window.
# --native BIN measures it again instead.
NATIVE_WHEEL = {"scroll": "scroll 0.00 1.00", "camera0": [0.0, 5.0, 11.5], "camera1": [0.0, 4.5099, 9.846],
                "rows0": [952, 200, 253, 17, 952, 234, 253, 17, 952, 268, 253, 17, 952, 302, 253, 17, 952, 336, 253, 17, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0],
                "rows1": [0, 0, 0, 0, 0, 0, 0, 0, 952, 203, 253, 17, 952, 237, 253, 17, 952, 271, 253, 17, 952, 305, 253, 17, 952, 339, 253, 17, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]}


def register(cases, module):
    global bt
    bt = module
    cases.update({"site": case_site, "loading": case_loading, "recovery": case_recovery, "wheel": case_wheel,
                  "limits": case_limits})


# ---- the published folder ----------------------------------------------------------------------
def case_site(browser, base, out):
    site = SETTINGS["site"]
    found = sorted(os.listdir(site))
    sizes = {name: os.path.getsize(os.path.join(site, name)) for name in found}
    packed = sum(len(gzip.compress(open(os.path.join(site, n), "rb").read(), 9)) for n in found)
    print(f"  {site}: {', '.join(f'{n} {sizes[n] / 1e6:.2f} MB' for n in found)}; "
          f"{sum(sizes.values()) / 1e6:.2f} MB, {packed / 1e6:.2f} MB gzipped")
    assert set(found) == SITE_FILES, f"the folder holds {sorted(set(found) - SITE_FILES)} beyond the page's files" \
        if set(found) >= SITE_FILES else f"the folder lacks {sorted(SITE_FILES - set(found))}"
    root = base.rsplit("/", 1)[0]
    for path in ("/CMakeCache.txt", "/apt/", "/third_party/", "/Makefile"):
        try:
            with urllib.request.urlopen(root + path, timeout=10) as answer:
                raise AssertionError(f"the server gives {path} (HTTP {answer.status})")
        except urllib.error.HTTPError as e:
            assert e.code == 404, f"{path}: HTTP {e.code}"
    with urllib.request.urlopen(root + "/", timeout=10) as answer:
        assert b"gbuffer-lab.js" in answer.read(), "/ is not the page"
    print("  /CMakeCache.txt, /apt/, /third_party/, /Makefile: 404; / is the page")
    return None


# ---- the loading line ----------------------------------------------------------------------------
def case_loading(browser, base, out):
    # The teacher's quick screenshot: whatever it catches must be the loading line or the editor
    # complete, never its first frame.
    shot = os.path.join(out, "quick-screenshot.png")
    profile = tempfile.mkdtemp(prefix="gbl-chromium-quick-")
    args = ["chromium", "--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
            f"--user-data-dir={profile}", f"--window-size={bt.WIDTH},{bt.HEIGHT}", f"--screenshot={shot}",
            "--hide-scrollbars", base]
    if os.getuid() == 0:
        args.append("--no-sandbox")
    try:
        subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120, check=False)
    finally:
        shutil.rmtree(profile, ignore_errors=True)
    assert os.path.isfile(shot), "chromium --screenshot wrote no file"
    image = bt.decode_png(open(shot, "rb").read())
    w, h, bpp, rows = image
    mean, spread, lit = bt.region_stats(image, (0, 0, w, h))
    background = sum(1 for y in range(0, h, 4) for x in range(0, w, 4)
                     if tuple(rows[y][x * bpp:x * bpp + 3]) == (32, 32, 32)) / ((h // 4) * (w // 4))
    print(f"  {shot}: {w}x{h}, mean luminance {mean:.3f}, {100 * background:.0f}% the page's background (#202020)")

    # In a page: the loading line covers the canvas until the editor says it is shown, after its
    # first complete frame; then it is gone.
    page = bt.Page(browser, base + "?log-frames=/dev/stdout")
    covered = lambda: page.cmd("Runtime.evaluate", {"expression": "!!document.getElementById('loading')",
                                                     "returnByValue": True})["result"].get("value")
    page.wait_for("the page's script", lambda: page.cmd("Runtime.evaluate", {
        "expression": "document.readyState", "returnByValue": True})["result"].get("value") != "loading", 30)
    early = covered()
    shown = lambda: [c for c in page.console if "the editor is shown at frame" in c]
    page.wait_for("the editor to be shown", shown, 120)
    at = int(shown()[0].split("at frame ")[1].split(",")[0])
    first = next(f["frame"] for f in page.frames if f.get("rendered"))
    page.wait_frames(2)
    print(f"  loading line at the start: {early}; the scene first rendered at frame {first}; "
          f"\"{shown()[0].split(': ', 1)[-1]}\"; loading line afterwards: {covered()}")
    page.screenshot(os.path.join(out, "loading-shown.png"))
    assert early, "the canvas is not covered while the editor loads"
    assert at >= first + 3, "the editor was shown before its first complete frame"
    assert not covered(), "the loading line is still there after the editor was shown"
    # The quick screenshot is the loading line (the page's background, bar a line of text) or a
    # complete editor, whose windows cover most of the page with other colours.
    assert background > 0.97 or background < 0.5, "the quick screenshot is neither the loading line nor the editor"
    return page


# ---- unsaved changes over reloads ------------------------------------------------------------------
def case_recovery(browser, base, out):
    page = bt.Page(browser, base + "?log-frames=/dev/stdout", (1600, 900))
    page.wait_for("a rendered frame", lambda: any(f.get("rendered") for f in page.frames), 120)
    offered = lambda since: [c for c in page.console[since:]
                             if "unsaved changes from" in c and not c.startswith('log: {"frame"')]

    def reload():
        page.cmd("Page.reload")
        page.frames.clear()
        page.wait_for("frames after the reload", lambda: len(page.frames) > 5, 120)

    # A page has no clean exit: two reloads with no input in between offer nothing. 8 s each: the
    # autosave would come 3 s after a change, and the page writes its storage every 2 s.
    for n in (1, 2):
        page.pump(8.0)
        since = len(page.console)
        reload()
        page.pump(2.0)
        assert not offered(since), f"reload {n} with no input offers: {offered(since)}"
    page.screenshot(os.path.join(out, "recovery-no-offer.png"))
    print("  two reloads with no input: no offer")

    kq = page.scroll_lights_until("the Kq field", lambda f: f["kqField"][2] > 0, 100.0)["kqField"]
    y = kq[1] + kq[3] / 2
    page.drag(kq[0] + kq[2] / 2, y, kq[0] + kq[2] / 2 + 80, y)
    page.pump(8.0)
    since = len(page.console)
    reload()
    page.wait_for("the offer after the reload", lambda: offered(since), 60)
    line = offered(since)[0]
    print("  an edit, then a reload: " + line)
    page.wait_frames(3)
    page.screenshot(os.path.join(out, "recovery.png"))
    assert "your unsaved changes from a moment ago" in line, "the offer does not say it in words"
    said = " ".join(c for c in page.console[since:] if not c.startswith('log: {"frame"'))
    for wrong in ("did not exit cleanly", "/home/web_user", "crash"):
        assert wrong not in said, f"the page says {wrong!r}"
    return page


# ---- the wheel ---------------------------------------------------------------------------------------
def native_wheel():
    if not SETTINGS["native"]:
        return NATIVE_WHEEL, "as recorded"
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "native_wheel.sh")
    work = tempfile.mkdtemp(prefix="gbl-native-wheel-")
    try:
        run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x800x24", script, SETTINGS["native"], work],
                             capture_output=True, text=True, timeout=300)
        assert run.returncode == 0, f"native_wheel.sh failed: {run.stdout[-500:]} {run.stderr[-500:]}"
        return json.loads(run.stdout.strip().splitlines()[-1]), "measured now"
    finally:
        shutil.rmtree(work, ignore_errors=True)


def row_shift(rows0, rows1):
    """How far the course's rows moved up: the y change of the rows wholly in view before and after."""
    shifts = [rows0[i + 1] - rows1[i + 1] for i in range(0, len(rows0), 4)
              if rows0[i + 3] > 0 and i < len(rows1) and rows1[i + 3] > 0]
    assert shifts, "no course row stayed in view"
    return shifts[0]


def case_wheel(browser, base, out):
    native, how = native_wheel()
    if not native:
        raise bt.Skip("no native reference: give --native build/gbuffer-lab (needs xvfb-run and xdotool)")
    step = [b - a for a, b in zip(native["camera0"], native["camera1"])]
    native_shift = row_shift(native["rows0"], native["rows1"])
    print(f"  desktop ({how}): one notch up moves the camera {native['camera0']} by "
          f"[{', '.join(f'{v:.4f}' for v in step)}]; one notch down scrolls the course {native_shift:.1f} px")
    # One notch in each of the browser's units; lines and pages come as a WheelEvent with that deltaMode
    # (the DevTools protocol's wheel has pixels only).
    for unit, mode, notch in (("pixels", 0, 100.0), ("lines", 1, 3.0), ("pages", 2, 1.0)):
        page = bt.Page(browser, base + "?log-frames=/dev/stdout")
        page.wait_for("a rendered frame", lambda: any(f.get("rendered") for f in page.frames), 120)
        view = page.wait_frames(3)["viewport"]

        def wheel(x, y, delta):
            if mode == 0:
                return page.wheel(x, y, delta)
            page.mouse("mouseMoved", x, y)
            page.pump(0.1)
            page.cmd("Runtime.evaluate", {"expression": f"document.getElementById('canvas').dispatchEvent(new WheelEvent("
                                                        f"'wheel', {{deltaY: {delta}, deltaMode: {mode}, clientX: {x}, "
                                                        f"clientY: {y}, bubbles: true, cancelable: true}}))"})

        x, y = view[0] + view[2] / 2, view[1] + view[3] / 2
        page.mouse("mouseMoved", x, y)
        camera0 = page.wait_frames(3)["camera"]
        first = len(page.frames)
        wheel(x, y, -notch)
        page.wait_for("the camera to move", lambda: page.frames[-1]["camera"] != camera0, 30)
        camera1 = page.wait_frames(3)["camera"]
        scrolls = [e for f in page.frames[first:] for e in f["events"] if e.startswith("scroll")]
        moved = [b - a for a, b in zip(camera0, camera1)]
        print(f"  {unit}: deltaY {-notch:g} -> {scrolls}; the camera {camera0} moved by "
              f"[{', '.join(f'{v:.4f}' for v in moved)}]")
        assert scrolls == [native["scroll"]], f"one notch up in {unit} is {scrolls}, the desktop's {native['scroll']}"
        # The same home view and the same dolly (0.85 of the distance per notch): within 1 mm.
        for a, b in zip(camera0, native["camera0"]):
            assert abs(a - b) < 1e-3, f"the camera starts at {camera0}, the desktop's at {native['camera0']}"
        for a, b in zip(moved, step):
            assert abs(a - b) < 1e-3, f"the notch moved the camera by {moved}, the desktop's by {step}"

        rows0 = page.frames[-1]["courseRows"]
        row = next(i for i in range(0, len(rows0), 4) if rows0[i + 3] > 0)
        x, y = rows0[row] + rows0[row + 2] / 2, rows0[row + 1] + rows0[row + 3] / 2
        page.mouse("mouseMoved", x, y)
        rows0 = page.wait_frames(3)["courseRows"]
        wheel(x, y, notch)
        page.wait_for("the course to scroll", lambda: page.frames[-1]["courseRows"] != rows0, 30)
        shift = row_shift(rows0, page.wait_frames(3)["courseRows"])
        print(f"  {unit}: deltaY {notch:g} over the course scrolls it {shift:.1f} px")
        page.screenshot(os.path.join(out, f"wheel-{unit}.png"))
        # ImGui scrolls a window by a multiple of the font's size per notch: the same pixels.
        assert abs(shift - native_shift) < 1.0, f"{unit}: the course scrolled {shift} px, the desktop's {native_shift}"
    return page


# ---- what the browser cannot run ---------------------------------------------------------------------
def case_limits(browser, base, out):
    page = bt.Page(browser, base + "?log-frames=/dev/stdout")
    page.wait_for("a rendered frame", lambda: any(f.get("rendered") for f in page.frames), 120)
    last = page.wait_frames(3)
    page.screenshot(os.path.join(out, "limits-course.png"))
    notes = last["courseNotes"]
    ids = [p.split(" ")[0] for p in last["courseProgress"].split("|")]
    print(f"  the menu bar's status: {last['status']!r}")
    assert "compute shaders" not in last["status"], "the menu bar shows the browser's limits, not the scene's line"
    assert last["status"].split("   ")[0].startswith("scene "), f"the menu bar does not show the scene's line"
    tiled = notes[ids.index("tiled")]
    print(f"  the course's note on the tiled lesson: {tiled!r}")
    assert "cannot run in this browser" in tiled and "compute shaders" in tiled, "the course does not say it"
    assert not notes[ids.index("attenuation")], "a lesson that runs has a note"
    print("  Help > About this browser lists: " + " | ".join(l[:60] for l in last["browserLimits"]))
    assert any("tiled mode is unavailable" in l for l in last["browserLimits"]), "the limits lack tiled mode"

    page = bt.Page(browser, base + "?log-frames=/dev/stdout&lesson=tiled:1")
    page.wait_for("the tiled lesson", lambda: page.frames and page.frames[-1].get("lesson") == "tiled:1", 120)
    last = page.wait_frames(5)
    page.screenshot(os.path.join(out, "limits-tiled-1.png"))
    print(f"  tiled:1 in mode {last['mode']}: {last['lessonNote']!r}")
    assert last["mode"] != "tiled", "the lesson switched to tiled mode, which cannot run here"
    assert "cannot run in this browser" in last["lessonNote"], "the step does not say it cannot run"
    nx, ny = last["lessonButtons"][4:6]
    page.click(nx, ny)
    page.wait_for("step 2", lambda: page.frames[-1].get("lesson") == "tiled:2", 30)
    last = page.wait_frames(3)
    page.screenshot(os.path.join(out, "limits-tiled-2.png"))
    print(f"  tiled:2 in mode {last['mode']}: note {'shown' if last['lessonNote'] else 'missing'}")
    assert last["mode"] != "tiled" and last["lessonNote"], "step 2 switched the mode or lost its note"
    return page
