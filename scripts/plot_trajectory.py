#!/usr/bin/python3
"""Plots an asv_batch trajectory CSV (t_s,ship,x_m,y_m,course_deg,speed_mps) to a PNG.

usage: plot_trajectory.py TRAJECTORY.csv OUT.png [--title TEXT] [--own NAME] [--land LAND.txt]
       plot_trajectory.py --pairs CSV1 PNG1 [CSV2 PNG2 ...]   (many plots in one process; titles from the names)

Land (static obstacles and chart land) is drawn filled from LAND.txt, the local-frame text that
`asv_chart --scenario FILE --local LAND.txt` writes ('polygon N' then N lines 'x y'). With --pairs, a
CSV named SCENARIO__PLANNER__sS.csv takes SCENARIO.land.txt from its folder when there is one.

The own ship (default: the first ship in the file) is drawn thick in blue, other ships thin, each with
its start marked by a circle and its end by a triangle; positions every 120 s are joined by dotted
lines between the own ship and each other ship so that the passing distances can be read.
"""
import argparse
import csv
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--pairs":
        pairs = sys.argv[2:]
        if len(pairs) % 2:
            print("plot_trajectory: --pairs needs CSV PNG pairs", file=sys.stderr)
            return 2
        rc = 0
        for k in range(0, len(pairs), 2):
            title = pairs[k].rsplit("/", 1)[-1][:-4].replace("__", " / ")
            folder, _, base = pairs[k].rpartition("/")
            land = (folder + "/" if folder else "") + base.split("__")[0] + ".land.txt"
            rc = max(rc, plot(pairs[k], pairs[k + 1], title, "", land))
        return rc
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("png")
    ap.add_argument("--title", default="")
    ap.add_argument("--own", default="")
    ap.add_argument("--land", default="")
    a = ap.parse_args()
    return plot(a.csv, a.png, a.title, a.own, a.land)


def read_land(path):
    """Polygons [(xs, ys)] of an asv_chart --local file; none when it is absent or empty."""
    polys = []
    try:
        with open(path) as f:
            for line in f:
                w = line.split()
                if w and w[0] == "polygon":
                    polys.append(([], []))
                elif len(w) == 2 and polys:
                    polys[-1][0].append(float(w[0]))
                    polys[-1][1].append(float(w[1]))
    except OSError:
        return []
    return polys


def plot(csv_path, png, title, own, land_path=""):
    ships = OrderedDict()
    try:
        with open(csv_path, newline="") as f:
            for row in csv.DictReader(f):
                s = ships.setdefault(row["ship"], {"t": [], "x": [], "y": []})
                s["t"].append(float(row["t_s"]))
                s["x"].append(float(row["x_m"]))
                s["y"].append(float(row["y_m"]))
    except (OSError, KeyError, ValueError) as e:
        print(f"plot_trajectory: cannot read {csv_path}: {e}", file=sys.stderr)
        return 2
    if not ships:
        print(f"plot_trajectory: {csv_path} has no rows", file=sys.stderr)
        return 2
    own = own or next(iter(ships))
    fig, ax = plt.subplots(figsize=(7, 7), dpi=100)
    for xs, ys in read_land(land_path) if land_path else []:
        ax.fill(xs, ys, color="#d9c9a0", ec="#8c7a50", lw=0.5, zorder=0)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, (name, s) in enumerate(ships.items()):
        is_own = name == own
        c = "tab:blue" if is_own else colours[(k + 1) % len(colours)]
        ax.plot(s["x"], s["y"], color=c, lw=2.5 if is_own else 1.2, label=name)
        ax.plot(s["x"][0], s["y"][0], "o", color=c, ms=5)
        ax.plot(s["x"][-1], s["y"][-1], "^", color=c, ms=6)
    if own in ships:
        o = ships[own]
        index = {t: i for i, t in enumerate(o["t"])}
        for name, s in ships.items():
            if name == own:
                continue
            for t, x, y in zip(s["t"], s["x"], s["y"]):
                i = index.get(t)
                if i is not None and int(round(t)) % 120 == 0:
                    ax.plot([o["x"][i], x], [o["y"][i], y], ":", color="grey", lw=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x east [m]")
    ax.set_ylabel("y north [m]")
    ax.grid(True, lw=0.3)
    if len(ships) <= 12:
        ax.legend(loc="best", fontsize=8)
    ax.set_title(title or csv_path, fontsize=9)
    fig.tight_layout()
    fig.savefig(png)
    plt.close(fig)
    return 0


if __name__ == "__main__":
    sys.exit(main())
