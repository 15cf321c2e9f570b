"""Lazarowska (2015), Sec. 3: Scenario 1 (Table 3) and Scenario 2 (Table 4), closed loop through asv_batch,
in paper mode and in sea mode, and the repeatability claim over independent seeds.

The paper reports, for each scenario, the own ship's successive courses (Sec. 3.1: 066 -> 077 -> 052;
Sec. 3.2: 061 -> 050 -> 079 -> 061) and that 100 repetitions gave identical results. It gives no times
for the alterations (its Fig. 10 and 13 are lost), so the times are ours only.
"""
from collections import Counter

from .common import Job, band_row, count_row, exact_row, manoeuvre_courses, rows_table, side

PAPER = "Lazarowska 2015"
# Scenario file, the paper's label, own initial course, the paper's alterations (+ starboard, deg).
SITUATIONS = [("lazarowska_1", "Scenario 1 (Table 3)", 66.0, [11.0, -25.0]),
              ("lazarowska_2", "Scenario 2 (Table 4)", 61.0, [-11.0, 29.0, -18.0])]
REPEAT_SEEDS = 100
# Band on an alteration: half the smallest angle between two lattice legs (14.0 deg, aco.md), so that a
# neighbouring lattice leg is outside.
ANGLE_BAND = 7.0
_STAIRCASE = ("paper mode sails the colony's best lattice path as found; on our construction graph (the paper's "
              "Fig. 6 is lost: rows 0.5 nm apart, legs 0, +-14, +-27, +-37 deg off the base line) that path is a "
              "staircase of short legs, where the paper's answer has two or three. Sea mode's waypoint reduction "
              "(smooth) is what turns the staircase into a few alterations")
_REPEAT = ("20 iterations of 10 ants (the paper's) cannot converge on our lattice: each seed's colony keeps a "
           "different best walk among very many of nearly equal length. The paper's identical repetitions "
           "imply a much smaller graph or a deterministic tie-break; the same seed repeats byte for byte here")
REASONS = {
    "Scenario 1 (Table 3)": _STAIRCASE,
    "Scenario 2 (Table 4)": _STAIRCASE + "; the first leg of ours goes to starboard of the paper's port one",
    ("Scenario 1 (Table 3)", "runs on one route of %d independent seeds" % REPEAT_SEEDS): _REPEAT,
    ("Scenario 2 (Table 4)", "runs on one route of %d independent seeds" % REPEAT_SEEDS): _REPEAT,
}


def jobs():
    out = []
    for scenario, _, _, _ in SITUATIONS:
        for mode in ("paper", "sea"):
            # Paper mode plans once, as the paper (AcoPlanner::plansOnce): no --follower key needed.
            out.append(Job("aco_%s_%s" % (scenario, mode), scenario, "aco", sets=["aco.mode=" + mode]))
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
    lines += ["### Manoeuvres, closed loop (seed 1)", "",
              "Courses in order, each with its alteration (+ starboard) and the time it was ordered.", "",
              "| | mode | courses | closest approach | path ratio | COLREGs score |", "|---|---|---|---:|---:|---:|"]
    for scenario, label, initial, paper in SITUATIONS:
        for mode in ("paper", "sea"):
            r = done["aco_%s_%s" % (scenario, mode)].runs[0]
            lines.append("| %s | %s | %s | %.0f m | %s | %.2f |" % (
                label, mode, courses_text(initial, r), r["min_separation_m"],
                "%.3f" % r["path_ratio"] if r["path_ratio"] is not None else "not arrived", r["colregs_score"]))
        paper_courses = manoeuvre_courses(initial, [{"course_change_deg": a} for a in paper])
        lines.append("| %s | the paper | %s | not given | not given | - |" % (
            label, " -> ".join(["%03.0f" % initial] + ["%03.0f (%+.0f)" % (c, a) for c, a in zip(paper_courses, paper)])))
        r = done["aco_%s_paper" % scenario].runs[0]
        ours = [m["course_change_deg"] for m in r["manoeuvres"]]
        rows.append(exact_row(PAPER, label, "number of alterations", len(paper), len(ours)))
        for k, a in enumerate(paper):
            o = ours[k] if k < len(ours) else None
            rows.append(exact_row(PAPER, label, "alteration %d side" % (k + 1), side(a), side(o) if o is not None else None))
            rows.append(band_row(PAPER, label, "alteration %d [deg, + starboard]" % (k + 1), a, o, ANGLE_BAND, "deg"))
        # Hull contact, not the hexagon entry the paper's claim is about: our check, not its number.
        rows.append(exact_row(PAPER, label, "closest approach outside the hexagon domain (no collision)", True,
                              not r["collision"], kind="self_check"))
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
