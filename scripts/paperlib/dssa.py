"""Hirayama et al. (2019), Sec. 5, Tables 1-3: DSSA and the three DSSA+ variants, every ship a DSSA agent
negotiating through asv_batch's in-process exchange, at the paper's trial counts (seeds 1..N).

Over the successful trials, as the paper does (Sec. 5.2): total length of paths, travel time of each
ship, detour rate of each ship; and the success rate. A trial succeeds when every ship arrives and no two
ships ever come closer than the collision distance (40, the scenarios' safety.min_separation_m).
"""
import math
import os
import shutil
import tempfile

import yaml

from . import common
from .common import Job, band_row, count_row

PAPER = "Hirayama et al. 2019"
SCENARIOS = [  # (scenario file, table title, trials in the paper, paper table key)
    ("dssa_two_ships", "Table 1: two ships pushing each other", 20, "two"),
    ("dssa_16_ships", "Table 2: 16 ships crossing each other", 50, "sixteen"),
    ("dssa_three_overtaking", "Table 3: three ships overtaking or being overtaken", 20, "three"),
]
VARIANTS = [("dssa", "DSSA"), ("dssa_plus_sc", "DSSA+ s>c"), ("dssa_plus_cs", "DSSA+ s<c"),
            ("dssa_plus_eq", "DSSA+ s=c")]
# Tables 1-3: total length of paths, travel time of each ship, detour rate of each ship, successes.
TABLES = {
    "two": {"dssa": (1150.0, 23.0, 1.17, 20), "dssa_plus_sc": (985.5, 22.7, 1.00, 20),
            "dssa_plus_cs": (1154.0, 25.0, 1.17, 20), "dssa_plus_eq": (1154.0, 25.0, 1.17, 20)},
    "sixteen": {"dssa": (9833.6, 24.6, 1.14, 32), "dssa_plus_sc": (8693.4, 33.2, 1.01, 50),
                "dssa_plus_cs": (9816.9, 26.5, 1.15, 47), "dssa_plus_eq": (9096.4, 25.3, 1.06, 49)},
    "three": {"dssa": (1709.0, 49.6, 1.02, 20), "dssa_plus_sc": (1702.0, 59.3, 1.01, 1),
              "dssa_plus_cs": (1713.5, 51.4, 1.02, 20), "dssa_plus_eq": (1705.9, 49.5, 1.01, 17)},
}
COLLISION_DISTANCE = 40.0
# Bands: the paper's own spread between variants that behave alike (Table 1 s<c and s=c are identical;
# Table 2 travel times differ by 1-2 units) sets them: 5 % on lengths and travel times, 0.05 on detour.
LENGTH_BAND, TIME_BAND, DETOUR_BAND = 0.05, 0.05, 0.05

# Table 1's lateral offset between the two ships is not given (the figure is lost); the straight length
# (492.4 each) is the paper's s>c total 985.5 / 2 at detour 1.00. The offset is fitted: of these, the one
# whose DSSA total length comes closest to the paper's 1150 (the scenario file must hold it; report()
# checks). The rows it is fitted to, and the s>c length, are calibration rows.
OFFSETS = [170, 180, 182, 184, 186, 188, 190, 200, 210, 220]
STRAIGHT = math.hypot(200.0, 450.0)
TABLE1_FITTED = {("Table 1, DSSA", "total length of paths"), ("Table 1, DSSA", "travel time of each ship"),
                 ("Table 1, DSSA", "detour rate of each ship"), ("Table 1, DSSA+ s>c", "total length of paths")}
# The weights of EF are given only as ratios. One unit u for every variant: DSSA alpha u; s>c alpha 10u,
# beta u; s<c alpha u, beta 10u; s=c u and u. The unit is chosen against every row of the three tables
# at these units (the scale table below); 1, the text's reading with the smaller weight 1, is used.
UNITS = [0.5, 1.0, 2.0]
UNIT = 1.0
WEIGHTS = {"dssa": (1.0, 0.0), "dssa_plus_sc": (10.0, 1.0), "dssa_plus_cs": (1.0, 10.0), "dssa_plus_eq": (1.0, 1.0)}

