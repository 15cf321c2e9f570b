#!/usr/bin/env python3
"""Real-traffic benchmark: the own ship in the place of logged vessels, judged against their masters.

From any MarineCadastre AIS CSV (default: $ASV_AIS_LOG, else the shared New York hour), windows are picked
automatically: every --step seconds from 5 minutes into the log, the vessels under way (3 kn or more at the
start, 1 km or more made good over the window) that meet others (another vessel under way within 1 km at
some time of the window), those meeting the most first, --per-start of them. Each becomes a scenario
(asv_scenario_from_ais --own-mmsi: her track as the route, her mean speed, her time x 1.3, and the human
record of her closest approach, time and path), run once per planner through asv_batch under GNU parallel.

The log is split by time: windows starting in its first half are the tuning range, which may be looked at
while the planners are improved; the second half is the test range, only ever reported (printed first).

Writes OUT (default out/benchmark/real/): scenarios/<range>/*.yaml, runs/<range>/*.json, refused.txt (windows
the scenario tool refused, and why), report.md and summary.json.
"""
import argparse
import bisect
import csv
import datetime
import json
import math
import os
import shutil
import statistics
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark import PLANNERS, fmt, percentile, progress, tool  # noqa: E402

DEFAULT_LOG = os.environ.get("ASV_AIS_LOG") or os.path.join(
    REPO, "..", "shared", "data", "ais", "real", "NYHarbor_2020_06_30_first_hour.csv")
UNDER_WAY_KN = 3.0    # at the start: a vessel under way, not manoeuvring off a berth
MADE_GOOD_M = 1000.0  # over the window: she goes somewhere
MEET_M = 1000.0       # another vessel under way this close at some time: she meets traffic
SAMPLE_S = 30.0       # the meeting test's time step
MAX_GAP_S = 600.0     # as asv_scenario_from_ais: a longer silence ends a track


def utc(text):
    return datetime.datetime.strptime(text.rstrip("Z").replace(" ", "T"), "%Y-%m-%dT%H:%M:%S").replace(
        tzinfo=datetime.timezone.utc).timestamp()


