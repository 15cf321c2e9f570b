#!/usr/bin/python3
"""Live parameters rostest (test/reconfigure.test): planner_node's dynamic_reconfigure server.

The test plays the rest of the pipeline (the own ship at the origin heading north at 5 m/s, one target
T1 head-on 4 km ahead at (100, 4000) steaming south at 5 m/s, collision risk) and changes
planner_live's parameters while it plans:
- at start the server shows the values in force: planner ga (the launch), min_separation 0 and
  replan_period 30 s (config/planner_node.yaml); with no minimum separation and GA (no domain of its
  own) no domain outline is shown;
- planner mopso with min_separation 1500 m: accepted, written back to the parameter server, the next
  plan comes from MOPSO ("parameters changed" replans at once), diagnostics report 1500 m in force, and
  `domains` shows the separation circle round T1: radius 1.1 x 1500 = 1650 m (kSeparationMargin);
- planner "bogus": refused with an ERROR on /rosout, MOPSO stays;
- mode "harbour": refused (sea or paper), the reason on /rosout; mode paper with MOPSO: accepted, the
  next plan from MOPSO, diagnostics report mode paper; planner ga with mode paper: accepted, the next plan
  from GA;
- replan_period 0.5 s: below the stated range (1-600 s), so the server clamps it to 1 s.
"""
import math
import threading
import unittest

import dynamic_reconfigure.client
import rospy
import rosunit
from asv_msgs.msg import Plan, RiskAssessment, Target, TargetArray, TargetRisk
from diagnostic_msgs.msg import DiagnosticArray
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Log
from visualization_msgs.msg import MarkerArray

NODE = "/planner_live"


class Pipeline(threading.Thread):
    """Own-ship odometry at 10 Hz, an empty picture at 2 Hz, until stopped."""

    def __init__(self):
        super().__init__(daemon=True)
        self.odom = rospy.Publisher("own/odom", Odometry, queue_size=10)
        self.targets = rospy.Publisher("targets", TargetArray, queue_size=10)
        self.risk = rospy.Publisher("risk", RiskAssessment, queue_size=10)

    def run(self):
        rate = rospy.Rate(10)
        k = 0
        start = rospy.Time.now()
        while not rospy.is_shutdown():
            now = rospy.Time.now()
            o = Odometry()
            o.header.stamp, o.header.frame_id, o.child_frame_id = now, "map", "own/base_link"
            o.pose.pose.orientation.z = o.pose.pose.orientation.w = math.sqrt(0.5)  # yaw 90 deg: north
            o.twist.twist.linear.x = 5.0
            self.odom.publish(o)
            if k % 5 == 0:
                sailed = 5.0 * (now - start).to_sec()
                tg = Target(id="T1", course_over_ground=math.pi, speed_over_ground=5.0, has_heading=True,
                            heading=math.pi, length=100.0, stamp=now, quality=100)
                tg.position.x, tg.position.y = 100.0, 4000.0 - sailed
                tg.velocity.y = -5.0
                t = TargetArray(targets=[tg])
                t.header.stamp, t.header.frame_id = now, "map"
                self.targets.publish(t)
                tr = TargetRisk(target_id="T1", risk_level=TargetRisk.RISK_COLLISION, compliant=True,
                                encounter=TargetRisk.ENCOUNTER_HEAD_ON, own_role=TargetRisk.ROLE_GIVE_WAY,
                                range=3900.0 - 2 * sailed, tcpa=(3900.0 - 2 * sailed) / 10.0, dcpa=100.0, cri=0.8)
                r = RiskAssessment(own_ship="own", data_ok=True, targets=[tr])
                r.header.stamp, r.header.frame_id = now, "map"
                self.risk.publish(r)
            k += 1
            rate.sleep()


def wait_for(condition, timeout):
    deadline = rospy.Time.now() + rospy.Duration(timeout)
    while not rospy.is_shutdown() and rospy.Time.now() < deadline:
        if condition():
            return True
        rospy.sleep(0.1)
    return condition()


