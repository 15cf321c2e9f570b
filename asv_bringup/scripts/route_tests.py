#!/usr/bin/python3
"""Route rostest: a real-traffic window sailed on a voyage plan through the whole ROS pipeline.

asv_scenario_from_ais puts the own ship in the place of a logged New York vessel (the shared AIS hour,
../shared/data/ais/real/, outside the repository): her track, thinned, is the own ship's route, and the
human block records what her master did. scenario.launch lockstep:=true runs it with a planner:
1. the own ship arrives, without collision or grounding, and the result reports the route (its legs)
   and the master's figures;
2. planner_node publishes the route in force on the latched route_markers (every waypoint) and, while she
   sails it, route_status with the route's size, a finite cross-track error and an active waypoint that
   moves on along the route.
Without the log the test is skipped, saying why. Run by rostest (test/route.test), which provides the
master.
"""
import json
import math
import os
import subprocess
import tempfile
import unittest

import rospkg
import rospy
import rosunit
from asv_msgs.msg import RouteStatus
from visualization_msgs.msg import MarkerArray

# The window (picked with scripts/real_traffic.py's rule: under way, meeting others) and the planner. The
# test is of the pipeline, not of the planner against the master (make benchmark's): the run may take
# twice her time.
OWN, START, DURATION, PLANNER, MARGIN = 367668450, "2020-06-30T00:13:00", 420, "ga", 1.0


def log_path():
    shared = os.environ.get("ASV_SHARED_DIR") or os.path.join(
        rospkg.RosPack().get_path("asv_bringup"), "..", "..", "shared")
    return os.path.join(shared, "data", "ais", "real", "NYHarbor_2020_06_30_first_hour.csv")


class Route(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("route_tests", anonymous=True, disable_signals=True)

    def test_a_real_window_sailed_on_its_route(self):
        path = log_path()
        if not os.path.exists(path):
            self.skipTest("New York AIS log not found at %s: the window needs the shared data" % path)
        out = tempfile.mkdtemp(prefix="asv_route_")
        scenario = os.path.join(out, "window.yaml")
        made = subprocess.run(["rosrun", "asv_core", "asv_scenario_from_ais", path, "--quiet", "--start", START,
                               "--duration", str(DURATION), "--own-mmsi", str(OWN), "--time-margin", str(MARGIN),
                               "--out", scenario],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
        self.assertEqual(made.returncode, 0, made.stdout.decode(errors="replace"))
        markers, status = [], []
        subs = [rospy.Subscriber("/own/route_markers", MarkerArray, markers.append, queue_size=10),
                rospy.Subscriber("/own/route_status", RouteStatus, status.append, queue_size=1000)]
        result = os.path.join(out, "result.json")
        try:
            proc = subprocess.run(
                ["roslaunch", "asv_bringup", "scenario.launch", "scenario_file:=" + scenario, "planner:=" + PLANNER,
                 "lockstep:=true", "out:=" + out, "result:=" + result, "output:=log"],
                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=900)
        finally:
            for s in subs:
                s.unregister()
        log = proc.stdout.decode(errors="replace")
        self.assertTrue(proc.returncode == 0 and os.path.exists(result), "run failed:\n" + log[-3000:])
        with open(result) as f:
            r = json.load(f)
        text = json.dumps({k: r.get(k) for k in ("arrived", "collision", "grounding", "route", "human",
                                                 "min_separation_m", "time_to_goal_s")})
        self.assertTrue(r["arrived"], text)
        self.assertFalse(r["collision"], text)
        self.assertFalse(r["grounding"], text)
        self.assertIn("human", r, text)
        legs = r["route"]["legs"]
        self.assertGreaterEqual(legs, 2, text)
        self.assertTrue(markers, "nothing on /own/route_markers")
        line = [m for m in markers[-1].markers if m.type == m.LINE_STRIP]
        self.assertEqual(len(line[0].points), legs, "the route line has a point per waypoint")
        self.assertTrue(status, "nothing on /own/route_status")
        self.assertTrue(all(s.waypoints == legs and math.isfinite(s.cross_track_error) for s in status))
        self.assertGreater(max(s.active_waypoint for s in status), min(s.active_waypoint for s in status),
                           "the active waypoint never moved on")


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "route", Route)
