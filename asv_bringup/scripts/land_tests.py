#!/usr/bin/python3
"""Land rostest: a run over land is a grounding through the ROS pipeline too, and a planner goes round.

scenarios/island.yaml (no traffic; the straight way to the goal crosses a 3 x 3 km island) through
scenario.launch lockstep:=true:
1. without a planner the own ship runs onto the island: sim_node's GROUNDING event, and the result says
   grounding with a COLREGs score of 0 (stop_on_collision ends the run there);
2. with GA (whose paper knows no land) the own ship goes round it and arrives, the hull kept clear;
3. sim_node publishes the island, filled, on the latched /sim/land for rviz.

Run by rostest (test/land.test), which provides the master.
"""
import json
import os
import subprocess
import tempfile
import unittest

import rospy
import rosunit
from asv_msgs.msg import SimEvent
from visualization_msgs.msg import MarkerArray


def run(planner, *extra):
    out = tempfile.mkdtemp(prefix="asv_land_")
    result = os.path.join(out, "result.json")
    proc = subprocess.run(
        ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=island", "planner:=" + planner,
         "lockstep:=true", "out:=" + out, "result:=" + result, "output:=log"] + list(extra),
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=900)
    log = proc.stdout.decode(errors="replace")
    if proc.returncode != 0 or not os.path.exists(result):
        raise AssertionError("run failed:\n" + log[-3000:])
    with open(result) as f:
        return json.load(f)


class Land(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("land_tests", anonymous=True, disable_signals=True)

    def test_without_a_planner_the_run_is_a_grounding(self):
        events, land = [], []
        subs = [rospy.Subscriber("/sim/events", SimEvent, events.append, queue_size=100),
                rospy.Subscriber("/sim/land", MarkerArray, land.append, queue_size=10)]
        try:
            r = run("none", "stop_on_collision:=true")
        finally:
            for s in subs:
                s.unregister()
        self.assertTrue(r["grounding"], json.dumps(r))
        self.assertEqual(r["min_obstacle_distance_m"], 0.0, json.dumps(r))
        self.assertEqual(r["colregs_score"], 0.0, json.dumps(r))
        self.assertFalse(r["collision"], json.dumps(r))
        self.assertTrue(any(e.type == SimEvent.GROUNDING and e.ship_a == "own" and e.ship_b == "island"
                            for e in events), [(e.type, e.ship_a, e.ship_b) for e in events])
        self.assertTrue(land, "nothing on /sim/land")
        square = land[-1].markers[0]
        self.assertEqual(len(square.points), 6, "a square is two filled triangles")

    def test_a_planner_goes_round_the_island(self):
        r = run("ga")
        self.assertFalse(r["grounding"], json.dumps(r))
        self.assertTrue(r["arrived"], json.dumps(r))
        self.assertGreater(r["min_obstacle_distance_m"], 90.0, json.dumps(r))


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "land", Land)