class LiveParameters(unittest.TestCase):
    def test_changes_while_running(self):
        rospy.init_node("reconfigure_tests")
        plans, errors, separation, modes = [], [], [], []
        rospy.Subscriber("plan", Plan, plans.append)
        rospy.Subscriber("/rosout", Log, lambda m: errors.append(m.msg) if m.level >= Log.ERROR else None)

        def diagnostics(m):
            for st in m.status:
                for kv in st.values:
                    if kv.key == "min separation [m]":
                        separation.append(float(kv.value))
                    if kv.key == "mode":
                        modes.append(kv.value)
        rospy.Subscriber("/diagnostics", DiagnosticArray, diagnostics)
        domains = []
        rospy.Subscriber("domains", MarkerArray,
                         lambda m: domains.append([d for d in m.markers if d.action == d.ADD]))
        Pipeline().start()
        self.assertTrue(wait_for(lambda: plans, 40.0), "no first plan")
        self.assertEqual(plans[-1].planner, "ga")

        client = dynamic_reconfigure.client.Client(NODE, timeout=30)
        c = client.get_configuration(timeout=10)
        self.assertEqual(c["planner"], "ga")
        self.assertEqual(c["min_separation"], 0.0)
        self.assertEqual(c["replan_period"], 30.0)
        self.assertTrue(wait_for(lambda: domains, 10.0), "no domains published")
        self.assertEqual(domains[-1], [], "GA without a minimum separation shows no domain")

        n = len(plans)
        c = client.update_configuration({"planner": "mopso", "min_separation": 1500.0})
        self.assertEqual(c["planner"], "mopso")
        self.assertEqual(c["min_separation"], 1500.0)
        self.assertEqual(rospy.get_param(NODE + "/min_separation"), 1500.0)
        self.assertTrue(wait_for(lambda: len(plans) > n and plans[-1].planner == "mopso", 20.0),
                        "no plan from mopso after the switch")
        self.assertTrue(wait_for(lambda: separation and separation[-1] == 1500.0, 10.0),
                        "diagnostics: min separation in force %s" % separation[-1:])
        self.assertTrue(wait_for(lambda: domains and domains[-1], 10.0), "no domain after the change")
        outline = domains[-1][0]
        self.assertEqual(len(outline.points), 37)  # 36-gon, closed
        centre = (sum(p.x for p in outline.points[:36]) / 36, sum(p.y for p in outline.points[:36]) / 36)
        self.assertAlmostEqual(centre[0], 100.0, delta=1.0)
        for p in outline.points:
            self.assertAlmostEqual(math.hypot(p.x - centre[0], p.y - centre[1]), 1650.0, delta=1.0)

        c = client.update_configuration({"planner": "bogus"})
        self.assertEqual(c["planner"], "mopso", "a planner that cannot load is refused")
        self.assertTrue(wait_for(lambda: any("live parameters refused" in e for e in errors), 10.0), errors)

        c = client.update_configuration({"mode": "harbour"})
        self.assertEqual((c["planner"], c["mode"]), ("mopso", "sea"), "an unknown mode is refused")
        self.assertTrue(wait_for(lambda: any("mode must be sea or paper" in e for e in errors), 10.0), errors)
        n = len(plans)
        c = client.update_configuration({"mode": "paper"})
        self.assertEqual((c["planner"], c["mode"]), ("mopso", "paper"))
        self.assertTrue(wait_for(lambda: len(plans) > n and plans[-1].planner == "mopso", 20.0),
                        "no plan from mopso in paper mode")
        self.assertTrue(wait_for(lambda: modes and modes[-1] == "paper", 10.0), modes[-1:])
        n = len(plans)
        c = client.update_configuration({"planner": "ga", "mode": "paper"})
        self.assertEqual((c["planner"], c["mode"]), ("ga", "paper"))
        self.assertTrue(wait_for(lambda: len(plans) > n and plans[-1].planner == "ga", 20.0),
                        "no plan from ga after the switch")
        self.assertTrue(wait_for(lambda: modes and modes[-1] == "paper", 10.0), modes[-1:])

        c = client.update_configuration({"replan_period": 0.5})
        self.assertEqual(c["replan_period"], 1.0, "clamped to the stated range")


if __name__ == "__main__":
    rosunit.unitrun("asv_planning", "reconfigure", LiveParameters)
