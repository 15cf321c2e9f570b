"""Shared parts of the paper reproductions: running asv_batch, comparison rows with their tolerances,
and the generated blocks of docs/results/*.md.

A row compares one of our numbers with the paper's, two-sided: better than the paper is outside the
tolerance just like worse, since a reproduction that beats the paper does not reproduce it.
"""
import csv
import json
import math
import os
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENARIOS = os.path.join(ROOT, "asv_bringup", "scenarios")


class Job:
    """One asv_batch call: a scenario, the own ship's planner, a seed range and parameter overrides."""

    def __init__(self, key, scenario, planner, seeds=1, first_seed=1, sets=(), agents=None, risk=False, sample=5.0,
                 follower=(), plans=False, trajectory=False):
        self.key, self.scenario, self.planner, self.sample = key, scenario, planner, sample
        self.follower = list(follower)
        self.seeds, self.first_seed, self.sets, self.agents, self.risk = seeds, first_seed, list(sets), agents, risk
        # Extra CSVs of the first seed's run (asv_batch --plans, --trajectory), as lists of row dicts.
        self.extra = {name: [] for name, on in (("plans", plans), ("trajectory", trajectory)) if on}
        self.runs, self.risk_rows, self.wall = [], [], 0.0

    def command(self, batch, workdir):
        out = os.path.join(workdir, self.key + ".jsonl")
        cmd = [batch, "--scenario", os.path.join(SCENARIOS, self.scenario + ".yaml"), "--planner", self.planner,
               "--runs", str(self.seeds), "--seed", str(self.first_seed), "--deterministic", "--quiet",
               "--json", out, "--sample-period", "%g" % self.sample]
        for s in self.sets:
            cmd += ["--set", s]
        for f in self.follower:
            cmd += ["--follower", f]
        if self.agents:
            cmd += ["--agents", self.agents]
        if self.risk:
            cmd += ["--risk", os.path.join(workdir, self.key + "_risk.csv")]
        for name in self.extra:
            cmd += ["--" + name, os.path.join(workdir, "%s_%s.csv" % (self.key, name))]
        return cmd, out

    def _first_seed_csv(self, path):
        """asv_batch names a CSV of several runs per seed: the first seed's."""
        if self.seeds > 1:
            root, ext = os.path.splitext(path)
            path = "%s_seed%d%s" % (root, self.first_seed, ext)
        with open(path) as f:
            return list(csv.DictReader(f))

    def run(self, batch, workdir):
        cmd, out = self.command(batch, workdir)
        t0 = time.time()
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        self.wall = time.time() - t0
        if proc.returncode != 0:
            raise RuntimeError("%s failed (%d):\n%s" % (" ".join(cmd), proc.returncode, proc.stdout.decode()))
        with open(out) as f:
            self.runs = [json.loads(line) for line in f if line.strip()]
        if self.risk:
            self.risk_rows = self._first_seed_csv(os.path.join(workdir, self.key + "_risk.csv"))
        for name in self.extra:
            self.extra[name] = self._first_seed_csv(os.path.join(workdir, "%s_%s.csv" % (self.key, name)))
        return self


def run_jobs(jobs, batch, workers, workdir, log=print):
    """Runs every job, `workers` asv_batch processes at once, with a progress line per finished job."""
    t0 = time.time()
    with ThreadPoolExecutor(max_workers=max(1, workers)) as pool:
        futures = [pool.submit(j.run, batch, workdir) for j in jobs]
        for k, fut in enumerate(futures):
            j = fut.result()
            log("[%3d/%d] %-34s %3d run(s) %6.1f s  (%.0f s in all)" %
                (k + 1, len(jobs), j.key, len(j.runs), j.wall, time.time() - t0))


# ---------------------------------------------------------------------------------------------------
# Rows

def _binom_cdf(k, n, p):
    if k < 0:
        return 0.0
    if k >= n:
        return 1.0
    return sum(math.comb(n, i) * p ** i * (1.0 - p) ** (n - i) for i in range(k + 1))


def clopper_pearson(k, n, confidence=0.95):
    """Exact (Clopper-Pearson) two-sided interval of a binomial proportion k/n, found by bisection on the
    binomial distribution function: lower = the p with P(X >= k) = a/2, upper = the p with P(X <= k) = a/2."""
    a = 1.0 - confidence

    def solve(f):  # f increasing in p on [0, 1]
        lo, hi = 0.0, 1.0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if f(mid) < 0.0 else (lo, mid)
        return 0.5 * (lo + hi)

    lower = 0.0 if k == 0 else solve(lambda p: (1.0 - _binom_cdf(k - 1, n, p)) - a / 2)
    upper = 1.0 if k == n else solve(lambda p: a / 2 - _binom_cdf(k, n, p))
    return lower, upper


