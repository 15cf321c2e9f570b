#!/usr/bin/python3
"""Plots an asv_batch trajectory CSV (t_s,ship,x_m,y_m,course_deg,speed_mps) to a PNG.

usage: plot_trajectory.py TRAJECTORY.csv OUT.png [--title TEXT] [--own NAME] [--land LAND.txt]
       plot_trajectory.py --pairs CSV1 PNG1 [CSV2 PNG2 ...]   (many plots in one process; titles from the names)

Land (static obstacles and chart land) is drawn filled from LAND.txt, the local-frame text that
`asv_chart --scenario FILE --local LAND.txt` writes ('polygon N' then N lines 'x y'). With --pairs, a
CSV named SCENARIO__PLANNER__sS.csv takes SCENARIO.land.txt from its folder when there is one.

The own ship (default: the first ship in the file) is drawn thick in blue on top of everything; the
other ships (targets) thinner and partly transparent. Each track has its start marked by a circle and
its end by a triangle. Up to 12 ships are named in a legend; with more, each target's name is written
small at the end of its track (the own ship is always named).
Closest point of approach: for each target, on the time stamps it shares with the own ship, the
nearest positions of the two are marked (a cross on the target, a dot on the own ship) and joined by
a thin line, labelled 'D nm @ T s'; with more than 12 ships only the 5 closest are labelled.
Time ticks: a small dot every N s along every track, N in 60, 120, 300, 600, 900, 1800 s so that the
run has about 10 of them (N is given under the title); the own ship's dots are labelled in minutes.
"""
import argparse
import csv
import math
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

NM = 1852.0
TICK_STEPS = (60, 120, 300, 600, 900, 1800)
LEGEND_MAX_SHIPS = 12   # more ships than this: names at the track ends instead of a legend
CPA_LABELS_MANY = 5     # more ships than LEGEND_MAX_SHIPS: only this many closest approaches labelled
OWN_COLOUR = "tab:blue"


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


def read_ships(csv_path):
    """{ship: {"t": [...], "x": [...], "y": [...]}} in the order the ships first appear."""
    ships = OrderedDict()
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            s = ships.setdefault(row["ship"], {"t": [], "x": [], "y": []})
            s["t"].append(float(row["t_s"]))
            s["x"].append(float(row["x_m"]))
            s["y"].append(float(row["y_m"]))
    return ships


def _time_key(t):
    # asv_batch writes every ship of a step with the same t_s text; rounding guards against float noise.
    return round(t, 3)


def closest_approach(own, target):
    """(distance_m, t_s, own_xy, target_xy) of the closest approach of `target` to `own`, both
    {"t": [...], "x": [...], "y": [...]}, over the time stamps both have; None when they share none.
    The earliest one wins a tie."""
    at = {}
    for t, x, y in zip(own["t"], own["x"], own["y"]):
        at.setdefault(_time_key(t), (x, y))
    best = None
    for t, x, y in zip(target["t"], target["x"], target["y"]):
        o = at.get(_time_key(t))
        if o is None:
            continue
        d = math.hypot(x - o[0], y - o[1])
        if best is None or d < best[0] or (d == best[0] and t < best[1]):
            best = (d, t, o, (x, y))
    return best


def tick_interval(duration_s):
    """The step of TICK_STEPS nearest (by ratio) to a tenth of the run, so that it has about 10 ticks."""
    want = max(duration_s, 1.0) / 10.0
    return min(TICK_STEPS, key=lambda n: abs(math.log(n / want)))


def ticks(ship, step):
    """[(t, x, y)] every `step` s (multiples of it) strictly after the ship's first time stamp and up to
    its last one, the positions interpolated linearly between rows."""
    if len(ship["t"]) < 2:
        return []
    t0, t1 = min(ship["t"]), max(ship["t"])
    order = np.argsort(ship["t"], kind="stable")
    ts = np.asarray(ship["t"])[order]
    xs = np.asarray(ship["x"])[order]
    ys = np.asarray(ship["y"])[order]
    k = math.floor(t0 / step) + 1
    out = []
    while k * step <= t1 + 1e-6:
        t = k * step
        out.append((t, float(np.interp(t, ts, xs)), float(np.interp(t, ts, ys))))
        k += 1
    return out


