#!/usr/bin/python3
"""Scripted encounter for the risk node demo (asv_risk/launch/demo.launch).

Plays an own ship and three targets at constant velocity over 15 minutes of scenario time, faster
than real time, feeding risk_node through its real topics (odom, targets), and prints how risk_node
judges each target: range, TCPA, DCPA, CRI, risk level, encounter, own role and the compliance flag.
The targets:
  ts1  crossing from port: the give-way vessel that never gives way (Hu et al. 2017, Fig. 6)
  ts2  head-on, offset 300 m to starboard
  ts3  crossing from starboard: the own ship must give way
Parameters (private): ~step (scenario seconds per update, 30), ~duration (900), ~wall_step (0.05 s),
~table (path of the text table to write; empty = none).
"""
import math
import sys

import rospy
from asv_msgs.msg import RiskAssessment, Target, TargetArray
from nav_msgs.msg import Odometry

KN = 1852.0 / 3600.0
# The stack's vocabulary (asv_msgs/TargetRisk, the run result's encounter and own_role).
ENC = {0: "none", 1: "head_on", 2: "crossing", 3: "overtaking", 4: "being_overtaken"}
ROLE = {0: "none", 1: "give_way", 2: "stand_on"}
RISK = {0: "0 none", 1: "1 risk", 2: "2 URGENT"}

OWN_SPEED = 12 * KN
# name: (x0, y0, course_deg, speed) in metres and m/s at t = 0; the own ship starts at (0, 0) heading north.
TARGETS = {
    "ts1": (-12 * KN * 1000, 12 * KN * 1000, 90.0, 12 * KN),          # meets us at t = 1000 s
    "ts2": (300.0, 16000.0, 180.0, 10 * KN),
    "ts3": (9000.0, 9000.0 + 0.0, 270.0, 9 * KN),
}


def main():
    rospy.init_node("encounter_demo")
    step = rospy.get_param("~step", 30.0)
    duration = rospy.get_param("~duration", 900.0)
    wall_step = rospy.get_param("~wall_step", 0.05)
    table_path = rospy.get_param("~table", "")
    odom_pub = rospy.Publisher("odom", Odometry, queue_size=10)
    tgt_pub = rospy.Publisher("targets", TargetArray, queue_size=10)
    latest = {}

    def on_risk(msg):
        latest[msg.header.stamp] = msg

    rospy.Subscriber("risk", RiskAssessment, on_risk)
    deadline = rospy.Time.now() + rospy.Duration(20.0)
    while tgt_pub.get_num_connections() == 0 or odom_pub.get_num_connections() == 0:
        if rospy.is_shutdown() or rospy.Time.now() > deadline:
            rospy.logfatal("risk_node did not subscribe to odom/targets within 20 s")
            sys.exit(1)
        rospy.sleep(0.05)

    lines = []
    header = "%6s  %-4s %8s %8s %8s %5s  %-8s %-20s %-14s %s" % (
        "t [s]", "ship", "range nm", "TCPA min", "DCPA nm", "CRI", "risk", "encounter", "own role", "flag")
    print(header)
    lines.append(header)
    last_state = {}
    t = 0.0
    while t <= duration and not rospy.is_shutdown():
        now = rospy.Time.now()
        od = Odometry()
        od.header.stamp = now
        od.header.frame_id = "map"
        od.child_frame_id = "own/base_link"
        od.pose.pose.position.y = OWN_SPEED * t
        od.pose.pose.orientation.z = math.sin(math.pi / 4)
        od.pose.pose.orientation.w = math.cos(math.pi / 4)
        od.twist.twist.linear.x = OWN_SPEED
        odom_pub.publish(od)
        rospy.sleep(wall_step / 2)
        arr = TargetArray()
        arr.header.stamp = rospy.Time.now()
        arr.header.frame_id = "map"
        for name, (x0, y0, c, v) in TARGETS.items():
            tg = Target()
            tg.id = name
            tg.source = Target.SOURCE_AIS
            cr = math.radians(c)
            tg.position.x = x0 + v * math.sin(cr) * t
            tg.position.y = y0 + v * math.cos(cr) * t
            tg.course_over_ground = cr
            tg.speed_over_ground = v
            tg.velocity.x, tg.velocity.y = v * math.sin(cr), v * math.cos(cr)
            tg.stamp = arr.header.stamp
            arr.targets.append(tg)
        tgt_pub.publish(arr)
        wait_until = rospy.Time.now() + rospy.Duration(5.0)
        while arr.header.stamp not in latest and rospy.Time.now() < wait_until and not rospy.is_shutdown():
            rospy.sleep(0.005)
        ra = latest.pop(arr.header.stamp, None)
        if ra is None:
            rospy.logerr("no risk assessment for t = %.0f s", t)
        else:
            for r in ra.targets:
                state = (r.risk_level, r.encounter, r.compliant)
                if last_state.get(r.target_id) != state or t >= duration:
                    last_state[r.target_id] = state
                    line = "%6.0f  %-4s %8.2f %8.1f %8.2f %5.2f  %-8s %-20s %-14s %s" % (
                        t, r.target_id, r.range / 1852.0, r.tcpa / 60.0, r.dcpa / 1852.0, r.cri,
                        RISK[r.risk_level], ENC[r.encounter], ROLE[r.own_role],
                        "compliant" if r.compliant else "NON-COMPLIANT (Rule 2(b))")
                    print(line)
                    lines.append(line)
        t += step
        rospy.sleep(wall_step / 2)
    if table_path:
        with open(table_path, "w") as f:
            f.write("\n".join(lines) + "\n")
    print("encounter_demo: %d scenario seconds assessed; rows are printed when a target's risk, "
          "encounter or flag changes" % duration)


if __name__ == "__main__":
    main()
