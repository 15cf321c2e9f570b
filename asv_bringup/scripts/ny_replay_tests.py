#!/usr/bin/python3
"""Real-traffic replay rostest (test/ny_replay.test): seven minutes of the New York Harbor AIS log.

The log (../shared/data/ais/real/, MarineCadastre CSV; outside the repository) is turned into a bag by
nmea_to_bag.py and replayed by replay.launch with own_mmsi:=367782880 (the ferry H203, 17 kn): her
odometry comes from her own AIS reports (own_ship_node), the rest of the traffic goes through ais_node,
the tracker and risk_node. Without the log the test is skipped, saying why.

Expected, computed here from the CSV independently of the pipeline (flat-earth metres round the origin,
each vessel dead-reckoned from her last report with its SOG and COG, the source's negative COG
unwrapped by +409.6):
1. every vessel that reports in the window becomes a target (at least 90 % of them: one report just
   before the end may not be published), and the own ship never does;
2. for the ferry H204 (MMSI 367780930) crossing ahead, the DCPA and TCPA risk_node reports match the
   dead-reckoned ones within 150 m + 10 % and 30 s + 10 %, whenever both ships reported 5-60 s before
   (the replay runs free: just after a report the pipeline may still show the one before).
"""
import calendar
import collections
import csv
import math
import os
import subprocess
import tempfile
import time
import unittest

import rospkg
import rospy
import rosunit
from asv_msgs.msg import RiskAssessment, TargetArray

OWN, OTHER = 367782880, 367780930
START, DURATION = "2020-06-30T00:08:00", 420
ORIGIN = (40.65, -74.05)


def log_path():
    shared = os.environ.get("ASV_SHARED_DIR") or os.path.join(
        rospkg.RosPack().get_path("asv_bringup"), "..", "..", "shared")
    return os.path.join(shared, "data", "ais", "real", "NYHarbor_2020_06_30_first_hour.csv")


def utc(text):
    return calendar.timegm(time.strptime(text, "%Y-%m-%dT%H:%M:%S"))


def read_log(path):
    """MMSI -> time-ordered (t, x, y, vx, vy) in flat-earth metres round ORIGIN."""
    lat0, lon0 = ORIGIN
    out = collections.defaultdict(list)
    with open(path) as f:
        for r in csv.DictReader(f):
            cog = float(r["COG"])
            cog = cog + 409.6 if cog < 0 else cog
            v = float(r["SOG"]) * 1852.0 / 3600.0
            x = math.radians(float(r["LON"]) - lon0) * 6371000.0 * math.cos(math.radians(lat0))
            y = math.radians(float(r["LAT"]) - lat0) * 6371000.0
            out[int(r["MMSI"])].append((utc(r["BaseDateTime"]), x, y, v * math.sin(math.radians(cog)),
                                        v * math.cos(math.radians(cog))))
    for track in out.values():
        track.sort()
    return out


def dead_reckoned(track, t, min_age=5.0, max_age=60.0):
    """The vessel at t from her last report, when that is between min_age and max_age old (just after a
    report the pipeline may still show the one before: it runs free, not in lockstep)."""
    last = [p for p in track if p[0] <= t]
    if not last or not min_age <= t - last[-1][0] <= max_age:
        return None
    t0, x, y, vx, vy = last[-1]
    return x + vx * (t - t0), y + vy * (t - t0), vx, vy


def cpa(own, other):
    dx, dy, dvx, dvy = other[0] - own[0], other[1] - own[1], other[2] - own[2], other[3] - own[3]
    dv2 = dvx * dvx + dvy * dvy
    tcpa = -(dx * dvx + dy * dvy) / dv2 if dv2 > 1e-9 else 0.0
    return math.hypot(dx + dvx * tcpa, dy + dvy * tcpa), tcpa


class NyReplay(unittest.TestCase):
    def test_real_traffic_targets_and_risk(self):
        path = log_path()
        if not os.path.exists(path):
            self.skipTest("New York AIS log not found at %s: the replay needs the shared data" % path)
        rospy.init_node("ny_replay_tests", anonymous=True, disable_signals=True)
        bag = os.path.join(tempfile.mkdtemp(prefix="asv_ny_"), "ny.bag")
        subprocess.run([os.path.join(os.path.dirname(os.path.abspath(__file__)), "nmea_to_bag.py"), path, bag,
                        "--start", START, "--duration", str(DURATION)], check=True, timeout=120)
        seen, risks = set(), []
        subs = [rospy.Subscriber("/replay/targets", TargetArray, lambda m: seen.update(t.mmsi for t in m.targets)),
                rospy.Subscriber("/replay/risk", RiskAssessment, risks.append, queue_size=1000)]
        proc = subprocess.run(["roslaunch", "asv_bringup", "replay.launch", "bag:=" + bag, "rate:=4",
                               "origin_lat_deg:=%.2f" % ORIGIN[0], "origin_lon_deg:=%.2f" % ORIGIN[1],
                               "own_mmsi:=%d" % OWN], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              timeout=400)
        for s in subs:
            s.unregister()
        self.assertEqual(proc.returncode, 0, proc.stdout.decode(errors="replace")[-3000:])
        log = read_log(path)
        t0 = utc(START)
        expected = {m for m, track in log.items() if m != OWN and any(t0 <= p[0] < t0 + DURATION for p in track)}
        self.assertNotIn(OWN, seen, "the own ship is no target")
        self.assertGreaterEqual(len(seen & expected), 0.9 * len(expected),
                                "%d of %d vessels became targets" % (len(seen & expected), len(expected)))
        checked = 0
        for r in risks:
            t = r.header.stamp.to_sec()
            own, other = dead_reckoned(log[OWN], t), dead_reckoned(log[OTHER], t)
            mine = [x for x in r.targets if x.mmsi == OTHER]
            if not (r.data_ok and own and other and mine):
                continue
            dcpa, tcpa = cpa(own, other)
            self.assertLess(abs(mine[0].dcpa - dcpa), 150.0 + 0.1 * dcpa, "t=%.0f DCPA %.0f, expected %.0f" %
                            (t - t0, mine[0].dcpa, dcpa))
            self.assertLess(abs(mine[0].tcpa - tcpa), 30.0 + 0.1 * abs(tcpa), "t=%.0f TCPA %.0f, expected %.0f" %
                            (t - t0, mine[0].tcpa, tcpa))
            checked += 1
        self.assertGreater(checked, 20, "too few risk assessments of the pair to compare")
        dangerous = collections.Counter(x.mmsi for r in risks for x in r.targets if x.risk_level >= 1)
        print("ny_replay: %d targets of %d vessels; %d assessments of %d compared; risk level >= 1: %s" %
              (len(seen & expected), len(expected), checked, OTHER, dict(dangerous)))


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "ny_replay", NyReplay)