_TABLE1 = ("Table 1's DSSA outcome is bimodal: one ship pushed out the far side (detour about 1.25) or both deflecting "
           "a little (about 1.09), and which mode the trials take flips within 1 of offset (the fit below); the paper's "
           "DSSA+ s<c is its DSSA (1154 and 1150), as ours is")
_TABLE1_EQ = ("our s=c ships resolve Table 1 partly by slowing, as s>c does (shorter paths, detour near 1), where the "
              "paper's s=c turns like its DSSA (1154, as s<c): with equal weights a speed change costs "
              "|spc| / MaxSPD (8 / 33 for the largest) against |turn| / 180 deg (45 / 180 for the largest), so "
              "slowing is the cheaper escape here")
_TIME = ("the paper's DSSA+ ships sail slower than their paths: its travel times exceed path / 25 (the time at "
         "RefSPD; the paper's DSSA times are exactly that, 1150 / 2 / 25 = 23.0) by 2-3 units in Tables 1-2 for "
         "every DSSA+ variant, even s<c, whose paths equal DSSA's, and by 11.5 for Table 2 s>c. Ours regain "
         "RefSPD as soon as no collision is predicted (the speed term of EF, Sec. 4, pulls them back) and lose "
         "at most 1; the text does not say what keeps its ships slow")
_SCALE = ("the weights of EF are given only as ratios; no one unit gives both the paper's Table 2 s>c (every trial "
          "succeeds) and Table 3 s>c (1 of 20): a larger unit makes turning dearer, so more Table 3 ships collide "
          "overtaking and more Table 2 ships fail (the scale table below)")
REASONS = {
    "Table 1, DSSA": _TABLE1, "Table 1, DSSA+ s<c": _TABLE1, "Table 1, DSSA+ s=c": _TABLE1_EQ,
    ("Table 1, DSSA+ s>c", "travel time of each ship"): _TIME,
    ("Table 2, DSSA", "success rate"): ("our DSSA fails less often than the paper's: the 16-ship layout is "
                                        "reconstructed from the prose and the collision distance 40 is our choice "
                                        "(\"sufficiently small\"); 45 gives 37 of 50 but paths 6 % longer than the "
                                        "paper's"),
    ("Table 2, DSSA+ s>c", "travel time of each ship"): _TIME,
    ("Table 2, DSSA+ s<c", "travel time of each ship"): _TIME, ("Table 2, DSSA+ s=c", "travel time of each ship"): _TIME,
    ("Table 2, DSSA+ s>c", "success rate"): _SCALE,
    ("Table 3, DSSA+ s>c", "success rate"): ("with MinSPD = RefSPD / 2 the 25 cannot follow the 10 and must turn, and "
                                             "the 10 must pass the 5 stopped at her goal: 11 of our 20 trials collide, "
                                             "the paper's 19 (\"in most of the trials\"). " + _SCALE),
    ("Table 3, DSSA+ s>c", "travel time of each ship"): ("the paper's one successful trial of 20 against our 9: "
                                                         "its slow ships are the survivors. " + _TIME),
}


def _two_ship_offset(dx, workdir):
    """Table 1 with the ships dx apart and the same straight length; the path of the scenario file written."""
    with open(os.path.join(common.SCENARIOS, "dssa_two_ships.yaml")) as f:
        sc = yaml.safe_load(f)
    ahead = round(math.sqrt(STRAIGHT ** 2 - dx ** 2), 3)
    crs = math.degrees(math.atan2(dx, ahead))
    for ship, side in ((sc["own_ship"], -1), (sc["targets"][0], 1)):
        ship["position"] = {"x_m": 400 + side * dx / 2, "y_m": 150}
        ship["goal"] = {"x_m": 400 - side * dx / 2, "y_m": round(150 + ahead, 3)}
        ship["course_deg"] = crs if side < 0 else 360 - crs
    path = os.path.join(workdir, "dssa_two_ships_offset_%g" % dx)
    with open(path + ".yaml", "w") as f:
        yaml.safe_dump(sc, f, sort_keys=False)
    return path


