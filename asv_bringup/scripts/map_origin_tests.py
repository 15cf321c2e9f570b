#!/usr/bin/python3
"""One map origin rostest.

1. A scenario without `origin` (the library's head_on with its origin line removed) runs end to end
   through scenario.launch: the map_origin node publishes 0 N 0 E (the simulator's documented default)
   latched on /map_origin and as /map_origin/lat_deg, /map_origin/lon_deg; ais_node, given no origin of
   its own, takes it, so the target's AIS reports land where the simulator put her (7 nm = 12964 m
   north of the own ship, by hand) and reach the risk picture with her MMSI. Before, ais_node and
   arpa_node needed an origin of their own and exited at start, and the own ship ran blind. The run is
   recorded: the bag holds /map_origin, which is what lets replay.launch run without an origin. The
   run also feeds a chart plotter (plotter:=true): what it hears on UDP places the own ship at 0 N 0 E
   (RMC within 1' of it), tracks the target (TTM 7 nm or less dead ahead) and forwards her
   AIVDM.
2. A node with no origin of its own and no /map_origin stops after /map_origin_timeout with the reason.
3. A node whose own origin differs from the run's /map_origin stops with both origins in the reason.

Run by rostest (test/map_origin.test), which provides the master.
"""
import json
import os
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import rosbag
import rospy
import rosunit
from asv_msgs.msg import RiskAssessment, TargetArray
from rosgraph_msgs.msg import Log
from sensor_msgs.msg import NavSatFix

HERE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SIM_TIME = 120.0  # [s] long enough for AIS reports (every 2-10 s) and the tracker's first assessments
PLOTTER_PORT = 10194
TARGET_RANGE = 7 * 1852.0  # [m] head_on.yaml: the target 7 nm dead ahead of the own ship at (0, 0)


def without_origin(src, dst):
    with open(src) as f:
        lines = [ln for ln in f if not ln.startswith("origin:")]
    assert len(lines) < sum(1 for _ in open(src)), "the library scenario lost its origin line"
    with open(dst, "w") as f:
        f.writelines(lines)


