#!/usr/bin/python3
"""Whole-pipeline rostest on generated situations nobody tuned the planners for.

asv_scenario_gen writes situations 0..9 of the Monte-Carlo benchmark's test range (seed 7919: one of
each of its first ten classes in asv_scenario_gen --list-classes order), each cut to 10 minutes after its last unaltered CPA so
that the run ends once the encounters are over. Each runs with one planner, the five in turn (situation i
with PLANNERS[i mod 5], so every planner meets two classes), through scenario.launch in
lockstep (sim_node -> NMEA -> ais_node/arpa_node -> tracker -> risk_node -> planner_node) and once
through asv_batch (ground truth, in process). Pass rules, as the benchmark's (docs/evaluation.md): the
own ship touches no ship and no land and keeps the scenario's minimum separation; and the ROS run and
the batch run agree in class (collision, separation kept, arrived).

Run by rostest (test/generated.test), which provides the master. Environment: ASV_GENERATED_ONLY
(comma-separated situation indices), ASV_PLANNERS_ONLY (comma-separated planners: each situation with
every one of them instead of one in turn).
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

import rosunit
import yaml

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))  # batch_result.py lies next to this file
from batch_result import batch_result  # noqa: E402

SEED = 7919  # the benchmark's test range (scripts/benchmark.py RANGES)
SITUATIONS = range(10)
# In turn over the situations: every planner goes through ROS on two of them (asv_batch runs every planner
# on every situation in the benchmark; here the question is whether ROS and batch agree).
PLANNERS = ["mopso", "dssa_plus", "aco", "ga", "dssa"]
KNOT = 1852.0 / 3600.0


def velocity(ship):
    speed = ship["speed_kn"] * KNOT
    c = math.radians(ship["course_deg"])
    return speed * math.sin(c), speed * math.cos(c)


def last_cpa(scenario):
    """[s] the latest CPA of a target with the own ship, both holding course and speed (hand formula)."""
    own = scenario["own_ship"]
    ox, oy = own["position"]["x_m"], own["position"]["y_m"]
    ovx, ovy = velocity(own)
    latest = 0.0
    for t in scenario["targets"]:
        rx, ry = t["position"]["x_m"] - ox, t["position"]["y_m"] - oy
        tvx, tvy = velocity(t)
        vx, vy = tvx - ovx, tvy - ovy
        if vx * vx + vy * vy > 1e-9:
            latest = max(latest, -(rx * vx + ry * vy) / (vx * vx + vy * vy))
    return latest


def generate(folder):
    """The situations, each cut to its last CPA + 600 s; {index: (path, scenario dict)}."""
    subprocess.run(["rosrun", "asv_core", "asv_scenario_gen", "--out", folder, "--seed", str(SEED), "--count",
                    str(len(SITUATIONS)), "--quiet"], check=True)
    out = {}
    with open(os.path.join(folder, "manifest.tsv")) as f:
        files = [row.split("\t")[0] for row in f.read().splitlines()[1:]]
    for index, name in enumerate(files):
        path = os.path.join(folder, name)
        with open(path) as f:
            text = f.read()
        scenario = yaml.safe_load(text)
        cut = min(scenario["duration_s"], math.ceil(last_cpa(scenario) + 600.0))
        with open(path, "w") as f:
            f.write(re.sub(r"^duration_s: .*$", "duration_s: %d" % cut, text, count=1, flags=re.M))
        scenario["duration_s"] = cut
        out[index] = (path, scenario)
    return out


def classes(r):
    return {"collision": r["collision"], "grounding": r.get("grounding", False),
            "separation kept": not r["safety_violation"], "arrived": r["arrived"]}


def run_ros(path, planner, seed):
    out = tempfile.mkdtemp(prefix="asv_gen_ros_")
    result = os.path.join(out, "result.json")
    cmd = ["roslaunch", "asv_bringup", "scenario.launch", "scenario_file:=" + path, "planner:=" + planner,
           "seed:=%d" % seed, "lockstep:=true", "out:=" + out, "result:=" + result, "output:=log"]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=600)
    log = proc.stdout.decode(errors="replace")
    if proc.returncode != 0 or not os.path.exists(result):
        raise AssertionError("scenario.launch failed:\n" + log[-3000:])
    with open(result) as f:
        return json.load(f)


class Generated(unittest.TestCase):
    pass


def make_test(index, path, scenario, planner):
    def test(self):
        seed = SEED + index
        ros = run_ros(path, planner, seed)
        batch = batch_result(path, "--planner", planner, "--seed", str(seed), timeout=600)
        what = "situation %d (%s) with %s:\nROS   %s\nbatch %s" % (index, scenario["name"], planner, json.dumps(ros),
                                                                  json.dumps(batch))
        threshold = scenario["safety"]["min_separation_m"]
        self.assertFalse(ros["collision"], "own ship collided: " + what)
        self.assertFalse(ros.get("grounding", False), "own ship grounded: " + what)
        self.assertGreaterEqual(ros["min_separation_m"], threshold, "minimum separation lost: " + what)
        self.assertEqual(classes(ros), classes(batch), "ROS and batch disagree: " + what)
    return test


def main():
    only = [int(s) for s in os.environ.get("ASV_GENERATED_ONLY", "").split(",") if s]
    planners = [p for p in os.environ.get("ASV_PLANNERS_ONLY", "").split(",") if p]
    situations = generate(tempfile.mkdtemp(prefix="asv_generated_"))
    for index, (path, scenario) in situations.items():
        if only and index not in only:
            continue
        for planner in planners or [PLANNERS[index % len(PLANNERS)]]:
            name = "test_%02d_%s_%s" % (index, scenario["name"].split("_s%d" % SEED)[0][len("gen_"):], planner)
            setattr(Generated, name, make_test(index, path, scenario, planner))
    rosunit.unitrun("asv_bringup", "generated_situations", Generated, sys.argv)


if __name__ == "__main__":
    main()
