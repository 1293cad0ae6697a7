#!/usr/bin/python3
"""Plots bench --json results: each mode's lighting time over the work floor against the light count."""
# Usage: scripts/plot_bench.py OUT.png BENCH.json [MORE.json ...]
# The work floor is lit pairs x quad's ns per evaluated pair (app/bench_command.h, pairCost);
# several JSON files (e.g. one per light-count range) are merged, later files winning.
import json
import sys

import matplotlib

matplotlib.use("Agg")  # headless: no display needed
import matplotlib.pyplot as plt  # noqa: E402


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip() + "\nusage: plot_bench.py OUT.png BENCH.json [MORE.json ...]", file=sys.stderr)
        return 2
    series = {}  # mode -> {lights: (vs floor, evaluated per lit)}
    title = ""
    combos = []
    for path in argv[2:]:
        with open(path) as f:
            data = json.load(f)
        title = f"{data['width']}x{data['height']}, {data['gl_renderer']}"
        combos += [c for c in data["combinations"] if c.get("pair_cost")]
    # quad's ns per pair by light count, from every file: a run without quad (large counts, where
    # bench refuses it) takes the nearest count's, as bench itself does within one run.
    quad = {c["lights"]: c["pair_cost"]["ns_per_evaluated_pair"] for c in combos if c["mode"] == "quad"}
    for c in combos:
        p = c["pair_cost"]
        if not quad or not c.get("light_pixel_pairs"):
            continue
        ns = quad[min(quad, key=lambda n: abs(n - c["lights"]))]
        floor_ms = c["light_pixel_pairs"] * ns * 1e-6
        mode = c["mode"] + ("/" + c["cull"] if "cull" in c else "")
        series.setdefault(mode, {})[c["lights"]] = (p["lighting_ms"] / floor_ms, p["evaluated_per_lit_pair"])
    if not series:
        print("plot_bench.py: no combination with a per-pair cost and a quad run to compare with", file=sys.stderr)
        return 1
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for mode, points in sorted(series.items()):
        xs = sorted(points)
        a.plot(xs, [points[x][0] for x in xs], marker="o", label=mode)
        b.plot(xs, [points[x][1] for x in xs], marker="o", label=mode)
    for ax, label in ((a, "lighting time / work floor"), (b, "evaluated / lit light-pixel pairs")):
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel("lights")
        ax.set_ylabel(label)
        ax.axhline(1.0, color="grey", lw=0.8, ls="--")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle("gbuffer-lab bench: " + title)
    fig.tight_layout()
    fig.savefig(argv[1], dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
