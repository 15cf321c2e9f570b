#!/usr/bin/python3
"""Stage-failure rostest: absence of data is never absence of danger.

A crossing (scenario crossing_give_way, MOPSO, free-running at 3x real time) runs through scenario.launch;
each pipeline node in turn hangs (SIGSTOP: alive for the master, silent on its topics), and once the
stage below has reacted it is killed (SIGKILL) and respawned by the launch. For each, the stage below
must:
- raise an ERROR alarm on /alarms (asv_msgs/Alarm) naming the lost input, within 2 s of simulated time
  of the kill (the planner's loss, seen by sim_node, within its own 3 s timeout plus its 1.5 s wall
  floor);
- with the tracker hung, send /risk with data_ok false, the fault and the age of its targets;
- for a lost picture (ingestion, tracker, risk node), put the planner in degraded operation: a plan
  whose message starts "degraded", or the plan in force kept with the alarm's action saying so, and
  never a new plan made on the missing picture;
- clear the alarm once the respawned node is back (within 15 s of wall time), and the planner plan again.
The run ends with no collision. The fault matrix (stage, detector, detection time, action, recovery)
is printed for the results.

Run by rostest (test/alarms.test), which provides the master.
"""
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest
from xmlrpc.client import ServerProxy

import rosgraph
import rospy
import rosunit
from asv_msgs.msg import Alarm, Plan, RiskAssessment
from rosgraph_msgs.msg import Clock

RATE = 3.0
# [s, simulated] the run's length: the five faults take about 75 simulated seconds (each: detection,
# 1 s of wall time hung, respawn, the alarm cleared, 2 s to settle, at RATE); after them the test only
# waits for the run to end, so twice that is enough, and the test fails, naming it, if the faults
# outlast the run.
SIM_TIME = 160.0
# stage killed -> (node that detects it, the input it names, detection limit [s, simulated])
FAULTS = [
    ("/tracker", "/risk_node", "/targets", 2.0),
    ("/risk_node", "/planner_own", "/risk", 2.0),
    ("/ais_node", "/tracker", "/ais/targets", 2.0),
    ("/arpa_node", "/tracker", "/arpa/targets", 2.0),
    ("/planner_own", "/sim_node", "/own/cmd", 3.0 + 1.5 * RATE + 0.5),
]


