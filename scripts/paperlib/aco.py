"""Lazarowska (2015), Sec. 3: Scenario 1 (Table 3) and Scenario 2 (Table 4), closed loop through asv_batch,
in paper mode and in sea mode, and the repeatability claim over independent seeds.

The paper reports, for each scenario, the own ship's successive courses (Sec. 3.1: 066 -> 077 -> 052;
Sec. 3.2: 061 -> 050 -> 079 -> 061), that the trajectory avoids every target "maintaining a safe
distance" (outside every hexagon) and that 100 repetitions gave identical results. It gives no times for
the alterations (its Fig. 10 and 13 are lost), so the times are ours only. The courses compared are the
plan's (the planner's own account, to the degree as the paper prints them); the hexagon is checked here,
independently of the planner's code, on the sailed track.
"""
import math
import re
from collections import Counter

from .common import Job, band_row, count_row, exact_row, manoeuvre_courses, side

PAPER = "Lazarowska 2015"
# Scenario file, the paper's label, own initial course, the paper's alterations (+ starboard, deg).
SITUATIONS = [("lazarowska_1", "Scenario 1 (Table 3)", 66.0, [11.0, -25.0]),
              ("lazarowska_2", "Scenario 2 (Table 4)", 61.0, [-11.0, 29.0, -18.0])]
REPEAT_SEEDS = 100
# The paper-mode grid's cell is wp_e / 9 because Scenario 1's answer, cells (5, 1) and (9, 0), ends 9
# cells out (AcoConfig::long_edges): that scenario's planned courses are fitted to, so its rows are
# calibration. Scenario 2's answer, (5, -1), (8, 0), (9, 0), was not used and lands on the same grid.
FITTED_TO = ("lazarowska_1",)
# Band on a planned alteration: the paper prints whole degrees (a difference of two rounded courses is
# within 1 deg) and neighbouring grid legs there are 2.7 deg apart (atan(1/4) - atan(1/5)): half of that.
ANGLE_BAND = 1.3
# The paper's hexagon (Sec. 3) [m]: bow a, "amidships" b (how far ahead of the beam the full width is
# kept), starboard c, stern d, port e, with our vertex layout (src/include/asv_core/risk/domain.h) in the
# target's frame (forward, starboard), counter-clockwise seen from above.
NM = 1852.0
HEXAGON = {"a": 1.0 * NM, "b": 0.6 * NM, "c": 0.6 * NM, "d": 0.25 * NM, "e": 0.25 * NM}
_S2_SHORTER = ("the shortest path on our grid goes from the end of the paper's first leg straight to wp_e (cells "
               "(5, -1), (9, 0): 049, 075); the paper's return to 061 first, (5, -1), (8, 0), (9, 0), is 54 m "
               "longer (0.75 nm x (sqrt 10 + 1 - sqrt 17)), and that direct leg enters no hexagon here "
               "(test_aco_planner, LazarowskaScenarios), so eq. (9) cannot prefer the paper's: its graph or targets "
               "must block the leg in a way the text does not give")


_REPEAT = ("20 iterations of 10 ants (the paper's) do not always find the shortest grid path: its mirror image "
           "(the two legs' cells swapped, e.g. (4, 1), (9, 0) for (5, 1), (9, 0)) is as long but for the turn "
           "model's first leg (metres), and 200 walks do not always meet both. The paper's identical repetitions "
           "imply a search that always does, or a deterministic tie-break the text does not give; the same seed "
           "repeats byte for byte here")
REASONS = {
    "Scenario 2 (Table 4)": _S2_SHORTER,
    ("Scenario 2 (Table 4)", "alteration 1 [deg, + starboard] (planned)"):
        "a tie: the mirror image of the shortest grid path (the two legs' cells swapped, (4, -1), (9, 0) for "
        "(5, -1), (9, 0)) is as long but for the turn model's first leg (metres), and seed 1's colony found it and "
        "not the shortest; the commonest route of the seeds below is the shortest, 049, 075. Either way, "
        + _S2_SHORTER,
    ("Scenario 1 (Table 3)", "runs on one route of %d independent seeds" % REPEAT_SEEDS): _REPEAT,
    ("Scenario 2 (Table 4)", "runs on one route of %d independent seeds" % REPEAT_SEEDS): _REPEAT,
}


def hexagon_gauge(own, target):
    """How deep the own ship is in the target's hexagon: the scale k of the hexagon (about the target) whose
    edge she is on; k < 1 is inside. own, target: trajectory rows (x_m, y_m; target course_deg)."""
    c = math.radians(float(target["course_deg"]))
    dx, dy = float(own["x_m"]) - float(target["x_m"]), float(own["y_m"]) - float(target["y_m"])
    f = dx * math.sin(c) + dy * math.cos(c)  # forward
    s = dx * math.cos(c) - dy * math.sin(c)  # starboard
    h = HEXAGON
    verts = [(h["a"], 0.0), (h["b"], -h["e"]), (0.0, -h["e"]), (-h["d"], 0.0), (0.0, h["c"]), (h["b"], h["c"])]
    k = 0.0
    for (f1, s1), (f2, s2) in zip(verts, verts[1:] + verts[:1]):
        # Edge line through two vertices; the gauge of (f, s) against it is n.p / n.v1 with n its normal.
        nf, ns = s2 - s1, f1 - f2
        den = nf * f1 + ns * s1
        k = max(k, (nf * f + ns * s) / den)
    return k


