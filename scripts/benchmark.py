#!/usr/bin/env python3
"""Monte-Carlo benchmark: generated situations x every planner through asv_batch (docs/evaluation.md).

Two seed ranges of asv_scenario_gen situations: the tuning range, which may be looked at while the planners
are improved, and the test range, which is only ever reported (the report prints it first). Each situation
runs once per planner, under GNU parallel on every core (or on several hosts with --sshloginfile), or as
chunks of a Slurm job array (scripts/slurm/benchmark.sbatch) merged by --report-only.

Writes out/benchmark/: scenarios/<range>/*.yaml, runs/<range>/<scenario>__<planner>.json (one result JSON
each), jobs.txt, report.md, summary.json, separation.png, score_by_class.png.
"""
import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

# The two ranges: asv_scenario_gen seeds. Situations 0..N-1 of each; asv_batch's planner seed is the
# range's seed plus the situation index. Never tune on the test range.
RANGES = [("test", 7919), ("tuning", 1)]
PLANNERS = ["aco", "mopso", "ga", "dssa", "dssa_plus"]
CLASSES = ["head_on", "crossing_give_way", "crossing_stand_on", "overtaking", "being_overtaken", "rule_breaker",
           "multi", "converging", "coastal", "offset_head_on", "head_on_starboard_occupied",
           "head_on_crossing_boundary", "stand_on_remote_duty", "late_give_way", "route_bend_crossing"]
# The pass rules the planners are held to (docs/evaluation.md): no own-ship collision or grounding, the
# minimum separation kept in at least 99 % of runs, mean COLREGs score >= 0.95 with one target, >= 0.85 with
# several.
PASS_SEPARATION = 0.99
PASS_SCORE_SINGLE = 0.95
PASS_SCORE_MULTI = 0.85
# ... no turn to port for a ship met head-on, crossing from starboard or (as the stand-on ship) on the
# port side unless the evaluator's note shows it was forced (no alteration of 10-90 deg to starboard nor
# half speed kept clear of every ship and of land), and no stand-on alteration excused by another duty
# ("rule 17 not applied").
UNFORCED_PORT_TURNS = ("rule 14 port turn", "rule 15 port turn", "rule 17(c) port turn")
RULE17_NOT_APPLIED = "rule 17 not applied"
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def tool(name, package):
    """A built executable: on PATH, else the devel space of this checkout."""
    found = shutil.which(name)
    if found:
        return found
    path = os.path.join(REPO, "devel", "lib", package, name)
    if os.access(path, os.X_OK):
        return path
    sys.exit("benchmark: %s not found (make build, then source devel/setup.bash)" % name)


def generate(out, situations, ranges):
    gen = tool("asv_scenario_gen", "asv_core")
    for name, seed in ranges:
        folder = os.path.join(out, "scenarios", name)
        shutil.rmtree(folder, ignore_errors=True)
        print("benchmark: generating %d %s situations (seed %d)..." % (situations, name, seed), flush=True)
        subprocess.run([gen, "--out", folder, "--count", str(situations), "--seed", str(seed), "--quiet"],
                       check=True)


def write_jobs(out, planners, ranges):
    """One line per run: range, scenario file, planner, planner seed, result file."""
    lines = []
    for name, seed in ranges:
        folder = os.path.join(out, "scenarios", name)
        with open(os.path.join(folder, "manifest.tsv")) as f:
            files = [row.split("\t")[0] for row in f.read().splitlines()[1:]]
        os.makedirs(os.path.join(out, "runs", name), exist_ok=True)
        for index, scenario in enumerate(files):
            stem = scenario[:-len(".yaml")]
            for p in planners:
                result = os.path.join(out, "runs", name, "%s__%s.json" % (stem, p))
                lines.append("\t".join([name, os.path.join(folder, scenario), p, str(seed + index), result]))
    path = os.path.join(out, "jobs.txt")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def run_jobs(jobs_file, jobs, sshloginfile, chunk=None):
    """asv_batch for every job line (or for chunk (k, n) of them) under GNU parallel."""
    if not shutil.which("parallel"):
        sys.exit("benchmark: GNU parallel is missing (scripts/setup installs it)")
    batch = tool("asv_batch", "asv_sim")
    with open(jobs_file) as f:
        lines = f.read().splitlines()
    if chunk:
        k, n = chunk
        lines = lines[k::n]
    todo = jobs_file + (".chunk%d" % chunk[0] if chunk else ".todo")
    with open(todo, "w") as f:
        f.write("\n".join(lines) + "\n")
    cmd = ["parallel", "--colsep", "\t", "--halt", "never", "--joblog", todo + ".log",
           "-j", str(jobs)]
    cmd += ["--sshloginfile", sshloginfile] if sshloginfile else []
    cmd += [batch, "--scenario", "{2}", "--planner", "{3}", "--seed", "{4}", "--quiet", "--json", "{5}.part",
            "&&", "mv", "{5}.part", "{5}", "::::", todo]
    print("benchmark: %d runs on %s job slot(s)%s..." % (len(lines), jobs,
          " over the hosts of " + sshloginfile if sshloginfile else ""), flush=True)
    started = time.time()
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL)
    progress(proc, todo + ".log", len(lines), started)
    return time.time() - started


