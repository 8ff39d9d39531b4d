"""Log-log work-precision plot of the nonsmooth table (issue 26).

Reads the CSV written by the table's work-precision example (columns
``problem,rtol,evaluations,error,time_error_s,wall_ms``) and writes an SVG:
x = evaluations of the vector field, y = the error against the run at
rtol 1e-13 (the ball: its first 20 impact times against the closed form),
one solid line per problem, points labelled with their rtol; dashed, the
error of the event time each problem has (the ball's accumulation point,
the tippe top's stem landing). SVG so that it diffs as text.

    cargo run --release --example table_work_precision -- --csv benches/table_work_precision.csv
    pip install matplotlib && python3 benches/plot_table_work_precision.py benches/table_work_precision.csv

Usage: ``python3 benches/plot_table_work_precision.py CSV [OUT.svg]``
(default output: ``benches/table_work_precision.svg`` next to this script).
"""

import csv
import math
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("svg")
import matplotlib.pyplot as plt  # noqa: E402

# Reproducible SVG: no timestamp or random ids in the output.
plt.rcParams["svg.hashsalt"] = "kreisel"
plt.rcParams["svg.fonttype"] = "none"

LABELS = {
    "ball": "ball dropped, e = 0.9: impact times (s)",
    "tippe_top_one_contact": "tippe top, ball slipping: state at 1.2 s",
    "tippe_top_through_impact": "tippe top through the stem's landing: state at 2.0 s",
    "euler_disk": "Euler's disk rolling: sin α at 4 s",
}
TIME_LABELS = {
    "ball": "ball: accumulation point (s)",
    "tippe_top_through_impact": "tippe top: stem landing time (s)",
}


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    src = argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    out = argv[2] if len(argv) > 2 else os.path.join(here, "table_work_precision.svg")
    series = OrderedDict()
    with open(src, newline="") as f:
        for row in csv.DictReader(f):
            series.setdefault(row["problem"], []).append(
                (
                    float(row["rtol"]),
                    int(row["evaluations"]),
                    float(row["error"]),
                    float(row["time_error_s"]),
                )
            )
    fig, ax = plt.subplots(figsize=(10, 6))
    colours = plt.get_cmap("tab10").colors
    for i, (problem, points) in enumerate(series.items()):
        points.sort(key=lambda p: -p[0])
        x = [p[1] for p in points]
        # A zero error (exact to the last bit) cannot go on a log axis.
        y = [max(p[2], 1e-17) for p in points]
        colour = colours[i % len(colours)]
        ax.plot(x, y, marker="o", color=colour, label=LABELS.get(problem, problem))
        for rtol, xi, yi in zip([p[0] for p in points], x, y):
            ax.annotate(
                f"{rtol:.0e}",
                (xi, yi),
                textcoords="offset points",
                xytext=(4, 3),
                fontsize=6,
                color=colour,
            )
        times = [(p[1], p[3]) for p in points if not math.isnan(p[3])]
        if times and problem in TIME_LABELS:
            ax.plot(
                [t[0] for t in times],
                [max(t[1], 1e-17) for t in times],
                marker="x",
                linestyle="--",
                color=colour,
                label=TIME_LABELS[problem],
            )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("evaluations of the vector field")
    ax.set_ylabel("error against rtol = 1e-13 (or the closed form)")
    ax.set_title("Bodies on the table: work–precision (DP5(4) between events)")
    ax.grid(True, which="major", alpha=0.4)
    ax.grid(True, which="minor", alpha=0.1)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(out, metadata={"Date": None})
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv)
