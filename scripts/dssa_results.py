#!/usr/bin/python3
"""Reproduces the experiments of Hirayama et al. (2019), Sec. 5 (Tables 1-3), through asv_batch and
writes the tables into docs/results/dssa.md (between the BEGIN/END markers; the rest of the page is
hand-written).

Every ship of the scenarios asv_bringup/scenarios/dssa_two_ships, dssa_16_ships and dssa_three_overtaking
is a DSSA agent; asv_batch runs them through its in-process DssaExchange (the core DSSA code path of the
planner plugins and the ROS agents). For each variant (DSSA and DSSA+ s>c, s<c, s=c) it runs the paper's
number of trials (seeds 1..N) and reports, over the successful trials as the paper does (Sec. 5.2), the
total length of paths, the travel time of each ship, the detour rate of each ship, and the success rate.
A trial succeeds when every ship arrives and no two ships ever come closer than the collision distance
(40, the scenario's safety.min_separation_m and the planners' collision_distance).

Run from the repository root after `make build` (`make dssa-results` does both):
    scripts/dssa_results.py [--trials-scale F] [--jobs N] [--out docs/results/dssa.md] [--check]
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENARIOS = [  # (scenario file, table title, trials in the paper, paper table key)
    ("dssa_two_ships", "Table 1: two ships pushing each other", 20, "two"),
    ("dssa_16_ships", "Table 2: 16 ships crossing each other", 50, "sixteen"),
    ("dssa_three_overtaking", "Table 3: three ships overtaking or being overtaken", 20, "three"),
]
VARIANTS = [("dssa", "DSSA"), ("dssa_plus_sc", "DSSA+ s>c"), ("dssa_plus_cs", "DSSA+ s<c"),
            ("dssa_plus_eq", "DSSA+ s=c")]
# The paper's figures, Tables 1-3: total length of paths, travel time of each ship, detour rate of each
# ship, successes (of 20, 50, 20 trials).
PAPER = {
    "two": {"dssa": (1150.0, 23.0, 1.17, 20), "dssa_plus_sc": (985.5, 22.7, 1.00, 20),
            "dssa_plus_cs": (1154.0, 25.0, 1.17, 20), "dssa_plus_eq": (1154.0, 25.0, 1.17, 20)},
    "sixteen": {"dssa": (9833.6, 24.6, 1.14, 32), "dssa_plus_sc": (8693.4, 33.2, 1.01, 50),
                "dssa_plus_cs": (9816.9, 26.5, 1.15, 47), "dssa_plus_eq": (9096.4, 25.3, 1.06, 49)},
    "three": {"dssa": (1709.0, 49.6, 1.02, 20), "dssa_plus_sc": (1702.0, 59.3, 1.01, 1),
              "dssa_plus_cs": (1713.5, 51.4, 1.02, 20), "dssa_plus_eq": (1705.9, 49.5, 1.01, 17)},
}
COLLISION_DISTANCE = 40.0
BEGIN = "<!-- BEGIN scripts/dssa_results.py: generated, do not edit by hand -->"
END = "<!-- END scripts/dssa_results.py -->"


def run_variant(batch, scenario, variant, trials, workdir):
    planner = "dssa" if variant == "dssa" else "dssa_plus"
    out = os.path.join(workdir, "%s_%s.jsonl" % (scenario, variant))
    path = os.path.join(ROOT, "asv_bringup", "scenarios", scenario + ".yaml")
    cmd = [batch, "--scenario", path, "--planner", planner, "--agents", planner, "--set",
           "%s.preset=%s" % (planner, variant), "--runs", str(trials), "--seed", "1", "--deterministic",
           "--quiet", "--json", out]
    t0 = time.time()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if proc.returncode != 0:
        raise RuntimeError("%s failed (%d):\n%s" % (" ".join(cmd), proc.returncode, proc.stdout.decode()))
    with open(out) as f:
        runs = [json.loads(line) for line in f if line.strip()]
    return runs, time.time() - t0


def summarise(runs):
    ok, collisions, min_sep, worst_wall = [], 0, math.inf, 0.0
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


def fmt(v, prec):
    return "-" if v is None or (isinstance(v, float) and not math.isfinite(v)) else "%.*f" % (prec, v)


def table(title, key, trials, results):
    head = "| |" + "".join(" %s | (paper) |" % label for _, label in VARIANTS)
    rows = ["### %s (%d trials, seeds 1..%d)" % (title, trials, trials), "", head,
            "|---|" + "---:|---:|" * len(VARIANTS)]

    def row(name, ours, paper):
        cells = "".join(" %s | %s |" % (ours(results[v]), paper(PAPER[key][v])) for v, _ in VARIANTS)
        rows.append("| %s |%s" % (name, cells))

    row("Total length of paths", lambda s: fmt(s["total_path"], 1), lambda p: fmt(p[0], 1))
    row("Travel time of each ship", lambda s: fmt(s["travel_time"], 1), lambda p: fmt(p[1], 1))
    row("Detour rate of each ship", lambda s: fmt(s["detour"], 2), lambda p: fmt(p[2], 2))
    row("Success rate", lambda s: "%d/%d" % (s["successes"], s["trials"]), lambda p: "%d/%d" % (p[3], trials))
    row("Collisions (closer than %g)" % COLLISION_DISTANCE, lambda s: str(s["collisions"]), lambda p: "")
    row("Min separation", lambda s: fmt(s["min_separation"], 1), lambda p: "")
    return rows


def verdict(all_results):
    lines = []
    for scenario, title, trials, key in SCENARIOS:
        for v, label in VARIANTS:
            s = all_results[scenario][v]
            p = PAPER[key][v]
            if s["successes"] * trials < p[3] * s["trials"]:
                lines.append("%s, %s: success %d/%d below the paper's %d/%d" %
                             (title.split(":")[0], label, s["successes"], s["trials"], p[3], trials))
            if s["successes"] and round(s["detour"], 2) > p[2]:
                lines.append("%s, %s: detour rate %.2f above the paper's %.2f" %
                             (title.split(":")[0], label, s["detour"], p[2]))
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--trials-scale", type=float, default=1.0,
                    help="fraction of the paper's trial counts to run (default 1: 20, 50, 20)")
    ap.add_argument("--jobs", type=int, default=2, help="asv_batch processes at once (default 2)")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "results", "dssa.md"),
                    help="markdown page whose generated block is replaced (default docs/results/dssa.md)")
    ap.add_argument("--batch", default=shutil.which("asv_batch") or
                    os.path.join(ROOT, "devel", "lib", "asv_sim", "asv_batch"),
                    help="the asv_batch executable (default: from the catkin devel space)")
    ap.add_argument("--check", action="store_true",
                    help="exit 1 when a success rate is below the paper's or a detour rate above it")
    a = ap.parse_args()
    if not os.access(a.batch, os.X_OK):
        sys.exit("dssa_results: no asv_batch at %s (make build, then source devel/setup.bash)" % a.batch)
    if "ROS_PACKAGE_PATH" not in os.environ:
        sys.exit("dssa_results: source devel/setup.bash first (asv_batch finds the planners through it)")
    jobs = []
    work = tempfile.mkdtemp(prefix="asv_dssa_")
    for scenario, _, trials, _ in SCENARIOS:
        n = max(1, int(round(trials * a.trials_scale)))
        for v, _ in VARIANTS:
            jobs.append((scenario, v, n))
    results = {s: {} for s, _, _, _ in SCENARIOS}
    t0 = time.time()
    with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        futures = [(j, pool.submit(run_variant, a.batch, j[0], j[1], j[2], work)) for j in jobs]
        for k, (j, fut) in enumerate(futures):
            runs, took = fut.result()
            s = summarise(runs)
            s["wall"] = took
            results[j[0]][j[1]] = s
            print("[%2d/%d] %-22s %-13s %2d/%2d succeeded, %d collisions, min sep %.1f (%.1f s)" %
                  (k + 1, len(jobs), j[0], j[1], s["successes"], s["trials"], s["collisions"],
                   s["min_separation"], took), flush=True)
    shutil.rmtree(work, ignore_errors=True)

    block = [BEGIN, "",
             "Generated by `scripts/dssa_results.py` (asv_batch, `--deterministic`, %d cores, %.0f s in all)."
             % (os.cpu_count() or 1, time.time() - t0), ""]
    for scenario, title, trials, key in SCENARIOS:
        block += table(title, key, results[scenario][VARIANTS[0][0]]["trials"], results[scenario]) + [""]
        # the paper's trial count is the one the "(paper)" column is out of
    problems = verdict(results)
    block += ["Against the paper: " + ("every success rate is at least the paper's and every detour rate "
                                       "is no worse (to two decimals)." if not problems else
                                       "; ".join(problems) + "."), "", END]
    with open(a.out) as f:
        page = f.read()
    if BEGIN in page and END in page:
        page = page[:page.index(BEGIN)] + "\n".join(block) + page[page.index(END) + len(END):]
    else:
        page = page.rstrip("\n") + "\n\n" + "\n".join(block) + "\n"
    with open(a.out, "w") as f:
        f.write(page)
    print("dssa_results: tables written to %s" % os.path.relpath(a.out, os.getcwd()))
    for p in problems:
        print("dssa_results: " + p)
    return 1 if a.check and problems else 0


if __name__ == "__main__":
    sys.exit(main())
