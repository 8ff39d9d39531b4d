"""Log-log work-precision plot of the free-body integrators and rapier.

Reads the CSV written by the work-precision example (columns
``method,dt,steps,error_rad,ns_per_step``) and writes an SVG: x = run time
for the whole 100 s of one body (ns per body-step × steps, in µs), y =
attitude error at t = 100 s in rad, one line per method (points in order of
decreasing dt, each labelled with its steps per second), rapier3d-f64
included. SVG so that it diffs as text.

    cargo run --release --example free_body_work_precision -- --csv benches/work_precision.csv
    pip install matplotlib && python3 benches/plot_work_precision.py benches/work_precision.csv

Usage: ``python3 benches/plot_work_precision.py CSV [OUT.svg]`` (default
output: ``benches/work_precision.svg`` next to this script).
"""

import csv
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("svg")
import matplotlib.pyplot as plt  # noqa: E402

# Reproducible SVG: no timestamp or random ids in the output.
plt.rcParams["svg.hashsalt"] = "kreisel"
plt.rcParams["svg.fonttype"] = "none"


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    src = argv[1]
    out = (
        argv[2]
        if len(argv) > 2
        else os.path.join(os.path.dirname(os.path.abspath(__file__)), "work_precision.svg")
    )
    series = OrderedDict()
    with open(src, newline="") as f:
        for row in csv.DictReader(f):
            series.setdefault(row["method"], []).append(
                (
                    float(row["dt"]),
                    float(row["ns_per_step"]) * int(row["steps"]) * 1e-3,
                    float(row["error_rad"]),
                )
            )

    fig, ax = plt.subplots(figsize=(10, 6))
    # Distinct colours and markers for any number of methods (tab20 has 20).
    colours = plt.get_cmap("tab20").colors
    markers = "o^vsDP*Xhd<>p"
    kreisel_methods = [m for m in series if m != "rapier"]
    for method, points in series.items():
        points.sort(key=lambda p: -p[0])
        x = [p[1] for p in points]
        # A zero error (exact to the last bit) cannot go on a log axis.
        y = [max(p[2], 1e-17) for p in points]
        if method == "rapier":
            style = dict(marker="s", linestyle="--", color="black", linewidth=2)
            label = "rapier3d-f64 (1000 bodies)"
        else:
            i = kreisel_methods.index(method)
            style = dict(marker=markers[i % len(markers)], color=colours[(2 * i) % 20 + (i // 10) % 2])
            label = method
        (line,) = ax.plot(x, y, label=label, **style)
        for dt, xi, yi in zip([p[0] for p in points], x, y):
            ax.annotate(
                f"1/{round(1 / dt)}",
                (xi, yi),
                textcoords="offset points",
                xytext=(4, 3),
                fontsize=6,
                color=line.get_color(),
            )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("run time for 100 s of one body (µs) = ns per body-step × steps / 1000")
    ax.set_ylabel("attitude error at t = 100 s (rad)")
    ax.set_title("Free rigid body, rapier's scenario: I = (1, 2, 3), ω₀ = (0.01, 1, 0), 100 s")
    ax.grid(True, which="major", alpha=0.4)
    ax.grid(True, which="minor", alpha=0.1)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(out, metadata={"Date": None})
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv)
