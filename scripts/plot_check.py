#!/usr/bin/python3
"""scripts/plot_trajectory.py works, as one JUnit test case (make test counts it).

Usage: plot_check.py OUT.xml
Checks, on synthetic trajectories in a temporary folder (values worked by hand below):
  closest_approach  the distance, time and positions of the closest approach on common time stamps,
                    and None without a common time stamp;
  tick_interval     about 10 time ticks over a run, rounded to 60/120/300/600/900/1800 s;
  plot              a non-empty PNG for a 15-ship CSV (names at the track ends) and for a 2-ship CSV
                    with a land file, also through the --pairs and single-file command lines;
                    exit status 2 for a missing, an empty and a header-only CSV.
Needs python3-matplotlib and python3-numpy (scripts/setup), not ROS. Exit status 1 on a finding.
"""
import contextlib
import io
import math
import os
import subprocess
import sys
import tempfile
import traceback

import junit_case

HERE = os.path.dirname(os.path.abspath(__file__))
HEADER = "t_s,ship,x_m,y_m,course_deg,speed_mps\n"


def straight(x0, y0, course_deg, speed, t_end=600, dt=10, t0=0):
    """Rows (t, x, y, course, speed) of a straight run at constant speed; course clockwise from north."""
    vx = speed * math.sin(math.radians(course_deg))
    vy = speed * math.cos(math.radians(course_deg))
    return [(t, x0 + vx * (t - t0), y0 + vy * (t - t0), course_deg, speed) for t in range(t0, t_end + 1, dt)]


def track(rows):
    return {"t": [float(r[0]) for r in rows], "x": [r[1] for r in rows], "y": [r[2] for r in rows]}


def write_csv(path, ships):
    """ships: [(name, rows)], written interleaved by time as asv_batch does."""
    lines = []
    for name, rows in ships:
        lines += [(r[0], k, "%g,%s,%.3f,%.3f,%.1f,%.2f\n" % (r[0], name, r[1], r[2], r[3], r[4]))
                  for k, r in enumerate(rows)]
    with open(path, "w") as f:
        f.write(HEADER + "".join(text for _, _, text in sorted(lines, key=lambda x: (x[0], x[1]))))


def port_ships(n):
    """The own ship going north through a port, (0, 0) to (0, 3000), with n - 1 targets from a ring of
    3 km around the port's centre (0, 1500), each heading about through it at 2 to 6 m/s."""
    ships = [("own", straight(0, 0, 0, 5))]
    for k in range(1, n):
        ang = 360.0 * k / (n - 1)
        x0 = 3000 * math.sin(math.radians(ang))
        y0 = 1500 + 3000 * math.cos(math.radians(ang))
        ships.append(("target_%02d" % k, straight(x0, y0, (ang + 180 + (k * 7) % 41 - 20) % 360, 2 + k % 5)))
    return ships


