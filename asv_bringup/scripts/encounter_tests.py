#!/usr/bin/python3
"""Whole-pipeline rostest: each planner on each standard encounter of the scenario library.

For every (encounter, planner) pair, scenario.launch runs the scenario through the real pipeline
(sim_node -> NMEA -> ais_node/arpa_node -> tracker -> risk_node -> planner_node -> autopilot) in
lockstep (every node processes each simulation step before the next: the same decisions on every run
and machine) until 300 s after the unaltered CPA, and the evaluator's result JSON must show:
  - no collision, and a minimum separation above the scenario's safety.min_separation_m;
  - role-correct behaviour (COLREGs), checked here from the manoeuvres independently of the score:
      give-way, head-on (Rule 14) and crossing (Rules 15, 16): the first alteration is to starboard;
      overtaking (Rule 13): the overtaking ship keeps out of the way (either side) - passes clear;
      stand-on, crossing (Rule 17) and being overtaken (Rule 17): no alteration before the CPA.

Numeric hygiene: while the runs go, every message on the pipeline's topics (odometry, NMEA-derived
targets, tracks, risk, plans, set-points, events) is walked field by field: no NaN or infinite value
may appear on any of them.

Run by rostest (test/encounters.test), which provides the master. Environment: ASV_ENCOUNTERS_ONLY
(comma-separated scenario names), ASV_PLANNERS_ONLY (comma-separated planners).
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import math
import threading

import rospkg
import rospy
import rosunit
import yaml
from asv_msgs.msg import CourseSpeedSetpoint, Plan, RiskAssessment, SimEvent, TargetArray
from nav_msgs.msg import Odometry

PLANNERS = ["aco", "ga", "mopso", "dssa", "dssa_plus"]
# scenario -> (own role, [s] TCPA of the unaltered encounter at t = 0, from the scenario geometry:
# range / closing speed, e.g. head-on 7 nm at 24 kn = 1050 s)
ENCOUNTERS = {
    "head_on": ("give_way_starboard", 1050.0),
    "crossing_give_way": ("give_way_starboard", 1484.9),
    "overtaking": ("give_way", 2700.0),
    "crossing_stand_on": ("stand_on", 1484.9),
    "being_overtaken": ("stand_on", 2700.0),
}




TOPICS = [("/own/odom", Odometry), ("/ts1/odom", Odometry), ("/ais/targets", TargetArray),
          ("/arpa/targets", TargetArray), ("/targets", TargetArray), ("/risk", RiskAssessment),
          ("/own/plan", Plan), ("/own/cmd", CourseSpeedSetpoint), ("/sim/events", SimEvent),
          ("/sim/ships", TargetArray)]


def non_finite(msg, path=""):
    """Paths of the float fields of msg (recursively) that are NaN or infinite.

    The checker walks every message of a run (60,000 odometry messages in a 3000 s run, with 72 covariance
    values each): a float array is tested in one pass and the paths are only built for a value that fails,
    which keeps the walk from taking a fifth of the run's CPU from the pipeline it watches."""
    if isinstance(msg, float):
        return [] if math.isfinite(msg) else [path]
    if isinstance(msg, (list, tuple)):
        if not msg or (isinstance(msg[0], float) and all(map(math.isfinite, msg))):
            return []
        bad = []
        for i, m in enumerate(msg):
            bad += non_finite(m, "%s[%d]" % (path, i))
        return bad
    bad = []
    for slot in getattr(msg, "__slots__", ()):
        v = getattr(msg, slot)
        if isinstance(v, float):
            if not math.isfinite(v):
                bad.append(path + "." + slot)
        elif not isinstance(v, (int, str, bytes)):
            bad += non_finite(v, path + "." + slot)
    return bad


class NumericChecker:
    def __init__(self):
        self.lock = threading.Lock()
        self.reset()
        self.subs = [rospy.Subscriber(t, c, self.check, callback_args=t, queue_size=1000) for t, c in TOPICS]

    def reset(self):
        with getattr(self, "lock", threading.Lock()):
            self.count = 0
            self.bad = []

    def check(self, msg, topic):
        b = non_finite(msg)
        with self.lock:
            self.count += 1
            if b and len(self.bad) < 20:
                self.bad.append("%s: %s" % (topic, ", ".join(b[:5])))


CHECKER = None


class Encounters(unittest.TestCase):
    pass


def make_test(scenario, path, planner, role, tcpa):
    def test(self):
        with open(path) as f:
            threshold = float(yaml.safe_load(f).get("safety", {}).get("min_separation_m", 926.0))
        out = tempfile.mkdtemp(prefix="asv_enc_")
        result = os.path.join(out, "result.json")
        cmd = ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=" + scenario, "planner:=" + planner,
               "lockstep:=true", "max_sim_time:=%g" % (tcpa + 300.0), "out:=" + out, "result:=" + result,
               "output:=log"]
        CHECKER.reset()
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
        log = proc.stdout.decode(errors="replace")
        self.assertEqual(proc.returncode, 0, "roslaunch failed:\n" + log[-3000:])
        self.assertTrue(os.path.exists(result), "no result JSON:\n" + log[-3000:])
        with open(result) as f:
            r = json.load(f)
        self.assertGreater(CHECKER.count, 100, "the numeric checker received nothing")
        self.assertEqual(CHECKER.bad, [], "non-finite values published")
        what = "%s/%s: %s" % (scenario, planner, json.dumps(r))
        self.assertFalse(r["collision"], what)
        self.assertGreater(r["min_separation_m"], threshold, what)
        cpa_t = r["targets"][0]["tcpa_at_start_s"]
        turns = [m for m in r["manoeuvres"] if m["t_s"] < cpa_t]
        if role == "give_way_starboard":
            self.assertTrue(turns, "no alteration before the CPA: " + what)
            self.assertGreater(turns[0]["course_change_deg"], 0.0, "first alteration to port: " + what)
        elif role == "stand_on":
            self.assertEqual(turns, [], "the stand-on ship altered before the CPA: " + what)
    return test


def main():
    global CHECKER
    rospy.init_node("encounter_tests", anonymous=True, disable_signals=True)
    CHECKER = NumericChecker()
    root = rospkg.RosPack().get_path("asv_bringup")
    only = [s for s in os.environ.get("ASV_ENCOUNTERS_ONLY", "").split(",") if s]
    planners = [p for p in os.environ.get("ASV_PLANNERS_ONLY", "").split(",") if p] or PLANNERS
    for scenario, (role, tcpa) in ENCOUNTERS.items():
        if only and scenario not in only:
            continue
        path = os.path.join(root, "scenarios", scenario + ".yaml")
        for planner in planners:
            setattr(Encounters, "test_%s_%s" % (scenario, planner), make_test(scenario, path, planner, role, tcpa))
    rosunit.unitrun("asv_bringup", "standard_encounters", Encounters, sysargs=sys.argv)


if __name__ == "__main__":
    main()
