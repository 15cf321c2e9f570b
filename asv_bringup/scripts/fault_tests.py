#!/usr/bin/python3
"""Node-fault rostest:
- the planner node killed mid-encounter is respawned by scenario.launch and is planning again within 2 s
  of wall time, and the run still passes clear;
- a plugin that overruns its time budget (fault injection: ~fault_plan_delay makes every plan 1.2 s long,
  budget 0.5 s, overrun_factor 2) is not flown: the fallback is in force, the plan says why, and the
  planner's diagnostics turn WARN with the reason.

Run by rostest (test/faults.test), which provides the master.
"""
import json
import os
import subprocess
import sys
import tempfile
import time
import unittest

import rospy
import rosunit
from asv_msgs.msg import Plan
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus

RESPAWN_LIMIT = 2.0  # [s, wall] from the kill to the first plan of the new planner node


class NodeFaults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("fault_tests", anonymous=True, disable_signals=True)

    def test_overrunning_plugin_falls_back_visibly(self):
        plans = []
        warnings = []
        rospy.set_param("/planner_own/fault_plan_delay", 1.2)
        s1 = rospy.Subscriber("/own/plan", Plan, plans.append, queue_size=100)

        def diag(m):
            for s in m.status:
                if "planner" in s.name and s.level == DiagnosticStatus.WARN:
                    warnings.append(s.message)
        s2 = rospy.Subscriber("/diagnostics", DiagnosticArray, diag, queue_size=100)
        out = tempfile.mkdtemp(prefix="asv_overrun_")
        launch = subprocess.Popen(
            ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=head_on", "planner:=mopso", "rate:=10",
             "max_sim_time:=1300", "start_delay:=1.0", "out:=" + out, "output:=log"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        try:
            deadline = time.monotonic() + 90.0
            while time.monotonic() < deadline and not (plans and any("overran" in w for w in warnings)):
                time.sleep(0.2)
        finally:
            launch.terminate()
            log = launch.communicate(timeout=60)[0].decode(errors="replace")
            rospy.delete_param("/planner_own/fault_plan_delay")
            s1.unregister()
            s2.unregister()
        self.assertTrue(plans, "no plan from the planner node:\n" + log[-3000:])
        self.assertTrue(all(p.status == Plan.STATUS_FALLBACK for p in plans),
                        "a late plan was flown: %s" % [p.message for p in plans if p.status != Plan.STATUS_FALLBACK])
        self.assertIn("overran its time budget", plans[0].message)
        self.assertGreaterEqual(plans[0].compute_time, 1.2)
        self.assertTrue(any("overran its time budget" in w for w in warnings),
                        "planner diagnostics never warned: %s" % warnings[-5:])

    def test_planner_respawns_and_plans_within_2_s(self):
        plans = []
        planner_diag = []
        rospy.Subscriber("/own/plan", Plan, lambda m: plans.append((time.monotonic(), m)), queue_size=100)

        def diag(m):
            for s in m.status:
                if "planner" in s.name:
                    planner_diag.append(s)
        rospy.Subscriber("/diagnostics", DiagnosticArray, diag, queue_size=100)
        out = tempfile.mkdtemp(prefix="asv_fault_")
        result = os.path.join(out, "result.json")
        launch = subprocess.Popen(
            ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=head_on", "planner:=mopso", "rate:=20",
             "max_sim_time:=1300", "start_delay:=1.0", "out:=" + out, "result:=" + result, "output:=log"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        try:
            deadline = time.monotonic() + 60.0
            while not plans and time.monotonic() < deadline:
                time.sleep(0.05)
            self.assertTrue(plans, "no plan from the planner node")
            time.sleep(5.0)  # mid-encounter: about 100 simulated seconds on
            before = len(plans)
            subprocess.run(["rosnode", "kill", "/planner_own"], check=True, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=20)
            # From the kill (rosnode kill returns once it has told the node to shut down), not from the start
            # of the rosnode command: that Python tool's own start-up is no part of the respawn.
            killed = time.monotonic()
            # The new node's first plan: a plan published after the kill whose replan reason is "first
            # plan" is the respawned node's (the old one is gone).
            first = None
            while time.monotonic() < killed + 10.0 and first is None:
                for t, m in plans[before:]:
                    if t > killed:
                        first = t
                        break
                time.sleep(0.02)
            self.assertIsNotNone(first, "the planner node was not respawned (no plan within 10 s)")
            print("node_faults: planning again %.2f s after the kill" % (first - killed))
            self.assertLess(first - killed, RESPAWN_LIMIT,
                            "planning again %.2f s after the kill (limit %.1f s)" % (first - killed, RESPAWN_LIMIT))
            log, _ = launch.communicate(timeout=300)
        finally:
            if launch.poll() is None:
                launch.terminate()
                launch.wait(timeout=30)
        self.assertEqual(launch.returncode, 0, log.decode(errors="replace")[-3000:])
        with open(result) as f:
            r = json.load(f)
        self.assertFalse(r["collision"], json.dumps(r))
        self.assertGreater(r["min_separation_m"], 926.0, json.dumps(r))
        self.assertTrue(planner_diag, "the planner node publishes no diagnostics")


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "node_faults", NodeFaults, sysargs=sys.argv)