class MapOrigin(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("map_origin_tests", anonymous=True, disable_signals=True)

    def test_a_scenario_without_origin_runs_end_to_end(self):
        tmp = tempfile.mkdtemp(prefix="asv_no_origin_")
        scenario = os.path.join(tmp, "no_origin.yaml")
        without_origin(os.path.join(HERE, "scenarios", "head_on.yaml"), scenario)
        origins, ais, risk = [], [], []
        subs = [rospy.Subscriber("/map_origin", NavSatFix, origins.append),
                rospy.Subscriber("/ais/targets", TargetArray, ais.append, queue_size=1000),
                rospy.Subscriber("/risk", RiskAssessment, risk.append, queue_size=1000)]
        heard = []
        sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        sock.bind(("127.0.0.1", PLOTTER_PORT))
        sock.settimeout(0.2)
        done = threading.Event()

        def listen():
            while not done.is_set():
                try:
                    heard.append(sock.recvfrom(4096)[0].decode().strip())
                except socket.timeout:
                    pass

        listener = threading.Thread(target=listen)
        listener.start()
        try:
            run = subprocess.run(
                ["roslaunch", "asv_bringup", "scenario.launch", "scenario_file:=" + scenario, "planner:=mopso",
                 "lockstep:=true", "max_sim_time:=%g" % SIM_TIME, "record:=true", "out:=" + tmp,
                 "plotter:=true", "plotter_port:=%d" % PLOTTER_PORT],
                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
        finally:
            done.set()
            listener.join()
            sock.close()
        for s in subs:
            s.unregister()
        log = run.stdout.decode(errors="replace")
        self.assertEqual(run.returncode, 0, log[-3000:])
        self.assertIn("has no origin: the map origin is 0 N 0 E", log)  # said on screen
        self.assertTrue(origins, "nothing on /map_origin")
        self.assertEqual((origins[0].latitude, origins[0].longitude), (0.0, 0.0))
        self.assertEqual(origins[0].header.frame_id, "map")
        self.assertEqual(rospy.get_param("/map_origin/lat_deg"), 0.0)
        self.assertEqual(rospy.get_param("/map_origin/lon_deg"), 0.0)
        # The target's AIS reports in the map where the simulator put her: x 0, y 12964 m at the start,
        # closing at 2 x 12 kn (12.35 m/s): within the run, y in [12964 - 12.35 * SIM_TIME, 12964].
        reports = [t for m in ais for t in m.targets]
        self.assertTrue(reports, "no AIS target: ais_node did not run without an origin of its own")
        self.assertTrue(all(t.mmsi != 0 for t in reports))
        for t in reports:
            self.assertAlmostEqual(t.position.x, 0.0, delta=60.0)
            self.assertGreater(t.position.y, TARGET_RANGE - 2 * 6.173 * SIM_TIME - 60.0)
            self.assertLess(t.position.y, TARGET_RANGE + 60.0)
        mmsis = {t.mmsi for t in reports}
        assessed = {t.mmsi for m in risk for t in m.targets}
        self.assertTrue(mmsis & assessed, "the AIS target %s never reached /risk (%s)" % (mmsis, assessed))
        with open(os.path.join(tmp, "result.json")) as f:
            result = json.load(f)
        closest = result["targets"][0]["closest_approach"]["target"]
        self.assertAlmostEqual(closest["lon_deg"], 0.0, delta=1e-3)
        self.assertLess(abs(closest["lat_deg"]), 0.2)  # 12964 m north of 0 N is 0.117 deg
        with rosbag.Bag(os.path.join(tmp, "run.bag")) as bag:
            recorded = [m for _, m, _ in bag.read_messages(topics=["/map_origin"])]
        self.assertEqual(len(recorded), 1, "the bag does not hold the map origin")
        self.assertEqual((recorded[0].latitude, recorded[0].longitude), (0.0, 0.0))
        # The chart plotter's view: the own ship near 0 N 0 E (she sails from it at 12 kn: at most 741 m =
        # 0.4' in 120 s), the target tracked dead ahead within 7 nm, her AIVDM forwarded.
        rmc = [l.split(",") for l in heard if l.startswith("$GPRMC") and l.split(",")[2] == "A"]
        self.assertTrue(rmc, "the plotter heard no valid RMC: %s" % heard[:5])
        self.assertTrue(all(r[3].startswith("0000.") and r[4] == "N" and r[5].startswith("00000.") for r in rmc),
                        rmc[-1])
        ttm = [l.split(",") for l in heard if l.startswith("$ECTTM")]
        self.assertTrue(ttm, "no TTM")
        self.assertTrue(all(float(t[2]) <= 7.0 and min(float(t[3]), 360.0 - float(t[3])) < 10.0 for t in ttm),
                        ttm[-1])
        self.assertTrue([l for l in heard if l.startswith("!AIVDM")], "the traffic's AIVDM not forwarded")

    def run_node(self, limit, *args):
        try:
            done = subprocess.run(["rosrun", "asv_risk", "ais_node"] + list(args), stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, timeout=limit, universal_newlines=True)
        except subprocess.TimeoutExpired:
            return None, "still running after %.0f s" % limit
        return done.returncode, done.stdout

    def test_b_no_origin_anywhere_stops_with_the_reason(self):
        rospy.set_param("/map_origin_timeout", 2.0)
        try:
            status, out = self.run_node(20.0, "__name:=mo_ais_none", "_input/type:=topic")
        finally:
            rospy.delete_param("/map_origin_timeout")
        self.assertEqual(status, 1, out[-600:])
        self.assertIn("no map origin: nothing was published on /map_origin within 2 s", out)
        self.assertIn("waiting for the map origin", out)  # progress while it waits

    def test_c_an_origin_that_disagrees_stops_the_node(self):
        fatal = []
        sub = rospy.Subscriber("/rosout", Log, lambda m: m.level == Log.FATAL and fatal.append(m), queue_size=100)
        pub = subprocess.Popen(["rosrun", "asv_ros", "map_origin", "__name:=mo_origin", "_lat_deg:=10.0",
                                "_lon_deg:=20.0"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            status, out = self.run_node(20.0, "__name:=mo_ais_other", "_input/type:=topic",
                                        "_origin_lat_deg:=54.6", "_origin_lon_deg:=18.8")
            deadline = time.time() + 5.0
            while time.time() < deadline and not any("mo_ais_other" in m.name for m in fatal):
                time.sleep(0.1)
        finally:
            pub.terminate()
            pub.wait()
            sub.unregister()
        self.assertEqual(status, 1, out)  # it stopped, as a process that died (roslaunch says so)
        self.assertIn("/map_origin says the map origin is 10.0000000 20.0000000, but this node uses "
                      "54.6000000 18.8000000", out)
        self.assertTrue(any("two map origins" in m.msg for m in fatal if "mo_ais_other" in m.name),
                        "the reason did not reach /rosout")


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "map_origin", MapOrigin, sys.argv)