def cpa_label(d, t):
    return "%.2f nm @ %d s" % (d / NM, int(round(t)))


def target_colours(n):
    """n colours for the targets: tab20 without its blues (the own ship's), dark shades first."""
    tab20 = plt.get_cmap("tab20").colors
    dark = [c for i, c in enumerate(tab20[0::2]) if i != 0]
    light = [c for i, c in enumerate(tab20[1::2]) if i != 0]
    palette = dark + light
    return [palette[k % len(palette)] for k in range(n)]


def plot(csv_path, png, title, own, land_path=""):
    try:
        ships = read_ships(csv_path)
    except (OSError, KeyError, ValueError) as e:
        print(f"plot_trajectory: cannot read {csv_path}: {e}", file=sys.stderr)
        return 2
    if not ships:
        print(f"plot_trajectory: {csv_path} has no rows", file=sys.stderr)
        return 2
    if own and own not in ships:
        print(f"plot_trajectory: {csv_path} has no ship '{own}'; the own ship is the first one",
              file=sys.stderr)
        own = ""
    own = own or next(iter(ships))
    many = len(ships) > LEGEND_MAX_SHIPS
    targets = [name for name in ships if name != own]
    colour = dict(zip(targets, target_colours(len(targets))))
    colour[own] = OWN_COLOUR
    o = ships[own]
    all_t = [t for s in ships.values() for t in s["t"]]
    step = tick_interval(max(all_t) - min(all_t))

    fig, ax = plt.subplots(figsize=(9, 9) if many else (8, 8), dpi=100)
    for xs, ys in read_land(land_path) if land_path else []:
        ax.fill(xs, ys, color="#d9c9a0", ec="#8c7a50", lw=0.5, zorder=0)

    # Tracks: targets thin and translucent below, the own ship thick on top.
    own_ticks = []
    for name in targets + [own]:
        s, c, is_own = ships[name], colour[name], name == own
        z = 10 if is_own else 3
        alpha = 1.0 if is_own else 0.7
        ax.plot(s["x"], s["y"], color=c, lw=2.8 if is_own else 1.0, alpha=alpha, zorder=z,
                label=f"{name} (own)" if is_own else name)
        ax.plot(s["x"][0], s["y"][0], "o", color=c, ms=6 if is_own else 4, alpha=alpha, zorder=z)
        ax.plot(s["x"][-1], s["y"][-1], "^", color=c, ms=7 if is_own else 5, alpha=alpha, zorder=z)
        tk = ticks(s, step)
        if tk:
            ax.plot([p[1] for p in tk], [p[2] for p in tk], "o", ls="none", ms=4 if is_own else 2.5,
                    color="white" if is_own else c, mec=c, mew=1.2 if is_own else 0, alpha=alpha, zorder=z + 0.5)
        if is_own:
            own_ticks = tk

    # Closest points of approach: a cross on the target, a dot on the own ship, a thin line between.
    cpas = []
    for name in targets:
        r = closest_approach(o, ships[name])
        if r is not None:
            cpas.append((r, name))
    cpas.sort(key=lambda rn: rn[0][0])
    for (d, t, oxy, txy), name in cpas:
        c = colour[name]
        ax.plot([oxy[0], txy[0]], [oxy[1], txy[1]], "-", color=c, lw=0.7, alpha=0.8, zorder=6)
        ax.plot(*txy, "X", color=c, mec="black", mew=0.4, ms=6, zorder=7)
        ax.plot(*oxy, "o", color=c, mec=OWN_COLOUR, mew=0.8, ms=4, zorder=11)

    ax.set_aspect("equal", adjustable="datalim")
    ax.margins(0.06)
    ax.set_xlabel("x east [m]")
    ax.set_ylabel("y north [m]")
    ax.grid(True, lw=0.3)
    if not many:
        ax.legend(loc="best", fontsize=8, framealpha=0.85)
    note = "time dots every %g min (the own ship's labelled); X = closest approach to %s%s" % (
        step / 60.0, own, ", the 5 closest labelled" if many and len(cpas) > CPA_LABELS_MANY else "")
    ax.set_title((title or csv_path) + "\n" + note, fontsize=9)
    fig.tight_layout()

    # Text last, once the axes are laid out, each label where it overlaps no other.
    labels = Labels(fig, ax)
    if many:
        s = ships[own]
        labels.add(own, (s["x"][-1], s["y"][-1]), OWN_COLOUR, fontsize=8.5, fontweight="bold")
    for (d, t, _, txy), name in cpas[:CPA_LABELS_MANY] if many else cpas:
        labels.add(cpa_label(d, t), txy, darker(colour[name]), fontsize=7, edge=colour[name])
    if many:
        for name in targets:
            s = ships[name]
            labels.add(name, (s["x"][-1], s["y"][-1]), darker(colour[name]), fontsize=6.5)
    for t, x, y in own_ticks:
        labels.add("%g min" % (t / 60.0), (x, y), OWN_COLOUR, fontsize=7, required=False)
    fig.savefig(png)
    plt.close(fig)
    return 0