# What a row's "paper" value is: a number the paper prints and nothing was fitted to (reproduced), one we
# fitted an unstated value of ours to (calibration), or not the paper's at all: a value of our own
# geometry or parameters, or one the text leaves to inference (self_check). Only reproduced rows count
# as reproduced.
KINDS = ("reproduced", "calibration", "self_check")


def row(paper, experiment, metric, paper_value, ours, tolerance, within, kind="reproduced"):
    if kind not in KINDS:
        raise ValueError("row kind %r is not one of %s" % (kind, KINDS))
    return {"paper": paper, "experiment": experiment, "metric": metric, "paper_value": paper_value,
            "ours": ours, "tolerance": tolerance, "within": bool(within), "kind": kind}


def count_row(paper, experiment, metric, k_paper, n_paper, k_ours, n_ours, kind="reproduced"):
    """A success count: within when the paper's proportion lies in the 95 % Clopper-Pearson interval of ours."""
    lo, hi = clopper_pearson(k_ours, n_ours)
    p = k_paper / n_paper
    return row(paper, experiment, metric, "%d/%d" % (k_paper, n_paper), "%d/%d" % (k_ours, n_ours),
               "binomial 95 %%: %.2f-%.2f" % (lo, hi), lo - 1e-12 <= p <= hi + 1e-12, kind)


def band_row(paper, experiment, metric, paper_value, ours, band, unit="", relative=False, kind="reproduced"):
    """A number within +-band of the paper's (band a fraction of the paper's value when relative)."""
    if ours is None or (isinstance(ours, float) and not math.isfinite(ours)):
        return row(paper, experiment, metric, paper_value, None, _band_text(band, unit, relative), False, kind)
    width = band * abs(paper_value) if relative else band
    return row(paper, experiment, metric, paper_value, round(ours, 3), _band_text(band, unit, relative),
               abs(ours - paper_value) <= width + 1e-9, kind)


def _band_text(band, unit, relative):
    return "+-%g %%" % (100 * band) if relative else "+-%g%s" % (band, (" " + unit) if unit else "")


def exact_row(paper, experiment, metric, paper_value, ours, kind="reproduced"):
    return row(paper, experiment, metric, paper_value, ours, "exact", paper_value == ours, kind)


def tally(rows):
    """{kind: (within, rows)} of a paper's rows."""
    return {k: (sum(r["within"] for r in rows if r["kind"] == k), sum(r["kind"] == k for r in rows)) for k in KINDS}


def tally_text(rows):
    """The pages' and the log's count: reproduced rows first, then the others apart."""
    t = tally(rows)
    text = "%d of %d reproduced rows within tolerance" % t["reproduced"]
    for k, name in (("calibration", "calibration"), ("self_check", "self-check")):
        if t[k][1]:
            text += "; %d of %d %s rows" % (t[k][0], t[k][1], name)
    return text


def knots_to_mps(kn):
    """The one knots -> m/s conversion of the paper scripts (1 kn = 1852 m / 3600 s)."""
    return kn * 1852.0 / 3600.0


def side(change_deg):
    return "starboard" if change_deg > 0 else "port"


# ---------------------------------------------------------------------------------------------------
# Documents

def fmt(v):
    if v is None:
        return "-"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, float):
        return "%.1f" % v if abs(v) >= 10 else "%.2f" % v
    return str(v)


def rows_table(rows, reasons=None):
    """Markdown table of rows; `reasons` maps (experiment, metric) to why a row is outside tolerance."""
    reasons = reasons or {}
    out = ["| experiment | metric | kind | paper | ours | tolerance | within | why, when outside |",
           "|---|---|---|---:|---:|---|---|---|"]
    for r in rows:
        why = "" if r["within"] else reasons.get((r["experiment"], r["metric"]), reasons.get(r["experiment"], ""))
        out.append("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            r["experiment"], r["metric"], r["kind"].replace("_", "-"), fmt(r["paper_value"]), fmt(r["ours"]),
            r["tolerance"], fmt(r["within"]), why))
    return out


def begin_marker(name):
    return "<!-- BEGIN scripts/papers.py %s: generated, do not edit by hand -->" % name


def end_marker(name):
    return "<!-- END scripts/papers.py %s -->" % name


def replace_block(path, name, lines):
    """Replaces the generated block `name` of a markdown page (appends it when the page has none)."""
    begin, end = begin_marker(name), end_marker(name)
    block = "\n".join([begin, ""] + lines + ["", end])
    with open(path) as f:
        page = f.read()
    if begin in page and end in page:
        page = page[:page.index(begin)] + block + page[page.index(end) + len(end):]
    else:
        page = page.rstrip("\n") + "\n\n" + block + "\n"
    with open(path, "w") as f:
        f.write(page)


def manoeuvre_courses(initial_course, manoeuvres):
    """Courses held after each manoeuvre (result `manoeuvres`: [{t_s, course_change_deg}])."""
    out, c = [], initial_course
    for m in manoeuvres:
        c = (c + m["course_change_deg"]) % 360.0
        out.append(c)
    return out
