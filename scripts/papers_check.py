#!/usr/bin/python3
"""scripts/papers.py and what it claims, as one JUnit test case (make test counts it).

Usage: papers_check.py OUT.xml
Checks:
  tolerance  the 95 % Clopper-Pearson interval against textbook values (20/20: 0.832-1; 0/20: 0-0.168;
             10/20: 0.272-0.728) and that a comparison is two-sided: 20/20 against the paper's 1/20 is
             outside, as is 10.0 against 5.0 +-2, while 20/20 against 17/20 is within;
  rows       a full run (every paper, about 30 s on 2 cores) writes summary.json rows with exactly the
             keys paper, experiment, metric, paper_value, ours, tolerance, within, kind, for all four
             papers; every kind is reproduced, calibration or self_check, and the rows that compare
             with our own numbers (Hu et al.'s closest approaches against our d_min, the flag time from
             our geometry, Fig. 6's inferred side) are self_check and the rows Hirayama et al.'s Table 1
             geometry and Lazarowska's paper-mode grid cell are fitted to are calibration;
  claims     the rows the results pages say we reproduce are within tolerance: Hu et al. Fig. 4(a)/(b)
             sides and Fig. 6 (flag at 300 s by hand, no alteration before it, evasion at once),
             Hirayama et al. Table 3 DSSA and Table 2 DSSA+ s=c and s>c success counts, Lazarowska Scenario 1's
             first alteration to starboard, Wu et al. collision-free;
  docs       the generated block of each docs/results/<paper>.md equals the fresh run's (apart from the
             line with the run's wall time): no number on those pages is typed by hand or stale.
Needs the catkin environment (source devel/setup.bash). Exit status 1 on a finding.
"""
import json
import os
import re
import subprocess
import sys
import tempfile

import junit_case

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from paperlib import common  # noqa: E402

KEYS = ["paper", "experiment", "metric", "paper_value", "ours", "tolerance", "within", "kind"]
# Rows that compare with our own numbers, not the paper's: they must say so (kind self_check).
SELF_CHECKS = [
    ("Hu et al. 2017", "Fig. 4(a) overtaking, open water", "closest approach [m] (design DCPA d_min)"),
    ("Hu et al. 2017", "Fig. 4(b) overtaking, land to starboard", "closest approach [m] (design DCPA d_min)"),
    ("Hu et al. 2017", "Fig. 6 non-compliant give-way target", "closest approach [m] (design DCPA d_min)"),
    ("Hu et al. 2017", "Fig. 6 non-compliant give-way target", "flag time [s] (Algorithm 1, by hand)"),
    ("Hu et al. 2017", "Fig. 6 non-compliant give-way target", "avoiding alterations, sides in order"),
]
# Rows whose paper value an unstated value of ours was fitted to: they must say so (kind calibration).
CALIBRATIONS = [
    ("Hirayama et al. 2019", "Table 1, DSSA", "total length of paths"),  # the two ships' offset
    ("Hirayama et al. 2019", "Table 1, DSSA", "detour rate of each ship"),
    ("Hirayama et al. 2019", "Table 1, DSSA+ s>c", "total length of paths"),  # their straight length
    ("Lazarowska 2015", "Scenario 1 (Table 3)", "alteration 1 [deg, + starboard] (planned)"),  # the grid cell
    ("Lazarowska 2015", "Scenario 1 (Table 3)", "alteration 2 [deg, + starboard] (planned)"),
]
CLAIMS = [
    ("Hu et al. 2017", "Fig. 4(a) overtaking, open water", "avoiding alterations, sides in order"),
    ("Hu et al. 2017", "Fig. 4(b) overtaking, land to starboard", "avoiding alterations, sides in order"),
    ("Hu et al. 2017", "Fig. 6 non-compliant give-way target", "flag time [s] (Algorithm 1, by hand)"),
    ("Hu et al. 2017", "Fig. 6 non-compliant give-way target", "alterations before the flag (stand on, Rule 17(a)(i))"),
    ("Hu et al. 2017", "Fig. 6 non-compliant give-way target", "first alteration after the flag [s after it]"),
    ("Hirayama et al. 2019", "Table 3, DSSA", "success rate"),
    ("Hirayama et al. 2019", "Table 2, DSSA+ s=c", "success rate"),
    ("Hirayama et al. 2019", "Table 2, DSSA+ s>c", "success rate"),  # arrived ships stay, MinSPD RefSPD / 2
    ("Lazarowska 2015", "Scenario 1 (Table 3)", "alteration 1 side (planned)"),
    ("Wu et al. 2022", "all", "collision-free"),
]


