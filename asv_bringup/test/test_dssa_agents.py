#!/usr/bin/python3
"""rostest: ships that each run their own distributed DSSA+ planner node reach their goals without a
collision (dssa_four_way.test), also when one ship's intentions are lost for a while (dssa_lossy.test).

Expectations come from the scenario file and the simulator's ground truth, not from the planners:
- on the straight tracks every pair of ships would meet (checked here from the scenario: without
  avoidance the closest approach of some pair is below `collision_m`), so arriving without a collision
  means the agents avoided each other;
- every planning ship of the scenario reports ARRIVAL on sim/events and no COLLISION is reported;
- the smallest distance between any two ships still under way (sim/ships) stays above ~min_separation;
- every ship published intentions on /intentions, in more than one search phase;
- with ~drop_ship: no intention of that ship was heard while its outgoing messages were dropped, and
  some were heard before and after (the loss really happened and the ship came back);
- with ~batch_planner: the same scenario through asv_batch (every ship that planner, its in-process
  exchange, seed 1) has the same outcome (every ship arrives, no collision), each ship's time to her goal
  agrees within TIME_BAND and the closest approach of two ships within GAP_BAND: the ROS agents and the
  batch's run one algorithm, only the exchange's timing differs.

Private parameters: scenario (file), time_limit [s, wall], min_separation [m], collision_m [m],
drop_ship, drop_from, drop_until [s, ROS time], batch_planner.
"""
import json
import math
import os
import sys
import threading
import time
import unittest

import rospy
import rostest
import yaml
from asv_msgs.msg import Intention, SimEvent, TargetArray

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "scripts"))
from batch_result import batch_result  # noqa: E402

SIM_EPOCH = 1.0e9  # ROS time of simulation time 0 (asv_sim sim_node)
TIME_BAND = 0.10  # ROS against asv_batch, each ship's time to her goal: one 1 s step in the paper's 20
GAP_BAND = 0.25  # ... and the closest approach of two ships: the exchange's timing moves a decision a little


def straight_min_distance(a, b):
    """Closest approach of two ships that keep their initial course and speed to their goals [m]."""
    def track(s):
        p = (float(s["position"]["x_m"]), float(s["position"]["y_m"]))
        g = (float(s["goal"]["x_m"]), float(s["goal"]["y_m"]))
        d = math.hypot(g[0] - p[0], g[1] - p[1])
        v = float(s["speed_mps"])
        return p, ((g[0] - p[0]) / d * v, (g[1] - p[1]) / d * v), d / v
    (pa, va, ta), (pb, vb, tb) = track(a), track(b)
    best = float("inf")
    t = 0.0
    while t <= min(ta, tb):
        best = min(best, math.hypot(pa[0] + va[0] * t - pb[0] - vb[0] * t, pa[1] + va[1] * t - pb[1] - vb[1] * t))
        t += 1.0
    return best