def progress(proc, joblog, total, started):
    """One progress line (rewritten on a terminal, every 30 s in a log) until the runs are done."""
    tty, last = sys.stderr.isatty(), 0.0
    while proc.poll() is None:
        time.sleep(1.0)
        now = time.time()
        if not tty and now - last < 30.0:
            continue
        last = now
        try:
            with open(joblog) as f:
                done = max(0, sum(1 for _ in f) - 1)
        except OSError:
            done = 0
        left = (now - started) / done * (total - done) if done else float("nan")
        line = "benchmark: %d/%d runs (%.0f %%), %.0f s elapsed, about %.0f s left" % (
            done, total, 100.0 * done / max(total, 1), now - started, left)
        print(("\r" + line) if tty else line, end="" if tty else "\n", file=sys.stderr, flush=True)
    if tty:
        print(file=sys.stderr)


def load_results(out, manifests):
    results = {}
    for name, _ in RANGES:
        folder = os.path.join(out, "runs", name)
        rows = []
        for fn in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
            if not fn.endswith(".json"):
                continue
            with open(os.path.join(folder, fn)) as f:
                r = json.loads(f.readline())
            stem = fn.split("__")[0]
            r["class"] = manifests[name].get(stem, {}).get("class", "?")
            r["file"] = os.path.join(out, "scenarios", name, stem + ".yaml")
            rows.append(r)
        results[name] = rows
    return results


def read_manifests(out):
    manifests = {}
    for name, _ in RANGES:
        entries = {}
        path = os.path.join(out, "scenarios", name, "manifest.tsv")
        if os.path.exists(path):
            with open(path) as f:
                head, *rows = [line.split("\t") for line in f.read().splitlines()]
            for row in rows:
                e = dict(zip(head, row))
                entries[e["file"][:-len(".yaml")]] = e
        manifests[name] = entries
    return manifests


def finding(note):
    """The rule finding a COLREGs note reports, or None."""
    if re.match(r"^rule 1[457](\(c\))?: the turn to port .* excused$", note):
        return None  # made keeping out of the way of another ship, who is named
    for pattern, key in [(r"^rule 8:", "rule 8 not apparent"), (r"^rule 8\(b\)", "rule 8(b) succession"),
                         (r"^rule 17 not applied", RULE17_NOT_APPLIED),
                         (r"^rule 16: the give-way ship took no", "rule 16 no action"),
                         (r"^rule 16:", "rule 16 late"), (r"^rule 14:", "rule 14 port turn"),
                         (r"^rule 15: turned", "rule 15 port turn"), (r"^rule 15: crossed", "rule 15 crossed ahead"),
                         (r"^rule 17\(c\)", "rule 17(c) port turn"), (r"^rule 17\(b\)", "rule 17(b) held on"),
                         (r"^rule 17:", "rule 17 stand-on altered")]:
        if re.match(pattern, note):
            # The evaluator says whether a Rule 14/15/17(c) port turn was forced (no alternative open).
            return key + " (forced)" if "; forced: " in note else key
    return None


def percentile(values, q):
    if not values:
        return None
    v = sorted(values)
    return v[min(len(v) - 1, int(math.ceil(q * len(v))) - 1)]


def mean(values):
    return statistics.fmean(values) if values else None