def darker(c, f=0.6):
    """The colour c darkened (text on white stays legible for the light shades)."""
    r, g, b = matplotlib.colors.to_rgb(c)
    return (r * f, g * f, b * f)


class Labels:
    """Small text labels at points, each put at the first of a few offsets where it overlaps no label
    placed before, nor the legend, and stays inside the axes (the farther offsets with a leader line);
    a required label that fits nowhere goes where it overlaps least, an optional one is left out."""
    NEAR = ((5, 3), (5, -3), (-5, 3), (-5, -3), (0, 8), (0, -8), (10, 12), (10, -12), (-10, 12), (-10, -12))
    # Farther out, with a leader line to the point: 8 directions at 25 and 45 points.
    FAR = tuple((round(r * math.cos(math.radians(a))), round(r * math.sin(math.radians(a))))
                for r in (25, 45) for a in range(30, 360, 45))

    def __init__(self, fig, ax):
        self.ax = ax
        fig.canvas.draw()  # fixes the axes limits (equal aspect) and the legend's place
        self.renderer = fig.canvas.get_renderer()
        self.frame = ax.get_window_extent(self.renderer)
        legend = ax.get_legend()
        self.placed = [legend.get_window_extent(self.renderer)] if legend else []

    def add(self, text, xy, colour, fontsize, fontweight="normal", edge="none", required=True):
        best = None
        for dx, dy in self.NEAR + (self.FAR if required else ()):
            far = abs(dx) + abs(dy) > 24
            leader = dict(arrowstyle="-", color=colour, lw=0.5, shrinkA=0, shrinkB=2) if far else None
            a = self.ax.annotate(
                text, xy, xytext=(dx, dy), textcoords="offset points", fontsize=fontsize, color=colour,
                fontweight=fontweight, zorder=13, annotation_clip=False, arrowprops=leader,
                ha="left" if dx > 0 else "right" if dx < 0 else "center", va="bottom" if dy >= 0 else "top",
                bbox=dict(boxstyle="round,pad=0.15", fc="white", ec=edge, lw=0.5, alpha=0.8))
            a.update_positions(self.renderer)
            bb = matplotlib.text.Text.get_window_extent(a, self.renderer).expanded(1.05, 1.1)  # without the leader
            inside = self.frame.containsx(bb.x0) and self.frame.containsx(bb.x1) and \
                self.frame.containsy(bb.y0) and self.frame.containsy(bb.y1)
            cost = sum(bb.overlaps(p) for p in self.placed) + (0 if inside else 100)
            if cost == 0:
                self.placed.append(bb)
                if best:
                    best[1].remove()
                return
            if best is None or cost < best[0]:
                if best:
                    best[1].remove()
                best = (cost, a, bb)
            else:
                a.remove()
        if required:
            self.placed.append(best[2])
        else:
            best[1].remove()


if __name__ == "__main__":
    sys.exit(main())