class DssaAgents(unittest.TestCase):
    def setUp(self):
        self.scenario_file = rospy.get_param("~scenario")
        with open(self.scenario_file) as f:
            self.scenario = yaml.safe_load(f)
        self.ships = [self.scenario["own_ship"]] + [t for t in self.scenario["targets"] if t.get("behaviour") == "planner"]
        self.names = [s["name"] for s in self.ships]
        self.time_limit = rospy.get_param("~time_limit", 55.0)
        self.min_separation = rospy.get_param("~min_separation", 300.0)
        self.collision_m = rospy.get_param("~collision_m", 200.0)
        self.drop_ship = rospy.get_param("~drop_ship", "")
        self.drop_from = rospy.get_param("~drop_from", 0.0)
        self.drop_until = rospy.get_param("~drop_until", 0.0)
        self.batch_planner = rospy.get_param("~batch_planner", "")
        self.lock = threading.Lock()
        self.events = []
        self.arrived = set()
        self.ended = False
        self.min_pair = (float("inf"), "", "", 0.0)
        self.phases = {n: set() for n in self.names}
        self.max_round = 0
        self.drop_heard = {"before": 0, "during": 0, "after": 0}
        self.subs = [
            rospy.Subscriber("/sim/events", SimEvent, self.on_event, queue_size=100),
            rospy.Subscriber("/sim/ships", TargetArray, self.on_ships, queue_size=100),
            rospy.Subscriber("/intentions", Intention, self.on_intention, queue_size=1000),
        ]

    def on_event(self, m):
        with self.lock:
            self.events.append(m)
            if m.type == SimEvent.ARRIVAL:
                self.arrived.add(m.ship_a)
            self.ended |= m.type == SimEvent.END

    def on_ships(self, m):
        with self.lock:
            under_way = [t for t in m.targets if t.id in self.names and t.id not in self.arrived]
            for i in range(len(under_way)):
                for k in range(i + 1, len(under_way)):
                    a, b = under_way[i], under_way[k]
                    d = math.hypot(a.position.x - b.position.x, a.position.y - b.position.y)
                    if d < self.min_pair[0]:
                        self.min_pair = (d, a.id, b.id, m.header.stamp.to_sec() - SIM_EPOCH)

    def on_intention(self, m):
        with self.lock:
            if m.ship_id in self.phases:
                self.phases[m.ship_id].add(m.phase)
            self.max_round = max(self.max_round, m.round)
            if m.ship_id == self.drop_ship:
                # Judged by its stamp, the sender's state time (odometry, up to one odometry period and
                # one search before the message is sent: hence the 2 s margin at the window's end).
                t = m.header.stamp.to_sec()
                key = "before" if t < self.drop_from else "during" if t < self.drop_until - 2.0 else "after"
                self.drop_heard[key] += 1

    def test_every_ship_arrives_without_collision(self):
        # The premise: without avoidance some pair of ships would collide.
        closest = min(straight_min_distance(a, b) for i, a in enumerate(self.ships) for b in self.ships[i + 1:])
        self.assertLess(closest, self.collision_m, "the scenario needs no avoidance: it tests nothing")

        deadline = time.time() + self.time_limit
        while not rospy.is_shutdown() and time.time() < deadline:
            with self.lock:
                if self.ended or self.arrived >= set(self.names):
                    break
            time.sleep(0.05)
        with self.lock:
            collisions = [(e.ship_a, e.ship_b, e.header.stamp.to_sec() - SIM_EPOCH) for e in self.events
                          if e.type == SimEvent.COLLISION]
            arrivals = {e.ship_a: e.header.stamp.to_sec() - SIM_EPOCH for e in self.events if e.type == SimEvent.ARRIVAL}
            rospy.loginfo("test_dssa_agents: arrivals %s, closest pair %.0f m (%s, %s at t = %.0f s), max round %d, "
                          "phases per ship %s, dropped ship heard %s", arrivals, self.min_pair[0], self.min_pair[1],
                          self.min_pair[2], self.min_pair[3], self.max_round,
                          {n: len(p) for n, p in self.phases.items()}, self.drop_heard)
            self.assertEqual(collisions, [], "collisions (ship, ship, t [s])")
            self.assertEqual(sorted(arrivals), sorted(self.names), "ships that reached their goal")
            self.assertGreater(self.min_pair[0], self.min_separation,
                               "closest approach of two ships under way: %s" % (self.min_pair,))
            for n in self.names:
                self.assertGreater(len(self.phases[n]), 1, "ship %s took part in the exchange" % n)
            if self.drop_ship:
                self.assertEqual(self.drop_heard["during"], 0, "intentions of %s heard inside the drop window" %
                                 self.drop_ship)
                self.assertGreater(self.drop_heard["before"], 0)
                self.assertGreater(self.drop_heard["after"], 0)
        if self.batch_planner:
            self.agree_with_batch(arrivals)

    def agree_with_batch(self, arrivals):
        ref = batch_result(self.scenario_file, "--planner", self.batch_planner, "--agents", self.batch_planner,
                           "--seed", "1")
        ships = {s["name"]: s for s in ref["ships"]}
        rospy.loginfo("test_dssa_agents: asv_batch: times to goal %s, closest %.0f m",
                      {n: s["time_to_goal_s"] for n, s in ships.items()}, ref["min_separation_m"])
        self.assertFalse(ref["collision"], "asv_batch: " + json.dumps(ref))
        for n in self.names:
            self.assertTrue(ships[n]["arrived"], "asv_batch: %s did not arrive" % n)
            want = ships[n]["time_to_goal_s"]
            self.assertLess(abs(arrivals[n] - want), TIME_BAND * want,
                            "%s: time to goal %.1f s through ROS, %.1f s through asv_batch" % (n, arrivals[n], want))
        want = ref["min_separation_m"]
        self.assertLess(abs(self.min_pair[0] - want), GAP_BAND * want,
                        "closest approach %.0f m through ROS, %.0f m through asv_batch" % (self.min_pair[0], want))


if __name__ == "__main__":
    rospy.init_node("test_dssa_agents")
    rostest.rosrun("asv_bringup", "test_dssa_agents", DssaAgents, sys.argv)
