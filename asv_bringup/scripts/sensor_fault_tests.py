#!/usr/bin/python3
"""Sensor-fault rostest: the scenario asv_bringup/test/sensor_faults.yaml through the whole pipeline
(scenario.launch, MOPSO), with sim_node playing its sensor_faults:

- ts1: AIS silent and lost by the radar for 150 s from t = 200 s. Her track coasts (age past the class A
  coast_after, 30 s), is dropped (class A drop_after, 120 s, after her last report), and comes back once
  she reports again (within 20 s of the end of the silence).
- ts2 and ts3 pass each other 300 m apart while the radar swaps their target numbers for 60 s from
  t = 450 s: no track ever shows a ship more than 300 m from where that ship really is (ships matched by
  MMSI against the simulator's ground truth on sim/ships).
- ts3: lost by the radar alone for 100 s from t = 600 s: her track lives on on AIS, never dropped.
- The ARPA reports both losses (status L), the run ends without a collision and with the own ship's
  passing distances kept (926 m).

Run by rostest (test/sensor_faults.test), which provides the master.
"""
import bisect
import json
import os
import subprocess
import sys
import tempfile
import unittest

import rospy
import rosunit
from asv_msgs.msg import TargetArray
from diagnostic_msgs.msg import DiagnosticArray

EPOCH = 1.0e9  # sim_node's ROS time of simulation time 0
MMSI = {"ts1": 244000101, "ts2": 244000102, "ts3": 244000103}
SCENARIO = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "test",
                        "sensor_faults.yaml")


class SensorFaults(unittest.TestCase):
    def test_sensor_faults_through_the_pipeline(self):
        rospy.init_node("sensor_fault_tests", anonymous=True, disable_signals=True)
        tracks = []  # (t, {mmsi: (x, y, age)})
        truth = []   # (t, {mmsi: (x, y)})
        arpa_lost = [0]

        def on_tracks(m):
            tracks.append((m.header.stamp.to_sec() - EPOCH,
                           {t.mmsi: (t.position.x, t.position.y, t.age) for t in m.targets if t.mmsi}))

        def on_truth(m):
            truth.append((m.header.stamp.to_sec() - EPOCH, {t.mmsi: (t.position.x, t.position.y) for t in m.targets}))

        def on_diag(m):
            for st in m.status:
                if "arpa" in st.name.lower():
                    for kv in st.values:
                        if kv.key == "targets lost (status L)":
                            arpa_lost[0] = max(arpa_lost[0], int(kv.value))

        subs = [rospy.Subscriber("/targets", TargetArray, on_tracks, queue_size=100),
                rospy.Subscriber("/sim/ships", TargetArray, on_truth, queue_size=100),
                rospy.Subscriber("/diagnostics", DiagnosticArray, on_diag, queue_size=100)]
        out = tempfile.mkdtemp(prefix="asv_sensor_faults_")
        result = os.path.join(out, "result.json")
        proc = subprocess.run(
            ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=sensor_faults", "scenario_file:=" + SCENARIO,
             "planner:=mopso", "lockstep:=true", "out:=" + out, "result:=" + result,
             "output:=log"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
        for s in subs:
            s.unregister()
        log = proc.stdout.decode(errors="replace")
        self.assertEqual(proc.returncode, 0, log[-3000:])
        with open(result) as f:
            r = json.load(f)
        self.assertFalse(r["collision"], json.dumps(r))
        self.assertGreater(r["min_separation_m"], 926.0, json.dumps(r))
        self.assertGreater(len(tracks), 500, "too few track arrays")
        self.assertGreater(len(truth), 100, "too few ground-truth arrays")

        ts1 = MMSI["ts1"]
        seen = [(t, ts1 in m) for t, m in tracks]
        # Before the silence she is tracked; during it her track coasts, then is dropped.
        self.assertTrue(all(ok for t, ok in seen if 60.0 < t < 200.0), "ts1 not tracked before the silence")
        coasting = [m[ts1][2] for t, m in tracks if 200.0 < t < 350.0 and ts1 in m]
        self.assertTrue(coasting and max(coasting) > 30.0, "ts1's track never coasted: ages %s" % coasting[-3:])
        dropped = [t for t, ok in seen if 200.0 < t < 350.0 and not ok]
        self.assertTrue(dropped, "ts1's track was never dropped during 150 s of silence")
        self.assertLess(min(dropped), 200.0 + 120.0 + 5.0, "dropped only at %.0f s" % min(dropped))
        back = [t for t, ok in seen if t >= 350.0 and ok]
        self.assertTrue(back and back[0] < 370.0, "ts1 not tracked again within 20 s: %s" % back[:1])

        # No track jumps to another ship: every tracked MMSI within 300 m of that ship's true position.
        truth_t = [t for t, _ in truth]
        worst = {}
        for t, m in tracks:
            if t < 60.0:
                continue  # the first reports and the filters settling
            i = bisect.bisect_left(truth_t, t)
            if i >= len(truth):
                break
            gt = truth[i][1]
            for mmsi, (x, y, _) in m.items():
                if mmsi in gt and (mmsi != ts1 or not 200.0 < t < 360.0):  # ts1 coasts on purpose
                    d = ((x - gt[mmsi][0]) ** 2 + (y - gt[mmsi][1]) ** 2) ** 0.5
                    worst[mmsi] = max(worst.get(mmsi, 0.0), d)
                    self.assertLess(d, 300.0, "track of MMSI %d %.0f m from the ship at t = %.0f s" % (mmsi, d, t))
        self.assertIn(MMSI["ts2"], worst)
        self.assertIn(MMSI["ts3"], worst)

        # ts3's radar loss: her track lives on AIS.
        ts3_gone = [t for t, m in tracks if 600.0 < t < 700.0 and MMSI["ts3"] not in m]
        self.assertFalse(ts3_gone, "ts3's track dropped during the radar loss at %s" % ts3_gone[:3])
        self.assertGreaterEqual(arpa_lost[0], 2, "the ARPA losses were not counted")
        print("sensor_faults: ts1 dropped %.0f s, back %.0f s; worst track error %s m; ARPA lost %d" %
              (min(dropped), back[0], {k: round(v) for k, v in worst.items()}, arpa_lost[0]))


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "sensor_faults", SensorFaults, sysargs=sys.argv)