def scenario_offset():
    """The lateral offset of the two ships in the scenario file."""
    with open(os.path.join(common.SCENARIOS, "dssa_two_ships.yaml")) as f:
        sc = yaml.safe_load(f)
    return abs(sc["targets"][0]["position"]["x_m"] - sc["own_ship"]["position"]["x_m"])


def planner_of(variant):
    return "dssa" if variant == "dssa" else "dssa_plus"


def _weights(v, unit):
    a, b = WEIGHTS[v]
    return ["%s.alpha=%g" % (planner_of(v), a * unit), "%s.beta=%g" % (planner_of(v), b * unit)] if b else \
        ["%s.alpha=%g" % (planner_of(v), a * unit)]


def _key(scenario, v, unit=UNIT):
    return "dssa_%s_%s" % (scenario, v) + ("" if unit == UNIT else "_u%g" % unit)


def jobs(mode="paper"):
    out = []
    for unit in UNITS:
        for scenario, _, trials, _ in SCENARIOS:
            for v, _ in VARIANTS:
                p = planner_of(v)
                sets = ["%s.preset=%s" % (p, v), "%s.mode=%s" % (p, mode)] + _weights(v, unit)
                out.append(Job(_key(scenario, v, unit), scenario, p, seeds=trials, agents=p, sets=sets))
    offsets = tempfile.mkdtemp(prefix="asv_papers_dssa_")
    for dx in OFFSETS:
        out.append(Job("dssa_offset_%g" % dx, _two_ship_offset(dx, offsets), "dssa", seeds=20, agents="dssa",
                       sets=["dssa.preset=dssa", "dssa.mode=%s" % mode]))
    return out


def summarise(runs):
    ok, collisions, min_sep = [], 0, math.inf
    for r in runs:
        ships = r["ships"]
        sep = min(s["min_separation_m"] for s in ships if s["min_separation_m"] is not None)
        min_sep = min(min_sep, sep)
        collided = r["collision"] or r["collisions_between_targets"] > 0 or sep < COLLISION_DISTANCE
        collisions += collided
        if not collided and all(s["arrived"] for s in ships):
            ok.append(r)
    n = len(ok)

    def mean(f):
        return sum(f(r) for r in ok) / n if n else math.nan

    return {
        "trials": len(runs), "successes": n, "collisions": collisions, "min_separation": min_sep,
        "total_path": mean(lambda r: sum(s["path_length_m"] for s in r["ships"])),
        "travel_time": mean(lambda r: sum(s["time_to_goal_s"] for s in r["ships"]) / len(r["ships"])),
        "detour": mean(lambda r: sum(s["path_ratio"] for s in r["ships"]) / len(r["ships"])),
    }


def _fmt(v, prec):
    return "-" if v is None or (isinstance(v, float) and not math.isfinite(v)) else "%.*f" % (prec, v)


def table(title, key, trials, results):
    head = "| |" + "".join(" %s | (paper) |" % label for _, label in VARIANTS)
    rows = ["#### %s (%d trials, seeds 1..%d)" % (title, trials, trials), "", head,
            "|---|" + "---:|---:|" * len(VARIANTS)]

    def line(name, ours, paper):
        cells = "".join(" %s | %s |" % (ours(results[v]), paper(TABLES[key][v])) for v, _ in VARIANTS)
        rows.append("| %s |%s" % (name, cells))

    line("Total length of paths", lambda s: _fmt(s["total_path"], 1), lambda p: _fmt(p[0], 1))
    line("Travel time of each ship", lambda s: _fmt(s["travel_time"], 1), lambda p: _fmt(p[1], 1))
    line("Detour rate of each ship", lambda s: _fmt(s["detour"], 2), lambda p: _fmt(p[2], 2))
    line("Success rate", lambda s: "%d/%d" % (s["successes"], s["trials"]), lambda p: "%d/%d" % (p[3], trials))
    line("Collisions (closer than %g)" % COLLISION_DISTANCE, lambda s: str(s["collisions"]), lambda p: "")
    line("Min separation", lambda s: _fmt(s["min_separation"], 1), lambda p: "")
    return rows