def check_closest_approach(pt, fail):
    own = track(straight(0, 0, 0, 5))  # (0, 5 t) for t = 0, 10, ..., 600 s
    # A target on the parallel opposite course 500 m east: from (500, 3000) south at 5 m/s, (500, 3000 - 5 t).
    # Abeam when 5 t = 3000 - 5 t: t = 300 s (a row), both at y = 1500; distance 500 m.
    r = pt.closest_approach(own, track(straight(500, 3000, 180, 5)))
    if r is None:
        fail("parallel opposite course: no closest approach")
    else:
        d, t, oxy, txy = r
        if abs(d - 500.0) > 1.0 or abs(t - 300.0) > 10.0:
            fail("parallel opposite course: %.2f m at %.1f s, expected 500 m at 300 s" % (d, t))
        if math.dist(oxy, (0, 1500)) > 1.0 or math.dist(txy, (500, 1500)) > 1.0:
            fail("parallel opposite course: positions %s %s, expected (0, 1500) (500, 1500)" % (oxy, txy))
    # A target from (1000, 2000) going south-west at 5 m/s, velocity (-3, -4) (course 216.87 deg).
    # Relative to the own ship: r(t) = (1000 - 3 t, 2000 - 9 t), relative velocity (-3, -9).
    # Continuous minimum at t* = (1000*3 + 2000*9) / (3^2 + 9^2) = 21000 / 90 = 233.3 s,
    #   r(t*) = (300, -100), |r| = sqrt(100000) = 316.23 m.
    # On the 10 s rows: t = 230: r = (310, -70), sqrt(101000) = 317.80 m (smallest);
    #                   t = 240: r = (280, -160), sqrt(104000) = 322.49 m.
    # So 317.80 m at 230 s, own ship at (0, 1150), target at (1000 - 690, 2000 - 920) = (310, 1080).
    sw = [(t, 1000 - 3 * t, 2000 - 4 * t, 216.87, 5.0) for t in range(0, 601, 10)]
    r = pt.closest_approach(own, track(sw))
    if r is None:
        fail("south-west target: no closest approach")
    else:
        d, t, oxy, txy = r
        if abs(d - 317.80) > 0.01 or t != 230.0:
            fail("south-west target: %.2f m at %.1f s, expected 317.80 m at 230 s" % (d, t))
        if abs(d - 316.23) > 2.0 or abs(t - 233.3) > 10.0:
            fail("south-west target: %.2f m at %.1f s, not near the continuous 316.23 m at 233.3 s" % (d, t))
        if math.dist(oxy, (0, 1150)) > 1e-6 or math.dist(txy, (310, 1080)) > 1e-6:
            fail("south-west target: positions %s %s, expected (0, 1150) (310, 1080)" % (oxy, txy))
    # Only the common time stamps count: a target whose rows fall at 5, 15, ... s shares none.
    if pt.closest_approach(own, track(straight(500, 3000, 180, 5, t0=5, t_end=595))) is not None:
        fail("no common time stamp: expected None")
    if pt.closest_approach(own, {"t": [], "x": [], "y": []}) is not None:
        fail("empty target: expected None")
    # Common stamps only from 350 s on (the target appears late, after the abeam time):
    # the closest approach is among those.
    late = track(straight(500, 3000, 180, 5))
    late = {k: v[35:] for k, v in late.items()}  # t = 350 ... 600 s: target at (500, 1250 - ...)
    r = pt.closest_approach(own, late)
    # At 350 s: own (0, 1750), target (500, 1250): sqrt(500^2 + 500^2) = 707.11 m, growing after.
    if r is None or abs(r[0] - 707.11) > 0.01 or r[1] != 350.0:
        fail("late target: %s, expected 707.11 m at 350 s" % (r,))
    # The label: 0.42 nm = 777.84 m; 611.6 s rounds to 612 s.
    if pt.cpa_label(777.84, 611.6) != "0.42 nm @ 612 s":
        fail("cpa_label(777.84, 611.6) = %r, expected '0.42 nm @ 612 s'" % pt.cpa_label(777.84, 611.6))


def check_ticks(pt, fail):
    # A tenth of the run, to the nearest step by ratio: 600 s -> 60; 3600 s -> 360 -> 300 (x1.2, not
    # 600 x1.67); 7200 s -> 720 -> 600 (x1.2, not 900 x1.25); 20 min -> 120; 10 h -> 1800 (the largest).
    for run, want in ((600, 60), (3600, 300), (7200, 600), (1200, 120), (36000, 1800), (30, 60)):
        got = pt.tick_interval(run)
        if got != want:
            fail("tick_interval(%d) = %s, expected %d" % (run, got, want))
    # Ticks every 60 s along the own ship (0, 5 t) for 0..600 s: 60, 120, ..., 600 s at y = 300, ..., 3000.
    tk = pt.ticks(track(straight(0, 0, 0, 5)), 60)
    want = [(60.0 * k, 0.0, 300.0 * k) for k in range(1, 11)]
    if len(tk) != len(want) or any(math.dist(a, b) > 1e-6 for a, b in zip(tk, want)):
        fail("ticks every 60 s: %s, expected %s" % (tk, want))
    # Rows every 25 s: the tick at 60 s is interpolated between 50 s and 75 s: y = 5 * 60 = 300.
    tk = pt.ticks(track(straight(0, 0, 0, 5, dt=25)), 60)
    if not tk or math.dist(tk[0], (60.0, 0.0, 300.0)) > 1e-6:
        fail("interpolated tick: %s, expected (60, 0, 300) first" % (tk[:1],))