def check_tolerance(report):
    for (k, n), (lo, hi) in {(20, 20): (0.8316, 1.0), (0, 20): (0.0, 0.1684), (10, 20): (0.2720, 0.7280)}.items():
        got = common.clopper_pearson(k, n)
        if abs(got[0] - lo) > 5e-4 or abs(got[1] - hi) > 5e-4:
            report("Clopper-Pearson %d/%d: %.4f-%.4f, expected %.4f-%.4f" % (k, n, got[0], got[1], lo, hi))
    if common.count_row("p", "e", "m", 1, 20, 20, 20)["within"]:
        report("20/20 counted as within the paper's 1/20: the comparison is not two-sided")
    if not common.count_row("p", "e", "m", 17, 20, 20, 20)["within"]:  # 0.85 lies in 0.832-1
        report("20/20 counted as outside the paper's 17/20")
    if common.band_row("p", "e", "m", 5.0, 10.0, 2.0)["within"] or not common.band_row("p", "e", "m", 5.0, 6.5, 2.0)["within"]:
        report("band_row: 10 within 5 +-2 or 6.5 outside it")


def generated(page):
    """The generated block of a page without its wall-time line."""
    text = open(page).read()
    b, e = common.begin_marker("results"), common.end_marker("results")
    if b not in text or e not in text:
        return None
    block = text[text.index(b):text.index(e)]
    return re.sub(r"^Generated by .*$", "", block, flags=re.M)


def check_run(tmp, report):
    docs = os.path.join(tmp, "docs")
    os.makedirs(docs)
    for p in ("aco", "dssa", "mopso", "ga"):
        with open(os.path.join(ROOT, "docs", "results", p + ".md")) as f, open(os.path.join(docs, p + ".md"), "w") as g:
            g.write(f.read())
    proc = subprocess.run([os.path.join(HERE, "papers.py"), "--out-dir", tmp, "--docs", docs],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if proc.returncode != 0:
        report("papers.py failed (%d):\n%s" % (proc.returncode, proc.stdout.decode()[-3000:]))
        return
    rows = json.load(open(os.path.join(tmp, "summary.json")))
    papers = {r["paper"] for r in rows}
    if len(papers) != 4:
        report("summary.json has rows for %s, not the four papers" % sorted(papers))
    for r in rows:
        if list(r.keys()) != KEYS:
            report("row keys %s, expected %s" % (list(r.keys()), KEYS))
            break
    index = {(r["paper"], r["experiment"], r["metric"]): r for r in rows}
    for r in rows:
        if r.get("kind") not in common.KINDS:
            report("row kind %r is not one of %s: %s" % (r.get("kind"), common.KINDS, json.dumps(r)))
            break
    for c in SELF_CHECKS:
        if c in index and index[c]["kind"] != "self_check":
            report("a comparison with our own number is labelled %s: %s" % (index[c]["kind"], c))
    for c in CALIBRATIONS:
        if c in index and index[c]["kind"] != "calibration":
            report("a row fitted to the paper is labelled %s: %s" % (index[c]["kind"], c))
    for c in CLAIMS:
        r = index.get(c)
        if r is None:
            report("no row %s" % (c,))
        elif not r["within"]:
            report("claimed reproduced, but outside tolerance: %s" % json.dumps(r))
    for p in ("aco", "dssa", "mopso", "ga"):
        fresh, kept = generated(os.path.join(docs, p + ".md")), generated(os.path.join(ROOT, "docs", "results", p + ".md"))
        if kept is None:
            report("docs/results/%s.md has no generated block (make papers)" % p)
        elif fresh != kept:
            report("docs/results/%s.md differs from a fresh run: run make papers and commit the pages" % p)


def main():
    with tempfile.TemporaryDirectory(prefix="papers_check.") as tmp:
        return junit_case.run(__doc__, "papers", "papers_check",
                              [check_tolerance, lambda report: check_run(tmp, report)],
                              "tolerances, rows, claims and pages all right")


if __name__ == "__main__":
    sys.exit(main())