def iso(t):
    return datetime.datetime.fromtimestamp(t, datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%S")


def read_log(path):
    """(MMSI -> time-sorted [(t, lat, lon, sog)], rows rejected): a row that does not read, or whose
    position or speed is out of range (SOG 102.3 kn is AIS's "not available"), is counted and left out."""
    tracks, rejected = {}, 0
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            try:
                t, lat, lon = utc(row["BaseDateTime"]), float(row["LAT"]), float(row["LON"])
                sog, mmsi = float(row["SOG"]), int(row["MMSI"])
            except (KeyError, ValueError, TypeError):
                rejected += 1
                continue
            if abs(lat) <= 90 and abs(lon) <= 180 and sog < 102.2:
                tracks.setdefault(mmsi, []).append((t, lat, lon, sog))
            else:
                rejected += 1
    for tr in tracks.values():
        tr.sort()
    return tracks, rejected


def position(track, times, t):
    """Where the vessel is at t (metres east/north of 0 N 0 E on a local scale), or None."""
    k = bisect.bisect_right(times, t) - 1
    if k < 0 or k + 1 >= len(track) or track[k + 1][0] - track[k][0] > MAX_GAP_S:
        return None
    (t0, la0, lo0, _), (t1, la1, lo1, _) = track[k], track[k + 1]
    s = (t - t0) / (t1 - t0) if t1 > t0 else 0.0
    lat, lon = la0 + s * (la1 - la0), lo0 + s * (lo1 - lo0)
    return (lon * 111320.0 * math.cos(math.radians(lat)), lat * 110540.0)


def pick(tracks, start, duration, per_start):
    """The vessels under way at `start` that meet others in the window, most meetings first."""
    times = {m: [p[0] for p in tr] for m, tr in tracks.items()}
    samples = [start + k * SAMPLE_S for k in range(int(duration / SAMPLE_S) + 1)]
    where = {m: [position(tr, times[m], t) for t in samples] for m, tr in tracks.items()}
    moving = {m for m, tr in tracks.items()
              if any(p[3] >= 1.0 for p in tr if start - MAX_GAP_S <= p[0] <= start + duration)}
    picks = []
    for m, tr in tracks.items():
        k = bisect.bisect_right(times[m], start) - 1
        a, b = where[m][0], where[m][-1]
        if k < 0 or tr[k][3] < UNDER_WAY_KN or a is None or b is None or math.dist(a, b) < MADE_GOOD_M:
            continue
        met = {o for o in moving if o != m and any(
            p and q and math.dist(p, q) <= MEET_M for p, q in zip(where[m], where[o]))}
        if met:
            picks.append((-len(met), m))
    return [m for _, m in sorted(picks)[:per_start]]


def windows(tracks, duration, step, per_start):
    """[(range, start, mmsi)]: starts every `step` s from 5 min into the log while the window fits."""
    first = min(tr[0][0] for tr in tracks.values())
    last = max(tr[-1][0] for tr in tracks.values())
    middle = 0.5 * (first + last)
    out, start = [], first + 300.0
    while start + duration <= last:
        rng = "tuning" if start < middle else "test"
        out += [(rng, start, m) for m in pick(tracks, start, duration, per_start)]
        start += step
    return out


def make_scenarios(log, out, picks, duration):
    """asv_scenario_from_ais for every pick; returns [(range, file)] and writes refused.txt."""
    from_ais = tool("asv_scenario_from_ais", "asv_core")
    made, refused = [], []
    for rng, start, mmsi in picks:
        folder = os.path.join(out, "scenarios", rng)
        os.makedirs(folder, exist_ok=True)
        stamp = iso(start)
        path = os.path.join(folder, "real_%s_%d.yaml" % (stamp[11:16].replace(":", ""), mmsi))
        p = subprocess.run([from_ais, log, "--quiet", "--start", stamp, "--duration", str(duration),
                            "--own-mmsi", str(mmsi), "--out", path], capture_output=True, text=True)
        if p.returncode == 0:
            made.append((rng, path))
        else:
            refused.append("%s %s %d: %s" % (rng, stamp, mmsi, p.stderr.strip().splitlines()[-1]))
    with open(os.path.join(out, "refused.txt"), "w") as f:
        f.write("\n".join(refused) + ("\n" if refused else ""))
    return made, refused


def run(out, made, planners, jobs, follower=()):
    if not shutil.which("parallel"):
        sys.exit("real_traffic: GNU parallel is missing (scripts/setup installs it)")
    batch = tool("asv_batch", "asv_sim")
    lines = []
    for rng, path in made:
        os.makedirs(os.path.join(out, "runs", rng), exist_ok=True)
        stem = os.path.basename(path)[:-len(".yaml")]
        for p in planners:
            lines.append("\t".join([path, p, os.path.join(out, "runs", rng, "%s__%s.json" % (stem, p))]))
    todo = os.path.join(out, "jobs.txt")
    with open(todo, "w") as f:
        f.write("\n".join(lines) + "\n")
    cmd = ["parallel", "--colsep", "\t", "--halt", "never", "--joblog", todo + ".log", "-j", str(jobs),
           batch, "--scenario", "{1}", "--planner", "{2}", "--quiet"]
    for kv in follower:
        cmd += ["--follower", kv]
    cmd += ["--json", "{3}.part", "&&", "mv", "{3}.part", "{3}", "::::", todo]
    print("real_traffic: %d runs on %d job slot(s)..." % (len(lines), jobs), flush=True)
    started = time.time()
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL)
    progress(proc, todo + ".log", len(lines), started)
    return time.time() - started


