#!/usr/bin/python3
"""Lockstep rostests: a ROS run decides the same way every time, and the way asv_batch does.

1. The same scenario, planner and seed run twice through scenario.launch lockstep:=true give the same
   result JSON byte for byte (apart from its wall-clock fields, wall_time_s and plan_time_ms), and the
   same messages, byte for byte, on every pipeline topic between the nodes (ingestion, tracks, risk,
   set-points).
2. Recording (record:=true) works into an output folder nothing has made yet, and the bag holds the
   pipeline's topics; the output folder is named after the scenario file actually run.
3. A sample of scenario/planner pairs through the ROS pipeline and through asv_batch land in the same
   class (collision / separation kept / arrived) with minimum separations within the tolerance of
   scripts/eval_ros.py (which make eval-ros runs on every pair).

Run by rostest (test/lockstep.test), which provides the master.
"""
import io
import json
import os
import subprocess
import sys
import tempfile
import threading
import unittest

import rospkg
import rospy
import rosunit
from asv_msgs.msg import CourseSpeedSetpoint, RiskAssessment, TargetArray

EPOCH = 1.0e9  # sim_node's ROS time of simulation time 0
TOPICS = [("/ais/targets", TargetArray), ("/arpa/targets", TargetArray), ("/targets", TargetArray),
          ("/risk", RiskAssessment), ("/own/cmd", CourseSpeedSetpoint)]
WALL_FIELDS = ("wall_time_s", "plan_time_ms")
SAMPLE = [("crossing_give_way", "ga"), ("head_on", "mopso")]


class Recorder:
    """Every message on TOPICS, serialised, in arrival order per topic."""

    def __init__(self):
        self.lock = threading.Lock()
        self.msgs = {t: [] for t, _ in TOPICS}
        self.subs = [rospy.Subscriber(t, c, self.on, callback_args=t, queue_size=100000) for t, c in TOPICS]

    def on(self, msg, topic):
        # The test node subscribes before the launch, so it is connected well before the first step;
        # the first simulated second is left out all the same (a margin for the connection).
        if msg.header.stamp.to_sec() - EPOCH < 1.0:
            return
        buf = io.BytesIO()
        msg.serialize(buf)
        with self.lock:
            self.msgs[topic].append(buf.getvalue())

    def close(self):
        for s in self.subs:
            s.unregister()
        return self.msgs


def run(scenario, planner, sim_time):
    out = tempfile.mkdtemp(prefix="asv_lockstep_")
    result = os.path.join(out, "result.json")
    rec = Recorder()
    proc = subprocess.run(
        ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=" + scenario, "planner:=" + planner,
         "lockstep:=true", "max_sim_time:=%g" % sim_time, "out:=" + out, "result:=" + result, "output:=log"],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=600)
    rospy.sleep(0.5)  # the last messages
    msgs = rec.close()
    log = proc.stdout.decode(errors="replace")
    if proc.returncode != 0 or not os.path.exists(result):
        raise AssertionError("run failed:\n" + log[-3000:])
    with open(result) as f:
        text = f.read()
    return text, msgs, log


def without_wall(text):
    r = json.loads(text)
    for k in WALL_FIELDS:
        r.pop(k, None)
    return json.dumps(r, sort_keys=True)


class Lockstep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("lockstep_tests", anonymous=True, disable_signals=True)

    def test_same_run_twice_same_result_and_messages(self):
        a, ma, log = run("crossing_give_way", "ga", 1800.0)
        self.assertIn("lockstep", log)
        b, mb, _ = run("crossing_give_way", "ga", 1800.0)
        self.assertEqual(without_wall(a), without_wall(b), "result JSON differs between two lockstep runs")
        for topic, _ in TOPICS:
            self.assertGreater(len(ma[topic]), 10, "too few messages on " + topic)
            self.assertEqual(len(ma[topic]), len(mb[topic]), "message count differs on " + topic)
            first = next((i for i, (x, y) in enumerate(zip(ma[topic], mb[topic])) if x != y), None)
            self.assertIsNone(first, "%s: message %s differs between two lockstep runs" % (topic, first))
        r = json.loads(a)
        self.assertFalse(r["collision"], a)  # and the crossing is a real test: the own ship gives way
        self.assertTrue(r["manoeuvres"], a)

    def test_recording_into_a_folder_that_does_not_exist_yet(self):
        # As on a fresh checkout: nothing has made the output folder when rosbag record starts.
        out = os.path.join(tempfile.mkdtemp(prefix="asv_record_"), "not", "yet")
        proc = subprocess.run(
            ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=head_on", "planner:=mopso", "lockstep:=true",
             "record:=true", "max_sim_time:=120", "out:=" + out, "output:=log"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=600)
        log = proc.stdout.decode(errors="replace")
        bag_path = os.path.join(out, "run.bag")
        self.assertTrue(os.path.exists(bag_path), "no bag recorded:\n" + log[-3000:])
        import rosbag  # only this test needs it
        with rosbag.Bag(bag_path) as bag:
            topics = bag.get_type_and_topic_info().topics
            for t in ("/sim/nmea", "/own/odom", "/targets", "/risk", "/own/plan", "/own/cmd", "/clock"):
                self.assertIn(t, topics, "topic %s not recorded" % t)
                self.assertGreater(topics[t].message_count, 0, "no message on " + t)

    def test_output_folder_is_named_after_the_scenario_file(self):
        cwd = tempfile.mkdtemp(prefix="asv_out_")
        path = os.path.join(rospkg.RosPack().get_path("asv_bringup"), "test", "sensor_faults.yaml")
        proc = subprocess.run(
            ["roslaunch", "asv_bringup", "scenario.launch", "scenario_file:=" + path, "planner:=ga",
             "lockstep:=true", "max_sim_time:=30", "output:=log"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=600, cwd=cwd, env=dict(os.environ, PWD=cwd))
        result = os.path.join(cwd, "out", "sensor_faults", "ga", "result.json")
        self.assertTrue(os.path.exists(result), proc.stdout.decode(errors="replace")[-3000:])

    def test_batch_and_ros_agree_on_a_sample(self):
        # One eval_ros.py call per pair of the sample (its options select scenarios and planners, and
        # their product would run every planner on every scenario: twice the runs for no new pair).
        script = os.path.join(rospkg.RosPack().get_path("asv_bringup"), "..", "scripts", "eval_ros.py")
        for scenario, planner in SAMPLE:
            out = tempfile.mkdtemp(prefix="asv_eval_ros_")
            proc = subprocess.run([sys.executable, script, "--scenarios", scenario, "--planners", planner, "--out", out],
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=1500)
            log = proc.stdout.decode(errors="replace")
            with open(os.path.join(out, "results.jsonl")) as f:
                rows = [json.loads(l) for l in f if l.strip()]
            self.assertEqual([(r["scenario"], r["planner"]) for r in rows], [(scenario, planner)], log)
            what = "%s/%s: %s" % (scenario, planner, json.dumps(rows[0])[:1500])
            self.assertNotIn("error", rows[0], what)
            self.assertEqual(rows[0]["differences"], [], what)
            self.assertEqual(proc.returncode, 0, log[-3000:])


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "lockstep", Lockstep, sysargs=sys.argv)
