#!/usr/bin/python3
"""plotter_node rostest: what a chart plotter hears on UDP, decoded here field by field.

The node (test/plotter_node.test) has its own map origin 54.6 N 18.8 E. The test publishes the own ship
1000 m east of it sailing 090 at 5 m/s (heading 090), one radar track 1 nm due north of her on 180 at
6 m/s with a risk-picture CPA of 100 m in 300 s, and two lines on nmea_in (an AIVDM and a GGA). Expected
by hand:
 - RMC: 1000 m east at 54.6 N is 1000 / (N cos 54.6) rad of longitude, N = a / sqrt(1 - e^2 sin^2 54.6)
   (WGS84): 0.0154728 deg = 0.9284' -> 01848.9284,E; latitude 54 36.0000' N; 9.7 kn; 090.0;
 - HDT 90.0; no VDO (own_mmsi 0 here);
 - TTM 01: 1.00 nm, bearing 0.0, 11.7 kn, 180.0, CPA 0.05 nm, TCPA 5.0 min, acquisition A (radar);
 - the AIVDM forwarded as it came, the GGA not;
 - own odometry stopped for more than stale_after (2 s): RMC status V, and no TTM.
"""
import math
import socket
import sys
import time
import unittest

import rospy
import rosunit
from asv_msgs.msg import NmeaSentence, RiskAssessment, Target, TargetArray, TargetRisk
from nav_msgs.msg import Odometry

PORT = 10193
AIVDM = "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A"  # the classic example of gpsd's AIVDM/AIVDO guide


def checksum_ok(line):
    body, _, cs = line[1:].partition("*")
    x = 0
    for c in body:
        x ^= ord(c)
    return cs[:2] == "%02X" % x


class PlotterNode(unittest.TestCase):
    def setUp(self):
        rospy.init_node("plotter_tests", anonymous=True)
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind(("127.0.0.1", PORT))
        self.sock.settimeout(0.05)
        self.odom = rospy.Publisher("/own/odom", Odometry, queue_size=10)
        self.targets = rospy.Publisher("/targets", TargetArray, queue_size=10)
        self.risk = rospy.Publisher("/risk", RiskAssessment, queue_size=10)
        self.nmea = rospy.Publisher("/sim/nmea", NmeaSentence, queue_size=10)

    def tearDown(self):
        self.sock.close()

    def listen(self, seconds, publish):
        lines = []
        end = time.time() + seconds
        next_pub = 0.0
        while time.time() < end:
            if time.time() >= next_pub:
                publish()
                next_pub = time.time() + 0.2
            try:
                data, _ = self.sock.recvfrom(4096)
                lines.append(data.decode().rstrip("\r\n"))
            except socket.timeout:
                pass
        return lines

    def publish_all(self):
        now = rospy.Time.now()
        o = Odometry()
        o.header.stamp = now
        o.header.frame_id = "map"
        o.child_frame_id = "own/base_link"
        o.pose.pose.position.x = 1000.0
        o.pose.pose.orientation.w = 1.0  # ENU yaw 0: heading 090
        o.twist.twist.linear.x = 5.0
        self.odom.publish(o)
        t = Target()
        t.id = "arpa:3"
        t.source = Target.SOURCE_ARPA
        t.arpa_number = 3
        t.position.x = 1000.0
        t.position.y = 1852.0
        t.course_over_ground = math.pi
        t.speed_over_ground = 6.0
        t.velocity.y = -6.0
        arr = TargetArray()
        arr.header.stamp = now
        arr.header.frame_id = "map"
        arr.targets = [t]
        self.targets.publish(arr)
        r = RiskAssessment()
        r.header.stamp = now
        tr = TargetRisk()
        tr.target_id = "arpa:3"
        tr.dcpa = 100.0
        tr.tcpa = 300.0
        r.targets = [tr]
        self.risk.publish(r)
        for s in (AIVDM, "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47"):
            self.nmea.publish(NmeaSentence(sentence=s))

    def test_plotter_hears_own_ship_targets_and_traffic(self):
        lines = self.listen(4.0, self.publish_all)
        self.assertTrue(lines, "nothing heard on UDP %d" % PORT)
        self.assertTrue(all(checksum_ok(l) for l in lines), lines)
        rmc = [l.split(",") for l in lines if l.startswith("$GPRMC")]
        self.assertTrue(rmc, lines)
        a, e2 = 6378137.0, 0.00669437999014
        phi = math.radians(54.6)
        n = a / math.sqrt(1 - e2 * math.sin(phi) ** 2)
        dlon_min = math.degrees(1000.0 / (n * math.cos(phi))) * 60.0
        last = rmc[-1]
        self.assertEqual(last[2], "A")
        # Within 2/10000 minute (0.4 m): the map is a tangent plane, 1000 m east of the origin it lies
        # 0.08 m above the ellipsoid and its latitude is 0.00006' south of 54 36'.
        self.assertEqual((last[3][:2], last[4]), ("54", "N"))
        self.assertAlmostEqual(float(last[3][2:]), 36.0, delta=2e-4)
        self.assertEqual((last[5][:3], last[6]), ("018", "E"))
        self.assertAlmostEqual(float(last[5][3:]), 48.0 + dlon_min, delta=2e-4)
        self.assertAlmostEqual(dlon_min, 0.9284, delta=1e-4)  # the figure in the docstring
        self.assertEqual(last[7:9], ["9.7", "90.0"])
        self.assertIn("$HEHDT,90.0,T*16", lines)
        self.assertFalse([l for l in lines if l.startswith("!AIVDO")])  # own_mmsi 0: no VDO
        ttm = [l.split(",") for l in lines if l.startswith("$ECTTM")]
        self.assertTrue(ttm, lines)
        self.assertEqual(ttm[-1][1:11], ["01", "1.00", "0.0", "T", "11.7", "180.0", "T", "0.05", "5.0", "N"])
        self.assertEqual(ttm[-1][-1][0], "A")
        self.assertIn(AIVDM, lines)  # forwarded as it came
        self.assertFalse([l for l in lines if l.startswith("$GPGGA")])
        # The own odometry stops: after stale_after the plotter is told the position is void.
        lines = self.listen(3.5, lambda: None)
        self.assertTrue(lines)
        self.assertTrue(lines[-1].startswith("$GPRMC,") and lines[-1].split(",")[2] == "V", lines[-3:])
        self.assertFalse([l for l in lines[-2:] if l.startswith("$ECTTM")])


if __name__ == "__main__":
    rosunit.unitrun("asv_risk", "plotter_node", PlotterNode, sys.argv)