def compare(key, title, label, s):
    exp = "%s, %s" % (title.split(":")[0], label)
    p = TABLES[key][next(v for v, l in VARIANTS if l == label)]
    trials = {"two": 20, "sixteen": 50, "three": 20}[key]
    nan = float("nan")

    def kind(metric):
        return "calibration" if (exp, metric) in TABLE1_FITTED else "reproduced"

    def band(metric, paper_value, ours, width, relative):
        return band_row(PAPER, exp, metric, paper_value, ours if s["successes"] else nan, width, relative=relative,
                        kind=kind(metric))

    return [count_row(PAPER, exp, "success rate", p[3], trials, s["successes"], s["trials"]),
            band("total length of paths", p[0], s["total_path"], LENGTH_BAND, True),
            band("travel time of each ship", p[1], s["travel_time"], TIME_BAND, True),
            band("detour rate of each ship", p[2], s["detour"], DETOUR_BAND, False)]


def _offset_fit(done):
    """Table 1's offset fit: DSSA's outcome at every offset tried, the best and the scenario's."""
    fits = []
    for dx in OFFSETS:
        s = summarise(done["dssa_offset_%g" % dx].runs)
        fits.append((abs(s["total_path"] - TABLES["two"]["dssa"][0]) if s["successes"] else math.inf, dx, s))
    best = min(fits, key=lambda f: f[:2])[1]
    if best != scenario_offset():
        raise RuntimeError("dssa_two_ships.yaml has the ships %g apart, but the Table 1 fit now gives %g: update the "
                           "scenario (and asv::dssaTwoShipScenario()) to the fitted offset" % (scenario_offset(), best))
    lines = ["#### Table 1's offset, fitted", "",
             "The ships' lateral offset is not given; at the straight length 492.4 each, DSSA over 20 trials at each "
             "offset tried (the scenario uses the one whose total length comes closest to the paper's 1150: %g):" % best,
             "", "| offset | total length of paths | detour rate of each ship | successes |", "|---:|---:|---:|---:|"]
    for _, dx, s in fits:
        lines.append("| %g%s | %s | %s | %d/%d |" % (dx, " (fitted)" if dx == best else "", _fmt(s["total_path"], 1),
                                                      _fmt(s["detour"], 2), s["successes"], s["trials"]))
    lines.append("| paper | 1150.0 | 1.17 | 20/20 |")
    return lines


def _unit_table(done):
    """Every variant at every weight unit: successes, and how many reproduced rows are within tolerance."""
    lines = ["#### The unit of the weights", "",
             "The paper gives only the ratios of alpha and beta. Successes per table and variant, and the reproduced "
             "rows within tolerance, at three units u (DSSA alpha u; s>c alpha 10u, beta u; s<c alpha u, beta 10u; "
             "s=c u, u); the pages above use u = %g:" % UNIT, "",
             "| | " + " | ".join("u = %g" % u for u in UNITS) + " | paper |", "|---|" + "---:|" * (len(UNITS) + 1)]
    within = {u: 0 for u in UNITS}
    for scenario, title, trials, key in SCENARIOS:
        for v, label in VARIANTS:
            cells = []
            for u in UNITS:
                s = summarise(done[_key(scenario, v, u)].runs)
                cells.append("%d/%d" % (s["successes"], s["trials"]))
                within[u] += sum(r["within"] for r in compare(key, title, label, s) if r["kind"] == "reproduced")
            lines.append("| %s, %s | %s | %d/%d |" % (title.split(":")[0], label, " | ".join(cells),
                                                      TABLES[key][v][3], trials))
    lines.append("| reproduced rows within tolerance | %s | |" % " | ".join(str(within[u]) for u in UNITS))
    return lines


def report(done, mode="paper"):
    rows, lines = [], []
    for scenario, title, trials, key in SCENARIOS:
        results = {v: summarise(done[_key(scenario, v)].runs) for v, _ in VARIANTS}
        lines += table(title, key, trials, results) + [""]
        for v, label in VARIANTS:
            rows += compare(key, title, label, results[v])
    lines += _offset_fit(done) + [""] + _unit_table(done)
    shutil.rmtree(os.path.dirname(done["dssa_offset_%g" % OFFSETS[0]].scenario), ignore_errors=True)
    return rows, lines
