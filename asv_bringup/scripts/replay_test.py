#!/usr/bin/python3
"""Record-then-replay rostest.

1. scenario.launch runs the head-on scenario through the whole pipeline with record:=true, leaving a
   bag with every topic (raw NMEA, odometry, the pipeline's /risk).
2. replay.launch plays the bag's sensor streams (/sim/nmea, /own/odom, /tf) through a fresh ingestion,
   tracker and risk pipeline under /replay, with the same parameters.
3. The replayed /replay/risk must reproduce the recorded /risk: for the recorded assessments whose
   the replay has one within a quarter of a second of (the tracker publishes at 2 Hz on its own timer,
   whose phase the replay does not reproduce), the same targets with the same risk level, encounter and
   role, and range and DCPA within tolerance (the tracker dead-reckons to its own publication time; the
   tolerances cover that phase and the tracker's filter state, not a different picture).

Run by rostest (test/replay.test), which provides the master.
"""
import bisect
import os
import subprocess
import sys
import tempfile
import unittest

import rosbag
import rospy
import rosunit
from asv_msgs.msg import RiskAssessment

SCENARIO = "head_on"
SIM_TIME = 900.0  # [s] the approach and the alteration (CPA at about 1050 s)


def key(stamp):
    return round(stamp.to_sec(), 1)


class RecordReplay(unittest.TestCase):
    def test_replay_reproduces_recorded_risk(self):
        out = tempfile.mkdtemp(prefix="asv_replay_")
        rec = subprocess.run(
            ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=" + SCENARIO, "planner:=mopso",
             "rate:=50", "max_sim_time:=%g" % SIM_TIME, "start_delay:=1.0", "record:=true", "out:=" + out,
             "output:=log"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
        log = rec.stdout.decode(errors="replace")
        self.assertEqual(rec.returncode, 0, log[-3000:])
        bag_path = os.path.join(out, "run.bag")
        self.assertTrue(os.path.exists(bag_path), "no bag:\n" + log[-3000:])
        recorded = {}
        nmea = 0
        with rosbag.Bag(bag_path) as bag:
            for topic, msg, _ in bag.read_messages(topics=["/risk", "/sim/nmea"]):
                if topic == "/risk":
                    recorded[key(msg.header.stamp)] = msg
                else:
                    nmea += 1
        self.assertGreater(nmea, 100, "the bag holds no raw NMEA")
        self.assertGreater(len(recorded), 100, "the bag holds no risk assessments")

        replayed = {}
        rospy.init_node("replay_test", anonymous=True, disable_signals=True)
        sub = rospy.Subscriber("/replay/risk", RiskAssessment,
                               lambda m: replayed.__setitem__(key(m.header.stamp), m), queue_size=1000)
        scenario_file = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                                     "scenarios", SCENARIO + ".yaml")
        rep = subprocess.run(
            ["roslaunch", "asv_bringup", "replay.launch", "bag:=" + bag_path, "rate:=20",
             "scenario_file:=" + scenario_file], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=300)
        sub.unregister()
        self.assertEqual(rep.returncode, 0, rep.stdout.decode(errors="replace")[-3000:])

        stamps = sorted(replayed)
        pairs = []
        for k in sorted(recorded):
            i = bisect.bisect_left(stamps, k)
            near = [stamps[j] for j in (i - 1, i) if 0 <= j < len(stamps)]
            if near:
                best = min(near, key=lambda s: abs(s - k))
                if abs(best - k) <= 0.25:
                    pairs.append((k, best))
        # The replay starts when the bag does and ends with it: nearly every recorded stamp is there.
        self.assertGreater(len(pairs), 0.8 * len(recorded),
                           "%d of %d recorded assessments replayed" % (len(pairs), len(recorded)))
        compared = same_level = 0
        for k, kr in pairs:
            a = {t.target_id: t for t in recorded[k].targets}
            b = {t.target_id: t for t in replayed[kr].targets}
            for tid, ta in a.items():
                if tid not in b:
                    continue
                tb = b[tid]
                compared += 1
                same_level += ta.risk_level == tb.risk_level and ta.encounter == tb.encounter and \
                    ta.own_role == tb.own_role
                self.assertAlmostEqual(ta.range, tb.range, delta=150.0, msg="range at t=%s" % k)
                if ta.tcpa > 0 and tb.tcpa > 0:
                    self.assertAlmostEqual(ta.dcpa, tb.dcpa, delta=300.0, msg="DCPA at t=%s" % k)
        self.assertGreater(compared, 100)
        self.assertGreater(same_level, 0.95 * compared,
                           "risk level/encounter/role equal in %d of %d" % (same_level, compared))


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "record_replay", RecordReplay, sysargs=sys.argv)
