#!/usr/bin/python3
"""Aids to navigation rostest (test/aids.test): planner_node keeps clear of an aid on aids_to_navigation.

The test plays the rest of the pipeline: the own ship at the origin heading north at 5 m/s
(own/odom), an empty picture (targets, risk with data_ok), and one aid to navigation 2 km ahead on the
straight way to the goal (0, 6000), latched on aids_to_navigation. Expected, by the rule stated in
planner_node.yaml: planner_aids (aid_clearance 300 m, min_obstacle_clearance_m 185.2 m) plans a path
that keeps at least max(300, 185.2) = 300 m from the aid; planner_blind (use_aids false) plans the
straight line, within 50 m of it, so the aid is what moved the plan.
"""
import math
import unittest

import rospy
import rosunit
from asv_msgs.msg import AidToNavigation, AidToNavigationArray, Plan, RiskAssessment, TargetArray
from nav_msgs.msg import Odometry

AID = (0.0, 2000.0)


def distance_to_segment(p, a, b):
    ax, ay = a
    bx, by = b
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - ax) * dx + (p[1] - ay) * dy) / length2))
    return math.hypot(p[0] - (ax + t * dx), p[1] - (ay + t * dy))


def plan_distance(plan, point):
    """Closest approach of the plan's path (from the own ship at the origin) to `point`."""
    path = [(0.0, 0.0)] + [(w.position.x, w.position.y) for w in plan.waypoints]
    return min(distance_to_segment(point, path[k], path[k + 1]) for k in range(len(path) - 1))


class Aids(unittest.TestCase):
    def test_the_plan_keeps_clear_of_an_aid(self):
        rospy.init_node("aids_tests")
        plans = {}
        subs = [rospy.Subscriber("aids/plan", Plan, lambda m: plans.__setitem__("aids", m)),
                rospy.Subscriber("blind/plan", Plan, lambda m: plans.__setitem__("blind", m))]
        aids = rospy.Publisher("aids_to_navigation", AidToNavigationArray, queue_size=1, latch=True)
        odom = rospy.Publisher("own/odom", Odometry, queue_size=10)
        targets = rospy.Publisher("targets", TargetArray, queue_size=10)
        risk = rospy.Publisher("risk", RiskAssessment, queue_size=10)
        arr = AidToNavigationArray()
        arr.header.frame_id = "map"
        aid = AidToNavigation(mmsi=992611234, name="BUOY", aid_type=24)
        aid.position.x, aid.position.y = AID
        arr.aids.append(aid)
        deadline = rospy.Time.now() + rospy.Duration(60.0)
        rate = rospy.Rate(10)
        k = 0
        while not rospy.is_shutdown() and rospy.Time.now() < deadline and len(plans) < 2:
            now = rospy.Time.now()
            arr.header.stamp = now
            if k % 10 == 0:
                aids.publish(arr)
            o = Odometry()
            o.header.stamp, o.header.frame_id, o.child_frame_id = now, "map", "own/base_link"
            o.pose.pose.orientation.z = o.pose.pose.orientation.w = math.sqrt(0.5)  # yaw 90 deg: north
            o.twist.twist.linear.x = 5.0
            odom.publish(o)
            if k % 5 == 0:
                t = TargetArray()
                t.header.stamp, t.header.frame_id = now, "map"
                targets.publish(t)
                r = RiskAssessment(own_ship="own", data_ok=True)
                r.header.stamp, r.header.frame_id = now, "map"
                risk.publish(r)
            k += 1
            rate.sleep()
        for s in subs:
            s.unregister()
        self.assertIn("aids", plans, "no plan from planner_aids")
        self.assertIn("blind", plans, "no plan from planner_blind")
        clear = plan_distance(plans["aids"], AID)
        blind = plan_distance(plans["blind"], AID)
        self.assertGreaterEqual(clear, 300.0 - 1.0, "plan passes %.0f m from the aid" % clear)
        self.assertLess(blind, 50.0, "without the aid the plan runs straight (%.0f m)" % blind)


if __name__ == "__main__":
    rosunit.unitrun("asv_planning", "aids", Aids)