def metrics(rows):
    """The figures of one planner (and class) on one range."""
    findings = {}
    for r in rows:
        for t in r["targets"]:
            for n in t["colregs_notes"]:
                key = finding(n)
                if key:
                    findings[key] = findings.get(key, 0) + 1
    single = [r["colregs_score"] for r in rows if len(r["targets"]) == 1]
    multi = [r["colregs_score"] for r in rows if len(r["targets"]) > 1]
    medians = [r["plan_time_ms"]["median"] for r in rows if r["plan_time_ms"]["median"] is not None]
    maxima = [r["plan_time_ms"]["max"] for r in rows if r["plan_time_ms"]["max"] is not None]
    return {
        "runs": len(rows),
        "collisions": sum(r["collision"] for r in rows),
        "groundings": sum(bool(r.get("grounding")) for r in rows),
        "collisions_between_targets": sum(r.get("collisions_between_targets", 0) for r in rows),
        "separation_kept": sum(not r["safety_violation"] for r in rows),
        "arrived": sum(r["arrived"] for r in rows),
        "path_ratio_mean": mean([r["path_ratio"] for r in rows if r["path_ratio"] is not None]),
        "colregs_score_mean": mean([r["colregs_score"] for r in rows]),
        "colregs_score_single": mean(single),
        "colregs_score_multi": mean(multi),
        "min_separation_m": min((r["min_separation_m"] for r in rows if r["min_separation_m"] is not None),
                                default=None),
        "findings": dict(sorted(findings.items())),
        "plan_time_ms": {"median": statistics.median(medians) if medians else None,
                         "p99": percentile(maxima, 0.99), "max": max(maxima, default=None)},
    }


def passes(m):
    """The pass rules, each True/False (None when there is nothing to judge)."""
    sep = m["separation_kept"] / m["runs"] if m["runs"] else None
    s1, sm = m["colregs_score_single"], m["colregs_score_multi"]
    return {"no collision": m["collisions"] == 0 and m["groundings"] == 0,
            "separation >= 99 %": None if sep is None else sep >= PASS_SEPARATION,
            "score single >= 0.95": None if s1 is None else s1 >= PASS_SCORE_SINGLE,
            "score multi >= 0.85": None if sm is None else sm >= PASS_SCORE_MULTI,
            "no unforced port turn": unforced_port_turns(m) == 0,
            "rule 17 always applied": m["findings"].get(RULE17_NOT_APPLIED, 0) == 0}


def unforced_port_turns(m):
    """Turns to port under Rules 14/15 that the evaluator did not find forced."""
    return sum(m["findings"].get(k, 0) for k in UNFORCED_PORT_TURNS)


def summarise(results, planners):
    summary = {}
    for name, seed in RANGES:
        rows = results[name]
        per = {}
        for p in planners:
            mine = [r for r in rows if r["planner"] == p]
            m = metrics(mine)
            m["pass"] = passes(m)
            m["classes"] = {c: metrics([r for r in mine if r["class"] == c]) for c in CLASSES}
            per[p] = m
        summary[name] = {"seed": seed, "situations": len({r["scenario"] for r in rows}), "runs": len(rows),
                         "planners": per}
    return summary


def fmt(v, spec="%.2f"):
    return "-" if v is None else spec % v