class Alarms(unittest.TestCase):
    def setUp(self):
        rospy.init_node("alarm_tests", anonymous=True, disable_signals=True)
        self.lock = threading.Lock()
        self.alarms = []  # (wall, msg)
        self.plans = []   # (wall, sim, msg)
        self.sim_time = 0.0
        self.sim_start = None  # the run's first /clock (the simulator's epoch)
        self.risks = []   # (wall, msg)
        self.subs = [
            rospy.Subscriber("/alarms", Alarm, self.on_alarm, queue_size=200),
            rospy.Subscriber("/own/plan", Plan, self.on_plan, queue_size=200),
            rospy.Subscriber("/clock", Clock, self.on_clock, queue_size=10),
            rospy.Subscriber("/risk", RiskAssessment, self.on_risk, queue_size=200),
        ]

    def on_risk(self, m):
        with self.lock:
            self.risks.append((time.monotonic(), m))

    def on_alarm(self, m):
        with self.lock:
            self.alarms.append((time.monotonic(), m))

    def on_plan(self, m):
        with self.lock:
            self.plans.append((time.monotonic(), m.header.stamp.to_sec(), m))

    def on_clock(self, m):
        self.sim_time = m.clock.to_sec()
        if self.sim_start is None:
            self.sim_start = self.sim_time

    def wait(self, cond, timeout):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            with self.lock:
                r = cond()
            if r:
                return r
            time.sleep(0.02)
        return None

    def hang(self, node):
        uri = rosgraph.Master("/alarm_tests").lookupNode(node)
        pid = ServerProxy(uri).getPid("/alarm_tests")[2]
        t = self.sim_time
        os.kill(pid, signal.SIGSTOP)
        return t, pid

    def fault(self, stage, detector, topic, limit):
        start = time.monotonic()
        killed_at, pid = self.hang(stage)
        raised = self.wait(lambda: next((m for w, m in self.alarms if w >= start and m.source == detector
                                         and m.level == Alarm.ERROR and topic in m.inputs), None), 20.0)
        self.assertIsNotNone(raised, "%s killed: no alarm from %s naming %s" % (stage, detector, topic))
        delay = raised.header.stamp.to_sec() - killed_at
        self.assertLessEqual(delay, limit, "%s: detected %.2f s (simulated) after the kill" % (stage, delay))
        action = raised.action
        if stage == "/tracker":
            # The risk node says its picture is old; it never sends it as a clear sea.
            flagged = self.wait(lambda: next((m for w, m in self.risks if w >= start and not m.data_ok), None), 5.0)
            self.assertIsNotNone(flagged, "risk never sent with data_ok false while the tracker hung")
            self.assertIn("/targets", flagged.data_fault)
            self.assertGreater(flagged.targets_age, 1.5)
        if stage != "/planner_own":
            degraded = self.wait(lambda: next((m for w, m in self.alarms if w >= start and m.source == "/planner_own"
                                               and m.level == Alarm.ERROR), None), 10.0)
            self.assertIsNotNone(degraded, "%s killed: the planner never went into degraded operation" % stage)
            self.assertIn("degraded", degraded.action)
            action = degraded.action
        time.sleep(1.0)
        os.kill(pid, signal.SIGKILL)  # the launch respawns it
        if stage != "/planner_own":
            # No plan made on the missing picture while the alarm is up: every plan in between is degraded.
            with self.lock:
                during = [m for w, s, m in self.plans if w >= start and s >= killed_at]
        cleared = self.wait(lambda: next((m for w, m in self.alarms if w >= start and m.source == detector
                                          and m.level == Alarm.OK and m.header.stamp >= raised.header.stamp),
                                         None), 15.0)
        self.assertIsNotNone(cleared, "%s: the alarm of %s never cleared after the respawn" % (stage, detector))
        if stage != "/planner_own":
            with self.lock:
                before_clear = [m for m in during if m.header.stamp < cleared.header.stamp]
            made = [m.message for m in before_clear if not m.message.startswith("degraded")
                    and m.status == Plan.STATUS_OK and "picture back" not in m.message]
            self.assertEqual(made, [], "%s: plans made on a missing picture" % stage)
        recovered = cleared.header.stamp.to_sec() - killed_at
        print("fault matrix: %-13s detected by %-13s in %.2f s (sim) | action: %s | alarm cleared %.1f s after the kill"
              % (stage, detector, delay, action, recovered))
        return delay

    def test_each_stage_killed_in_turn(self):
        out = tempfile.mkdtemp(prefix="asv_alarms_")
        result = os.path.join(out, "result.json")
        launch = subprocess.Popen(
            ["roslaunch", "asv_bringup", "scenario.launch", "scenario:=crossing_give_way", "planner:=mopso",
             "rate:=%g" % RATE, "max_sim_time:=%g" % SIM_TIME, "start_delay:=2.0", "out:=" + out, "result:=" + result,
             "geojson:=", "output:=log"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        try:
            self.assertTrue(self.wait(lambda: self.plans, 60.0), "no plan from the planner node")
            time.sleep(3.0)
            with self.lock:
                early = [m for w, m in self.alarms if m.level == Alarm.ERROR]
            self.assertEqual(early, [], "alarms in a healthy run: %s" % [(m.source, m.causes) for m in early])
            for stage, detector, topic, limit in FAULTS:
                self.fault(stage, detector, topic, limit)
                time.sleep(2.0)  # the pipeline settles before the next fault
            elapsed = self.sim_time - (self.sim_start or 0.0)
            print("stage_alarms: the faults ended at t = %.0f s (simulated) of %.0f" % (elapsed, SIM_TIME))
            self.assertLess(elapsed, SIM_TIME - 10.0, "the faults outlasted the run: raise SIM_TIME")
            log, _ = launch.communicate(timeout=300)
        finally:
            if launch.poll() is None:
                launch.terminate()
                launch.wait(timeout=30)
        self.assertEqual(launch.returncode, 0, log.decode(errors="replace")[-3000:])
        with open(result) as f:
            r = json.load(f)
        self.assertFalse(r["collision"], json.dumps(r))


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "alarms", Alarms, sysargs=sys.argv)