def load(out):
    results = {}
    for rng in ("test", "tuning"):
        folder = os.path.join(out, "runs", rng)
        rows = []
        for fn in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
            if fn.endswith(".json"):
                with open(os.path.join(folder, fn)) as f:
                    r = json.loads(f.readline())
                r["window"] = fn.split("__")[0]
                rows.append(r)
        results[rng] = rows
    return results


def median(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def metrics(rows):
    human = [r for r in rows if r.get("human")]
    maxima = [r["plan_time_ms"]["max"] for r in rows if r["plan_time_ms"]["max"] is not None]
    n = max(len(rows), 1)
    return {
        "runs": len(rows),
        "collisions": sum(r["collision"] for r in rows),
        "groundings": sum(bool(r.get("grounding")) for r in rows),
        "arrived": sum(r["arrived"] for r in rows),
        "arrived_pct": 100.0 * sum(r["arrived"] for r in rows) / n,
        "separation_at_least_master_pct": 100.0 * sum(
            (r.get("separation_vs_human") or 0.0) >= 1.0 for r in human) / max(len(human), 1),
        "time_vs_human_median": median([r.get("time_vs_human") for r in human]),
        "separation_vs_human_median": median([r.get("separation_vs_human") for r in human]),
        "max_xte_m_median": median([r.get("route", {}).get("max_xte_m") for r in rows]),
        "plan_time_ms": {"median": median([r["plan_time_ms"]["median"] for r in rows]),
                         "p99": percentile(maxima, 0.99), "max": max(maxima, default=None)},
    }


def table(summary_range):
    out = ["| planner | runs | own collisions | groundings | arrived | separation >= master's | time / master's "
           "(median) | separation / master's (median) | off route, max (median) [m] | plan ms median / p99 / max |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    for p, m in summary_range.items():
        pt = m["plan_time_ms"]
        out.append("| %s | %d | %d | %d | %d (%.0f %%) | %.0f %% | %s | %s | %s | %s / %s / %s |" % (
            p, m["runs"], m["collisions"], m["groundings"], m["arrived"], m["arrived_pct"],
            m["separation_at_least_master_pct"], fmt(m["time_vs_human_median"]),
            fmt(m["separation_vs_human_median"]), fmt(m["max_xte_m_median"], "%.0f"), fmt(pt["median"], "%.1f"),
            fmt(pt["p99"], "%.1f"), fmt(pt["max"], "%.1f")))
    return out


def window_table(rows, planners):
    windows = sorted({r["window"] for r in rows})
    out = ["| window | master: closest approach [m], time [s] | " + " | ".join(planners) + " |",
           "|---|---|" + "---|" * len(planners)]
    for w in windows:
        mine = {r["planner"]: r for r in rows if r["window"] == w}
        h = next((r["human"] for r in mine.values() if r.get("human")), None)
        cells = []
        for p in planners:
            r = mine.get(p)
            if not r:
                cells.append("-")
                continue
            state = "COLLISION" if r["collision"] else "aground" if r.get("grounding") else (
                "%.0f s" % r["time_to_goal_s"] if r["arrived"] else "not arrived")
            cells.append("%s, %s m" % (state, fmt(r["min_separation_m"], "%.0f")))
        out.append("| %s | %s | %s |" % (w, "%.0f, %.0f" % (h["min_separation_m"], h["time_s"]) if h else "-",
                                        " | ".join(cells)))
    return out


def report(out, log, results, summary, refused, wall):
    lines = ["# Real-traffic benchmark", "",
             "Generated by `scripts/real_traffic.py` (`make benchmark`) from the runs in `%s/runs/`; do not edit." %
             os.path.relpath(out, REPO), "",
             "Log: `%s`. The own ship takes the place of a logged vessel under way that meets others, sails her "
             "track (thinned) as a route at her mean speed, and has her time x 1.3 to arrive; \"master\" is what "
             "that vessel did. **test**: windows starting in the second half of the log, only ever reported; "
             "**tuning**: the first half. Plan time on %d cores shared by %d job slots." % (
                 os.path.basename(log), os.cpu_count(), wall.get("jobs", 0)), ""]
    for rng in ("test", "tuning"):
        rows = results[rng]
        lines += ["## %s range: %d windows, %d runs" % (rng, len({r["window"] for r in rows}), len(rows)), ""]
        lines += table(summary[rng]) + ["", "Per window (time to goal or why not, closest approach):", ""]
        lines += window_table(rows, list(summary[rng])) + [""]
    if refused:
        lines += ["Windows the scenario tool refused (`refused.txt`):", ""] + ["- " + r for r in refused] + [""]
    if wall.get("follower"):
        lines += ["Follower settings over planner_node.yaml's: `%s`." % "`, `".join(wall["follower"]), ""]
    if wall.get("seconds"):
        lines += ["Wall time of the runs: %.0f s." % wall["seconds"], ""]
    with open(os.path.join(out, "report.md"), "w") as f:
        f.write("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--csv", default=DEFAULT_LOG, help="MarineCadastre AIS CSV (default: $ASV_AIS_LOG or the "
                    "shared New York hour)")
    ap.add_argument("--out", default=os.path.join(REPO, "out", "benchmark", "real"), help="output folder")
    ap.add_argument("--planners", default=",".join(PLANNERS), help="comma-separated (default: all five)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count(), help="parallel job slots (default: every core)")
    ap.add_argument("--duration", type=float, default=600.0, help="window she is followed for [s] (default 600)")
    ap.add_argument("--step", type=float, default=480.0, help="between window starts [s] (default 480)")
    ap.add_argument("--per-start", type=int, default=3, help="vessels per window start (default 3)")
    ap.add_argument("--follower", action="append", default=[], metavar="KEY=VALUE",
                    help="a planner_node replanning-policy parameter for every run, as asv_batch --follower "
                    "(repeatable), e.g. narrow_fairway_width_m=0 to compare without Rule 9")
    ap.add_argument("--report-only", action="store_true", help="report the runs already in OUT/runs")
    a = ap.parse_args()
    planners = [p for p in a.planners.split(",") if p]
    if any(p not in PLANNERS for p in planners) or a.duration <= 0 or a.step <= 0 or a.per_start < 1:
        ap.error("--planners a subset of %s; --duration, --step > 0; --per-start >= 1" % ",".join(PLANNERS))
    if not os.path.exists(a.csv):
        print("real_traffic: SKIPPED: no AIS log at %s (set ASV_AIS_LOG or --csv)" % a.csv)
        return 0
    out = os.path.abspath(a.out)
    wall, refused = {"jobs": a.jobs, "follower": a.follower}, []
    if not a.report_only:
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        print("real_traffic: reading %s..." % a.csv, flush=True)
        tracks, rejected = read_log(a.csv)
        if rejected:
            print("real_traffic: %d rows rejected (unreadable, or position or speed out of range)" % rejected,
                  flush=True)
        picks = windows(tracks, a.duration, a.step, a.per_start)
        made, refused = make_scenarios(a.csv, out, picks, a.duration)
        print("real_traffic: %d windows picked, %d made, %d refused (refused.txt)" % (
            len(picks), len(made), len(refused)), flush=True)
        wall["seconds"] = run(out, made, planners, a.jobs, a.follower)
    elif os.path.exists(os.path.join(out, "refused.txt")):
        refused = open(os.path.join(out, "refused.txt")).read().splitlines()
    results = load(out)
    summary = {rng: {p: metrics([r for r in results[rng] if r["planner"] == p]) for p in planners}
               for rng in ("test", "tuning")}
    summary["cores"] = os.cpu_count()
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
    report(out, a.csv, results, summary, refused, wall)
    for rng in ("test", "tuning"):
        print("\n%s range:" % rng)
        print("\n".join(table(summary[rng])))
    print("\nreal_traffic: %s/report.md, summary.json" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