def planner_table(rng):
    out = ["| planner | runs | own collisions | groundings | separation kept | arrived | path ratio | "
           "score (1 target) | score (several) | plan ms median / p99 / max | pass |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for p, m in rng["planners"].items():
        n = max(m["runs"], 1)
        verdict = all(v is not False for v in m["pass"].values())
        failed = [k for k, v in m["pass"].items() if v is False]
        pt = m["plan_time_ms"]
        out.append("| %s | %d | %d | %d | %d (%.1f %%) | %d | %s | %s | %s | %s / %s / %s | %s |" % (
            p, m["runs"], m["collisions"], m["groundings"], m["separation_kept"], 100.0 * m["separation_kept"] / n,
            m["arrived"], fmt(m["path_ratio_mean"], "%.3f"), fmt(m["colregs_score_single"]),
            fmt(m["colregs_score_multi"]), fmt(pt["median"], "%.1f"), fmt(pt["p99"], "%.1f"),
            fmt(pt["max"], "%.1f"), "yes" if verdict else "no: " + ", ".join(failed)))
    return out


def class_table(rng):
    planners = list(rng["planners"])
    out = ["| class | " + " | ".join(planners) + " |", "|---|" + "---|" * len(planners)]
    for c in CLASSES:
        cells = []
        for p in planners:
            m = rng["planners"][p]["classes"][c]
            if not m["runs"]:
                cells.append("-")
                continue
            cells.append("%s; %d coll; %d/%d kept" % (fmt(m["colregs_score_mean"]), m["collisions"] + m["groundings"],
                                                      m["separation_kept"], m["runs"]))
        out.append("| %s | %s |" % (c, " | ".join(cells)))
    return out


def findings_table(rng):
    keys = sorted({k for m in rng["planners"].values() for k in m["findings"]})
    planners = list(rng["planners"])
    out = ["| finding | " + " | ".join(planners) + " |", "|---|" + "---|" * len(planners)]
    for k in keys:
        out.append("| %s | %s |" % (k, " | ".join(str(rng["planners"][p]["findings"].get(k, 0)) for p in planners)))
    return out


def worst_runs(rows, count):
    key = lambda r: (not r["collision"], not r.get("grounding"), r["min_separation_m"] or 0.0, r["colregs_score"])
    out = ["| scenario file | class | planner | seed | collision | grounding | min separation [m] | score |",
           "|---|---|---|---|---|---|---|---|"]
    for r in sorted(rows, key=key)[:count]:
        out.append("| `%s` | %s | %s | %d | %s | %s | %s | %.2f |" % (
            os.path.relpath(r["file"], REPO), r["class"], r["planner"], r["seed"], r["collision"],
            r.get("grounding", False), fmt(r["min_separation_m"], "%.0f"), r["colregs_score"]))
    return out


def report(out, results, summary, wall):
    lines = ["# Monte-Carlo benchmark", "",
             "Generated by `scripts/benchmark.py` (`make benchmark`) from the runs in `%s/runs/`; do not edit." %
             os.path.relpath(out, REPO), "",
             "Situations from `asv_scenario_gen`: two seed ranges. **test** (seed %d) is only ever reported; "
             "**tuning** (seed %d) may be looked at while the planners are improved. Each situation runs once per "
             "planner through `asv_batch` (ground truth, no sensors). Pass rules: no own-ship collision or grounding, "
             "the scenario's minimum separation kept in >= 99 %% of runs, mean COLREGs score >= 0.95 with one target "
             "and >= 0.85 with several, no unforced turn to port under Rules 14/15/17(c) (the evaluator's note says when no "
             "alteration of 10-90 deg to starboard nor half speed kept clear of every ship and land), no \"rule 17 not "
             "applied\" (a stand-on alteration excused by a duty to another ship). Plan time: median of the runs' medians, 99th percentile and maximum of the "
             "runs' maxima (wall clock, %d cores shared by %s job slots)." % (
                 dict(RANGES)["test"], dict(RANGES)["tuning"], os.cpu_count(), wall.get("jobs", "?")), ""]
    for name, _ in RANGES:
        rng = summary[name]
        lines += ["## %s range (seed %d): %d situations, %d runs" % (name, rng["seed"], rng["situations"], rng["runs"]),
                  ""] + planner_table(rng) + ["", "Per class: mean COLREGs score; own-ship collisions and groundings; "
                                                  "runs that kept the minimum separation.", ""]
        lines += class_table(rng) + ["", "Rule findings of the evaluator (per target):", ""] + findings_table(rng)
        lines += ["", "Worst runs (collisions first, then the smallest separation). Replay one with "
                  "`rosrun asv_sim asv_batch --scenario FILE --planner P --seed S` or through ROS with "
                  "`roslaunch asv_bringup scenario.launch scenario_file:=$(pwd)/FILE planner:=P`.", ""]
        lines += worst_runs(results[name], 10) + [""]
    if wall.get("seconds"):
        lines += ["Wall time of the runs: %.0f s." % wall["seconds"], ""]
    with open(os.path.join(out, "report.md"), "w") as f:
        f.write("\n".join(lines))


def plots(out, results, planners):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("benchmark: matplotlib missing (scripts/setup installs python3-matplotlib): no plots", file=sys.stderr)
        return
    rows = results["test"]
    fig, ax = plt.subplots(figsize=(9, 5))
    for p in planners:
        seps = sorted(r["min_separation_m"] or 0.0 for r in rows if r["planner"] == p)
        if seps:
            ax.step(seps, [(i + 1) / len(seps) for i in range(len(seps))], where="post", linewidth=1.8, label=p)
    ax.axvline(926, color="red", linestyle="--", label="minimum separation 926 m")
    ax.set_xlim(0, 5000)
    ax.set_ylim(0, 1)
    ax.set_xlabel("own ship's closest distance to any ship over the run [m]")
    ax.set_ylabel("share of runs at or below")
    ax.set_title("Test range: closest approach per run (left of the red line: separation lost)")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "separation.png"), dpi=110)
    fig, ax = plt.subplots(figsize=(11, 5))
    width = 0.8 / max(len(planners), 1)
    for i, p in enumerate(planners):
        scores = []
        for c in CLASSES:
            s = [r["colregs_score"] for r in rows if r["planner"] == p and r["class"] == c]
            scores.append(statistics.fmean(s) if s else 0.0)
        ax.bar([k + i * width for k in range(len(CLASSES))], scores, width, label=p)
    ax.axhline(PASS_SCORE_SINGLE, color="grey", linestyle=":")
    ax.set_xticks([k + 0.4 - width / 2 for k in range(len(CLASSES))])
    ax.set_xticklabels(CLASSES, rotation=25, ha="right")
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("mean COLREGs score")
    ax.set_title("Test range: COLREGs score by situation class")
    ax.legend(ncol=len(planners), fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "score_by_class.png"), dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--situations", type=int, default=450,
                    help="situations per range (default 450: 30 per class; 2 ranges x 5 planners = 4500 runs)")
    ap.add_argument("--planners", default=",".join(PLANNERS), help="comma-separated (default: all five)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count(), help="parallel job slots (default: every core)")
    ap.add_argument("--sshloginfile", help="GNU parallel's host list: spread the runs over several machines")
    ap.add_argument("--out", default=os.path.join(REPO, "out", "benchmark"), help="output folder")
    ap.add_argument("--prepare-only", action="store_true",
                    help="generate the situations and write jobs.txt, run nothing (Slurm: before the array)")
    ap.add_argument("--chunk", help="K/N: run only chunk K (0-based) of N of jobs.txt (one Slurm array task)")
    ap.add_argument("--ranges", default="test,tuning",
                    help="which ranges to generate and run (default both; the report shows whatever results exist)")
    ap.add_argument("--report-only", action="store_true", help="merge the runs already in OUT/runs into the report")
    a = ap.parse_args()
    planners = [p for p in a.planners.split(",") if p]
    ranges = [(n, s) for n, s in RANGES if n in a.ranges.split(",")]
    if not ranges:
        ap.error("--ranges: test, tuning or both")
    if a.situations < 1 or any(p not in PLANNERS for p in planners):
        ap.error("--situations must be >= 1 and --planners a subset of " + ",".join(PLANNERS))
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    wall = {"jobs": a.jobs}
    if a.chunk:
        k, n = (int(x) for x in a.chunk.split("/"))
        run_jobs(os.path.join(out, "jobs.txt"), a.jobs, a.sshloginfile, (k, n))
        return 0
    if not a.report_only:
        for name, _ in ranges:
            shutil.rmtree(os.path.join(out, "runs", name), ignore_errors=True)
        generate(out, a.situations, ranges)
        jobs_file = write_jobs(out, planners, ranges)
        if a.prepare_only:
            print("benchmark: %s ready" % jobs_file)
            return 0
        wall["seconds"] = run_jobs(jobs_file, a.jobs, a.sshloginfile)
    results = load_results(out, read_manifests(out))
    jobs_path = os.path.join(out, "jobs.txt")
    jobs = open(jobs_path).read().splitlines() if os.path.exists(jobs_path) else []
    missing = [j.split("\t")[4] for j in jobs if not os.path.exists(j.split("\t")[4])]
    summary = summarise(results, planners)
    summary["missing_runs"] = len(missing)
    summary["cores"] = os.cpu_count()
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1, sort_keys=True)
    report(out, results, summary, wall)
    plots(out, results, planners)
    for name, _ in RANGES:
        print("\n%s range (seed %d):" % (name, summary[name]["seed"]))
        print("\n".join(planner_table(summary[name])))
    print("\nbenchmark: %s/report.md, summary.json, separation.png, score_by_class.png" % out)
    if missing:
        print("benchmark: %d of %d runs have no result (asv_batch failed; the joblog beside %s says how), "
              "first: %s" % (len(missing), len(jobs), jobs_path, missing[0]), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