def deepest_in_hexagon(trajectory, own_name="own"):
    """The smallest hexagon gauge of the own ship against any target over the sailed track."""
    by_time = {}
    for r in trajectory:
        by_time.setdefault(r["t_s"], {})[r["ship"]] = r
    if not any(own_name in ships for ships in by_time.values()):
        raise RuntimeError("no track of the own ship '%s' in the trajectory" % own_name)
    best = math.inf
    for ships in by_time.values():
        if own_name not in ships:
            continue
        for name, r in ships.items():
            if name != own_name:
                best = min(best, hexagon_gauge(ships[own_name], r))
    return best


def planned_courses(plans):
    """The first plan's courses [deg] from its message (\"courses 066 077 052 deg\")."""
    if not plans:
        raise RuntimeError("the paper-mode run made no plan")
    m = re.search(r"courses ([0-9 ]+) deg", plans[0]["message"])
    return [float(c) for c in m.group(1).split()] if m else []


def alterations(courses):
    return [(b - a + 180.0) % 360.0 - 180.0 for a, b in zip(courses, courses[1:])]


def jobs():
    out = []
    for scenario, _, _, _ in SITUATIONS:
        for mode in ("paper", "sea"):
            # Paper mode plans once, as the paper (AcoPlanner::plansOnce): no --follower key needed.
            out.append(Job("aco_%s_%s" % (scenario, mode), scenario, "aco", sets=["aco.mode=" + mode], plans=True,
                           trajectory=True, sample=1.0))
        out.append(Job("aco_%s_repeat" % scenario, scenario, "aco", seeds=REPEAT_SEEDS, sets=["aco.mode=paper"]))
    return out


def signature(run):
    """A route as the paper compares them: each alteration's size to the degree and time to the minute."""
    return tuple((round(m["course_change_deg"]), round(m["t_s"] / 60.0)) for m in run["manoeuvres"])


def courses_text(initial, run):
    legs = ["%03.0f" % initial] + ["%03.0f (%+.0f, %.1f min)" % (c, m["course_change_deg"], m["t_s"] / 60.0)
                                   for c, m in zip(manoeuvre_courses(initial, run["manoeuvres"]), run["manoeuvres"])]
    return " -> ".join(legs)


def report(done):
    rows, lines = [], []
    lines += ["### Manoeuvres (seed 1)", "",
              "Planned: the courses of the plan as the planner prints them. Sailed: the closed loop's courses in "
              "order, each with its alteration (+ starboard) and the time it was ordered. Deepest in a hexagon: the "
              "smallest scale of any target's hexagon (about the target) that the sailed track touches, sampled "
              "every second; below 1 the hexagon was entered.", "",
              "| | mode | planned | sailed | closest approach | deepest in a hexagon | path ratio | COLREGs score |",
              "|---|---|---|---|---:|---:|---:|---:|"]
    for scenario, label, initial, paper in SITUATIONS:
        for mode in ("paper", "sea"):
            job = done["aco_%s_%s" % (scenario, mode)]
            r = job.runs[0]
            # Paper mode plans once; sea mode replans, so its first plan is not the route sailed.
            planned = (" -> ".join("%03.0f" % c for c in planned_courses(job.extra["plans"])) if mode == "paper"
                       else "%d plans" % len(job.extra["plans"]))
            lines.append("| %s | %s | %s | %s | %.0f m | %.2f | %s | %.2f |" % (
                label, mode, planned,
                courses_text(initial, r), r["min_separation_m"], deepest_in_hexagon(job.extra["trajectory"]),
                "%.3f" % r["path_ratio"] if r["path_ratio"] is not None else "not arrived", r["colregs_score"]))
        paper_courses = manoeuvre_courses(initial, [{"course_change_deg": a} for a in paper])
        lines.append("| %s | the paper | %s | - | not given | not given | not given | - |" % (
            label, " -> ".join(["%03.0f" % initial] + ["%03.0f (%+.0f)" % (c, a) for c, a in zip(paper_courses, paper)])))
        job = done["aco_%s_paper" % scenario]
        ours = alterations(planned_courses(job.extra["plans"]))
        kind = "calibration" if scenario in FITTED_TO else "reproduced"
        rows.append(exact_row(PAPER, label, "number of alterations (planned)", len(paper), len(ours), kind))
        for k, a in enumerate(paper):
            o = ours[k] if k < len(ours) else None
            rows.append(exact_row(PAPER, label, "alteration %d side (planned)" % (k + 1), side(a),
                                  side(o) if o is not None else None, kind))
            rows.append(band_row(PAPER, label, "alteration %d [deg, + starboard] (planned)" % (k + 1), a, o,
                                 ANGLE_BAND, "deg", kind=kind))
        rows.append(exact_row(PAPER, label, "no hexagon entered, sailed (Sec. 3: \"maintaining a safe distance\")",
                              True, deepest_in_hexagon(job.extra["trajectory"]) >= 1.0))
    lines += ["", "### Repeatability over independent seeds (paper mode)", "",
              "The paper ran each scenario 100 times and got the same answer every time. Here seeds 1..%d, each "
              "a different random colony; a route is the list of alterations to the degree and their times to "
              "the minute." % REPEAT_SEEDS, "",
              "| | runs | distinct routes | runs on the commonest route | runs on seed 1's route | collisions |",
              "|---|---:|---:|---:|---:|---:|"]
    for scenario, label, _, _ in SITUATIONS:
        runs = done["aco_%s_repeat" % scenario].runs
        sigs = Counter(signature(r) for r in runs)
        same = sigs[signature(runs[0])]
        lines.append("| %s | %d | %d | %d | %d | %d |" % (label, len(runs), len(sigs), sigs.most_common(1)[0][1],
                                                           same, sum(r["collision"] for r in runs)))
        rows.append(count_row(PAPER, label, "runs on one route of %d independent seeds" % len(runs),
                              100, 100, sigs.most_common(1)[0][1], len(runs)))
    return rows, lines
