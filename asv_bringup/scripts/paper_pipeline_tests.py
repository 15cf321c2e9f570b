#!/usr/bin/python3
"""The papers' own pipeline checks, through the whole ROS pipeline (scenario.launch):

- Hu et al. (MOPSO), the non-compliant target of Fig. 6 (scenario hu_non_compliant): no collision,
  risk_node raises the non-compliance flag for the target, and the own ship's manoeuvre starts within
  MANOEUVRE_DELAY simulated seconds of the first risk level 2 (or before it: Rule 17(a)(ii) lets the
  stand-on ship act as soon as the give-way ship is seen not to act).
- Wu et al. (GA), a crossing in which the own ship gives way (scenario crossing_give_way): no collision,
  and once the own ship has altered, the target's CRI falls below the GA's action threshold (0.61,
  section 4) before the CPA.
- The paper experiments of `make papers` through ROS, in paper mode (the scenarios' planner_params), each
  against the same scenario through asv_batch: Lazarowska (ACO) Scenario 1 (lazarowska_1: the plan made
  once and sailed; the first alteration to starboard, astern of the ship crossing from starboard, as the
  paper's 066 -> 077) and Wu et al. (GA) in port (wu_port, the 3-DOF model in the loop). ROS and batch
  must agree in outcome (collision, minimum separation kept, arrival). The GA's closest approaches must
  also agree within BAND (ROS plans from tracked AIS targets, the batch from the true states). ACO plans
  once: one plan in each, but through ROS it is made when the tracks are confirmed, minutes after the
  batch's at t = 0, and the lattice answer from there passes at another distance.

Run by rostest (test/paper_pipeline.test), which provides the master.
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import rospkg
import rospy
import rosunit
from asv_msgs.msg import RiskAssessment

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))  # batch_result.py lies next to this file
from batch_result import batch_result  # noqa: E402

EPOCH = 1.0e9  # sim_node's ROS time of simulation time 0
MANOEUVRE_DELAY = 30.0  # [s, sim] risk 2 -> the first course change: replan (<= 2 s), set-point (1 s),
#                          the evaluator's manoeuvre detection (30 s window start): documented bound
GA_CRI_THRESHOLD = 0.61
BAND = 0.25  # ROS against asv_batch, closest approach per target: tracking noise moves a plan a little


def run(scenario, planner, sim_time, risks):
    out = tempfile.mkdtemp(prefix="asv_paper_")
    result = os.path.join(out, "result.json")
    del risks[:]
    proc = subprocess.run(
        ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=" + scenario, "planner:=" + planner,
         "lockstep:=true", "max_sim_time:=%g" % sim_time, "out:=" + out, "result:=" + result,
         "output:=log"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
    log = proc.stdout.decode(errors="replace")
    if proc.returncode != 0 or not os.path.exists(result):
        raise AssertionError("run failed:\n" + log[-3000:])
    with open(result) as f:
        return json.load(f)


def batch(scenario):
    path = os.path.join(rospkg.RosPack().get_path("asv_bringup"), "scenarios", scenario + ".yaml")
    return batch_result(path, "--deterministic")


class PaperPipeline(unittest.TestCase):
    risks = []

    @classmethod
    def setUpClass(cls):
        rospy.init_node("paper_pipeline_tests", anonymous=True, disable_signals=True)
        rospy.Subscriber("/risk", RiskAssessment, lambda m: cls.risks.append(m), queue_size=1000)

    def test_hu_non_compliant_mopso(self):
        r = run("hu_non_compliant", "mopso", 1500.0, self.risks)
        what = json.dumps(r)
        self.assertFalse(r["collision"], what)
        self.assertGreater(r["min_separation_m"], 926.0, what)
        flagged = [m.header.stamp.to_sec() - EPOCH for m in self.risks if any(not t.compliant for t in m.targets)]
        self.assertTrue(flagged, "risk_node never flagged the target non-compliant")
        urgent = [m.header.stamp.to_sec() - EPOCH for m in self.risks if m.max_risk_level >= 2]
        self.assertTrue(urgent, "risk level 2 never reached")
        self.assertTrue(r["manoeuvres"], "no manoeuvre: " + what)
        first = r["manoeuvres"][0]["t_s"]
        print("hu_non_compliant: flagged at %.0f s, risk 2 at %.0f s, manoeuvre at %.0f s" %
              (flagged[0], urgent[0], first))
        self.assertLessEqual(first, urgent[0] + MANOEUVRE_DELAY, what)

    def test_wu_crossing_ga(self):
        r = run("crossing_give_way", "ga", 1800.0, self.risks)
        what = json.dumps(r)
        self.assertFalse(r["collision"], what)
        self.assertTrue(r["manoeuvres"], "no manoeuvre: " + what)
        first = r["manoeuvres"][0]["t_s"]
        cpa = r["targets"][0]["tcpa_at_start_s"]
        after = [max([t.cri for t in m.targets] or [0.0]) for m in self.risks
                 if first < m.header.stamp.to_sec() - EPOCH < cpa]
        before = [max([t.cri for t in m.targets] or [0.0]) for m in self.risks
                  if m.header.stamp.to_sec() - EPOCH <= first]
        self.assertTrue(after, "no risk assessment after the manoeuvre")
        print("crossing_give_way/ga: max CRI before the manoeuvre %.2f, lowest after %.2f" %
              (max(before or [0.0]), min(after)))
        self.assertGreater(max(before or [0.0]), GA_CRI_THRESHOLD, "the GA acted without the CRI above its threshold")
        self.assertLess(min(after), GA_CRI_THRESHOLD, "CRI never fell below the threshold: " + what)

    def agree(self, ros, ref, band=None):
        what = "ROS: %s\nbatch: %s" % (json.dumps(ros), json.dumps(ref))
        self.assertFalse(ros["collision"], what)
        for key in ("collision", "safety_violation", "arrived"):
            self.assertEqual(ros[key], ref[key], key + ": " + what)
        closest = {t["name"]: t["min_distance_m"] for t in ref["targets"]}
        for t in ros["targets"]:
            want = closest[t["name"]]
            print("%s: %s closest %.0f m through ROS, %.0f m through asv_batch" %
                  (ros["scenario"], t["name"], t["min_distance_m"], want))
            if band:
                self.assertLess(abs(t["min_distance_m"] - want), band * want, what)

    def test_lazarowska_1_aco_paper_mode(self):
        r = run("lazarowska_1", "aco", 3000.0, self.risks)
        ref = batch("lazarowska_1")
        self.agree(r, ref)
        self.assertEqual([r["plan_time_ms"]["count"], ref["plan_time_ms"]["count"]], [1, 1], "plans once")
        self.assertTrue(r["manoeuvres"], json.dumps(r))
        self.assertGreater(r["manoeuvres"][0]["course_change_deg"], 0.0, "paper: 066 -> 077, to starboard")

    def test_wu_port_ga_paper_mode(self):
        r = run("wu_port", "ga", 1500.0, self.risks)
        self.agree(r, batch("wu_port"), BAND)


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "paper_pipeline", PaperPipeline, sysargs=sys.argv)
