#!/usr/bin/python3
"""nmea_to_bag: an NMEA log with times -> a bag of asv_msgs/NmeaSentence that replay.launch plays.

usage: nmea_to_bag.py INPUT OUTPUT.bag [--topic TOPIC] [--frame-id ID] [--source NAME]
                      [--start TIME] [--duration S]

INPUT is one of:
  * an NMEA log whose sentences carry NMEA 4 tag blocks with a time (\\c:<UNIX seconds or ms>*hh\\!AIVDM...),
    as AIS-catcher, kplex and asv_ais_csv_to_nmea write them;
  * an NMEA log with a leading time column: "<time> <sentence>" or "<time>,<sentence>", the time in UNIX
    seconds or UTC YYYY-MM-DDTHH:MM:SS[.fff][Z];
  * a decoded AIS log in MarineCadastre CSV columns (.csv): converted to AIVDM sentences with
    asv_ais_csv_to_nmea first (types 1/18 and 5/24; --start and --duration are passed to it);
  * gpsd's JSON (gpspipe -w, gpsdecode; a file whose first object line starts with '{', or with a
    time column and then '{'): re-encoded the same way by asv_ais_csv_to_nmea --gpsd-json, since gpsd
    keeps no sentence. A report's time is its line's time column (gpspipe -t) or else the last TPV's.
Each sentence becomes one message stamped with its time (header.stamp, and the bag's record time), the
line kept whole (tag block included) in `sentence`. A sentence before the first time in the file has no
time and is dropped; one without its own time after that takes the last time seen (a multi-sentence
message's later parts): both counted in the summary. Lines that hold no sentence, or a time column that is
no time, are counted as skipped.

  --topic TOPIC    topic written (default /sim/nmea, what replay.launch plays)
  --frame-id ID    header.frame_id (default ais)
  --source NAME    `source` of each message (default: nmea_to_bag:<INPUT file name>)
  --start TIME     with a CSV or gpsd JSON: first report time kept (UTC YYYY-MM-DDTHH:MM:SS)
  --duration S     with a CSV or gpsd JSON: seconds kept from the start

Exit status: 0, 1 when the input cannot be read or holds no timed sentence, 2 on a usage error.
"""
import argparse
import calendar
import os
import re
import shutil
import subprocess
import sys
import time

TAG_TIME = re.compile(r"(?:^|,)c:(\d+)")
LEADING_TIME = re.compile(r"^\s*([0-9]{4}-[0-9]{2}-[0-9]{2}[T ][0-9:.]+Z?|[0-9]{9,}(?:\.[0-9]+)?)[\s,]+(.*)$")


def parse_utc(text):
    """UTC YYYY-MM-DDTHH:MM:SS[.fff][Z] -> UNIX seconds."""
    text = text.rstrip("Z").replace(" ", "T")
    whole, _, frac = text.partition(".")
    seconds = calendar.timegm(time.strptime(whole, "%Y-%m-%dT%H:%M:%S"))
    return seconds + (float("0." + frac) if frac else 0.0)


def tag_time(line):
    """The c: time of a leading NMEA 4 tag block, in seconds (ms when the number is that large)."""
    if not line.startswith("\\"):
        return None
    end = line.find("\\", 1)
    if end < 0:
        return None
    m = TAG_TIME.search(line[1:end].split("*")[0])
    if not m:
        return None
    t = int(m.group(1))
    return t / 1000.0 if t > 100000000000 else float(t)


def split_line(line):
    """(time or None, sentence or None) of one log line."""
    line = line.strip()
    if not line or line.startswith("#"):
        return None, None
    t = tag_time(line)
    if t is not None:
        return t, line
    m = LEADING_TIME.match(line)
    if m and m.group(2).lstrip().startswith(("!", "$", "\\")):
        stamp = m.group(1)
        sentence = m.group(2).strip()
        try:
            t = float(stamp) if re.fullmatch(r"[0-9.]+", stamp) else parse_utc(stamp)
        except ValueError:  # a time column that is no time (month 13...): the line is skipped, counted
            return None, None
        return t, sentence
    start = min([i for i in (line.find("!"), line.find("$"), line.find("\\")) if i >= 0], default=-1)
    return None, (line[start:] if start >= 0 else None)