def check_plot(pt, tmp, fail):
    def png_ok(path):
        with open(path, "rb") as f:
            return f.read(8) == b"\x89PNG\r\n\x1a\n" and os.path.getsize(path) > 10000

    many = os.path.join(tmp, "port.csv")
    write_csv(many, port_ships(15))
    rc = pt.plot(many, os.path.join(tmp, "port.png"), "15 ships", "")
    if rc != 0 or not png_ok(os.path.join(tmp, "port.png")):
        fail("15-ship plot: rc %d, PNG %s" % (rc, "missing or empty"))
    two = os.path.join(tmp, "headon__dssa__s1.csv")
    write_csv(two, [("asv", straight(0, 0, 0, 5)), ("ferry", straight(500, 3000, 180, 5))])
    land = os.path.join(tmp, "headon.land.txt")
    with open(land, "w") as f:
        f.write("polygon 4\n-800 1000\n-300 1000\n-300 1800\n-800 1800\npolygon 3\n900 0\n1400 0\n1150 600\n")
    if len(pt.read_land(land)) != 2:
        fail("read_land: %d polygons, expected 2" % len(pt.read_land(land)))
    rc = pt.plot(two, os.path.join(tmp, "headon.png"), "2 ships with land", "ferry", land)
    if rc != 0 or not png_ok(os.path.join(tmp, "headon.png")):
        fail("2-ship plot with land: rc %d, PNG missing or empty" % rc)
    empty = os.path.join(tmp, "empty.csv")
    open(empty, "w").close()
    header_only = os.path.join(tmp, "header.csv")
    with open(header_only, "w") as f:
        f.write(HEADER)
    for bad in (os.path.join(tmp, "missing.csv"), empty, header_only):
        with contextlib.redirect_stderr(io.StringIO()):  # its 'cannot read' / 'has no rows' are expected
            rc = pt.plot(bad, os.path.join(tmp, "bad.png"), "", "")
        if rc != 2:
            fail("plot(%s): rc %d, expected 2" % (os.path.basename(bad), rc))
    if os.path.exists(os.path.join(tmp, "bad.png")):
        fail("a PNG was written for a missing or empty CSV")
    # Both command lines, as make eval and a user call them.
    script = os.path.join(HERE, "plot_trajectory.py")
    runs = [([script, "--pairs", two, os.path.join(tmp, "pairs.png"), many, os.path.join(tmp, "pairs2.png")], 0),
            ([script, many, os.path.join(tmp, "single.png"), "--title", "T", "--own", "target_03",
              "--land", land], 0),
            ([script, "--pairs", two], 2),
            ([script, "--help"], 0)]
    for cmd, want in runs:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=300)
        if p.returncode != want:
            what = " ".join(os.path.basename(c) for c in cmd[:2])
            fail("%s: exit %d, expected %d: %s" % (what, p.returncode, want, p.stdout[-300:]))
    for name in ("pairs.png", "pairs2.png", "single.png"):
        if not os.path.exists(os.path.join(tmp, name)) or not png_ok(os.path.join(tmp, name)):
            fail("command line: %s missing or empty" % name)


def main():
    out = junit_case.out_path(__doc__)
    findings = []
    try:
        import plot_trajectory as pt
    except ImportError as e:
        findings.append("cannot import plot_trajectory (scripts/setup installs python3-matplotlib "
                        "python3-numpy): %s" % e)
    else:
        with tempfile.TemporaryDirectory(prefix="plot_check.") as tmp:
            for check in (lambda: check_closest_approach(pt, findings.append),
                          lambda: check_ticks(pt, findings.append),
                          lambda: check_plot(pt, tmp, findings.append)):
                try:
                    check()
                except Exception:  # a crash is a finding too
                    findings.append(traceback.format_exc())
    junit_case.write(out, "plot_trajectory", "plot_check",
                     "%d plot_trajectory finding(s)" % len(findings) if findings else None, "\n".join(findings))
    print("plot_check: %s" % ("closest approach, ticks and plots all right" if not findings
                              else "\n" + "\n".join(findings)))
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
