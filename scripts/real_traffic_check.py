#!/usr/bin/python3
"""scripts/real_traffic.py picks its windows as documented, as one JUnit test case (make test counts it).

Usage: real_traffic_check.py OUT.xml
On a synthetic MarineCadastre CSV (positions worked by hand below): a vessel under way that meets two others
is picked first; one that meets one is picked after it; a vessel alone, and one making 2 kn (under the 3 kn
of "under way") are never picked; windows starting in the log's first half are the tuning range, the
second half the test range. Needs no ROS and no build. Exit status 1 on a finding.
"""
import os
import sys
import tempfile

import junit_case

HEADER = ("BaseDateTime,LON,LAT,MMSI,SOG,COG,Heading,VesselName,IMO,CallSign,VesselType,Status,Length,Width,"
          "Draft,Cargo,TranscieverClass\n")
KN = 1852.0 / 3600.0
M_PER_DEG_LAT = 110540.0  # the picker's scale (real_traffic.position)


def rows(mmsi, lat0, lon, knots, north, minutes=40):
    """A vessel on a meridian from lat0, north (or south) at `knots`, a report a minute from 00:00."""
    out = []
    for k in range(minutes + 1):
        lat = lat0 + (1 if north else -1) * knots * KN * 60.0 * k / M_PER_DEG_LAT
        out.append("2020-06-30T00:%02d:00,%.6f,%.6f,%d,%.1f,%.1f,511,,,,,,,,,,A\n" % (
            k, lon, lat, mmsi, knots, 0.0 if north else 180.0))
    return out


def check_picks(finding):
    # A (111) north at 10 kn on 74.000 W from 40.600 N; B (222) south at 10 kn on 73.9905 W, 804 m east of A
    # (0.0095 deg x 84.6 km at 40.6 N); C (333) far east, alone; D (444) north at 2 kn on 74.006 W, 508 m
    # west of A and 1312 m from B. Window 00:05-00:15: A (10 kn, 3 km made good) meets B and D; B meets A;
    # C meets nobody; D is not under way.
    import real_traffic as rt
    # E (555) and F (666) meet at 00:33 far from the others, 423 m apart (0.005 deg of longitude), each at
    # 10 kn: 0.002792 deg of latitude a minute, F from 40.500 + 2 x 33 x 0.002792 = 40.6843 N.
    lines = (rows(111, 40.600, -74.0000, 10, True) + rows(222, 40.640, -73.9905, 10, False) +
             rows(333, 40.600, -73.5000, 10, True) + rows(444, 40.605, -74.0060, 2, True) +
             rows(555, 40.500, -73.8000, 10, True) + rows(666, 40.6843, -73.7950, 10, False))
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "log.csv")
        with open(path, "w") as f:
            # Two rows that must be counted, not read: a broken latitude and SOG 102.3 ("not available").
            f.write(HEADER + "".join(lines) + "2020-06-30T00:01:00,-74.0,north,777,5.0,0.0\n" +
                    "2020-06-30T00:01:00,-74.0,40.6,777,102.3,0.0\n")
        tracks, rejected = rt.read_log(path)
    if rejected != 2 or 777 in tracks:
        finding("read_log rejected %d rows (expected the 2 bad ones) and kept 777: %s" % (rejected, 777 in tracks))
    start = rt.utc("2020-06-30T00:05:00")
    picks = rt.pick(tracks, start, 600.0, 3)
    if picks != [111, 222]:
        finding("pick(3) = %s, expected [111, 222] (A meets two, B one; C alone, D at 2 kn)" % picks)
    if rt.pick(tracks, start, 600.0, 1) != [111]:
        finding("pick(1) should keep the vessel meeting the most, 111")
    # The log runs 00:00-00:40, its middle 00:20; windows of 600 s every 480 s from 00:05: 00:05 and 00:13
    # (tuning), 00:21 and 00:29 (test); 00:37 + 600 s is past the log's end. A meets B and D only in the
    # first (at 00:05 D is 680 m north and 508 m west of her: 849 m), E meets F only in the last (at 00:31
    # they are still 2 x 2 x 0.002792 deg, 1.23 km, apart).
    picked = rt.windows(tracks, 600.0, 480.0, 3)
    starts = sorted({(rng, rt.iso(t)[11:16]) for rng, t, _ in picked})
    expected = [("test", "00:29"), ("tuning", "00:05")]
    if sorted(m for rng, _, m in picked if rng == "test") != [555, 666]:
        finding("test range picks %s, expected 555 and 666" % picked)
    if starts != expected:
        finding("windows %s, expected %s" % (starts, expected))


def main():
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    return junit_case.run(__doc__, "real_traffic", "real_traffic_check", [check_picks],
                          "windows picked and split as documented")


if __name__ == "__main__":
    sys.exit(main())