def is_gpsd_json(path):
    """True when the first line holding a '{' has only a time column (or nothing) before it."""
    with open(path, errors="replace") as f:
        for line in f:
            brace = line.find("{")
            sentence = min((line.find(c) for c in "!$\\" if c in line), default=-1)
            if sentence >= 0 and (brace < 0 or sentence < brace):
                return False  # an NMEA sentence comes first
            if brace >= 0:
                return True
    return False


def csv_to_nmea(path, start, duration, gpsd_json=False):
    tool = shutil.which("asv_ais_csv_to_nmea")
    if tool is None:
        here = os.path.dirname(os.path.abspath(__file__))
        for candidate in (os.path.join(here, "..", "..", "devel", "lib", "asv_core", "asv_ais_csv_to_nmea"),
                          os.path.join(here, "..", "..", "asv_core", "asv_ais_csv_to_nmea")):
            if os.access(candidate, os.X_OK):
                tool = candidate
    if tool is None:
        raise RuntimeError("asv_ais_csv_to_nmea not found (build the workspace and source devel/setup.bash)")
    cmd = [tool, path] + (["--gpsd-json"] if gpsd_json else []) + (["--start", start] if start else []) + (["--duration", str(duration)] if duration else [])
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    sys.stderr.write(proc.stderr)
    if proc.returncode != 0:
        raise RuntimeError("asv_ais_csv_to_nmea failed on " + path)
    return proc.stdout.splitlines()


def write_bag(lines, out, topic, frame_id, source):
    import rosbag
    import rospy
    from asv_msgs.msg import NmeaSentence
    counts = {"written": 0, "untimed": 0, "time taken from the line before": 0, "skipped": 0}
    last = None
    with rosbag.Bag(out, "w") as bag:
        for k, line in enumerate(lines):
            t, sentence = split_line(line)
            if sentence is None:
                counts["skipped"] += 1 if line.strip() and not line.startswith("#") else 0
                continue
            if t is None:
                if last is None:
                    counts["untimed"] += 1
                    continue
                counts["time taken from the line before"] += 1
                t = last
            last = t
            msg = NmeaSentence(sentence=sentence, source=source)
            msg.header.stamp = rospy.Time.from_sec(t)
            msg.header.frame_id = frame_id
            msg.header.seq = counts["written"]
            bag.write(topic, msg, msg.header.stamp)
            counts["written"] += 1
            if k and k % 100000 == 0:
                print("nmea_to_bag: %d lines" % k, file=sys.stderr)
    return counts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0], epilog=__doc__.split("\n", 2)[2],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, usage=argparse.SUPPRESS)
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--topic", default="/sim/nmea")
    ap.add_argument("--frame-id", default="ais")
    ap.add_argument("--source", default="")
    ap.add_argument("--start", default="")
    ap.add_argument("--duration", type=float, default=0.0)
    a = ap.parse_args()
    try:
        if a.input.lower().endswith(".csv"):
            lines = csv_to_nmea(a.input, a.start, a.duration)
        elif is_gpsd_json(a.input):
            lines = csv_to_nmea(a.input, a.start, a.duration, gpsd_json=True)
        else:
            with open(a.input, errors="replace") as f:
                lines = f.read().splitlines()
        counts = write_bag(lines, a.output, a.topic, a.frame_id, a.source or "nmea_to_bag:" + os.path.basename(a.input))
    except (OSError, RuntimeError, ValueError) as e:
        print("nmea_to_bag: %s" % e, file=sys.stderr)
        return 1
    print("nmea_to_bag: %s -> %s on %s: %s" % (a.input, a.output, a.topic,
                                               ", ".join("%s %d" % kv for kv in counts.items())), file=sys.stderr)
    return 0 if counts["written"] else 1


if __name__ == "__main__":
    sys.exit(main())
