#!/usr/bin/python3
"""nmea_to_bag rostest (test/nmea_to_bag.test): logs with times become bags replay.launch plays.

Expected values by hand:
1. A tag-block log: each sentence stamped with its c: time (seconds, or milliseconds when that large);
   the second part of a two-sentence message, which has no tag block, takes the first part's time;
   a comment is ignored, a line with no sentence is skipped, a sentence before any time is dropped.
2. A log with a leading UTC time column: 2020-06-30T00:00:05Z is 1593475205 s.
3. A MarineCadastre CSV (two rows written here): through asv_ais_csv_to_nmea and back through
   asv_ais_decode -u, the class B row gives a type 18 with lat 40.54291 deg = 24325746 (1/10000 min),
   lon -74.02433 deg = -44414598, SOG 19.0 kn = 190, and COG -61.8 (the source's 12-bit wrap) =
   -61.8 + 409.6 = 347.8 deg = 3478; its static data as type 24 parts A (name) and B (length 26 m ->
   13 + 13, beam 5 m -> 3 + 3 rounded); the class A row a type 1 and a type 5, stamped 2020-06-30T00:01:00
   = 1593475260 s.
4. gpsd JSON (gpspipe -w, written here): a type 5 then a type 1 before any time (refused: untimed), a
   TPV at 00:00:10.5, the type 1 again (stamped 1593475210, the TPV's second), and an unscaled type 18
   with a gpspipe -t time column 2020-06-30 00:00:20 (1593475220) and speed/course not available.
   Decoded back: type 1 lat 40.6175 deg = 24370500 and lon -74.0475 = -44428500 (1/10000 min), speed
   12.3 kn = 123, course 224.0 = 2240, heading 215, name EVER DIADEM, length 225 + 70 = 295 m -> 148 +
   148; the type 18 keeps speed 1023 and course 3600 (not available).
5. gpsd itself: gpsdecode reads what the re-encoding wrote, and its JSON fed back gives the same
   positions, speeds, courses and headings (a round trip through an independent decoder).
"""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

import rosbag
import rosunit

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "nmea_to_bag.py")


def devel_tool(name):
    for d in os.environ.get("CMAKE_PREFIX_PATH", "").split(":"):
        p = os.path.join(d, "lib", "asv_core", name)
        if os.access(p, os.X_OK):
            return p
    raise AssertionError(name + " not found under CMAKE_PREFIX_PATH")


def convert(text, name, *args):
    d = tempfile.mkdtemp(prefix="asv_nmea_to_bag_")
    src, bag = os.path.join(d, name), os.path.join(d, "out.bag")
    with open(src, "w") as f:
        f.write(text)
    proc = subprocess.run([TOOL, src, bag] + list(args), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, timeout=60)
    msgs = []
    if os.path.exists(bag):
        with rosbag.Bag(bag) as b:
            msgs = [(topic, m, t) for topic, m, t in b.read_messages()]
    return proc, msgs


TYPE1 = "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A"
TYPE5 = ["!AIVDM,2,1,3,A,55?MbV02;H;s<HtKP00EHE:0@T4@Dl0000000016L961O5Gf0NSQEp6ClRh0,0*0C",
         "!AIVDM,2,2,3,A,00000000000,2*27"]


def tagged(sentence, t):
    body = "s:test,c:%d" % t
    cs = 0
    for ch in body:
        cs ^= ord(ch)
    return "\\%s*%02X\\%s" % (body, cs, sentence)


class NmeaToBag(unittest.TestCase):
    def test_tag_block_times(self):
        text = "\n".join([TYPE1,  # before any time: dropped
                          "# a comment",
                          tagged(TYPE1, 1593475200),
                          "garbage without a sentence",
                          tagged(TYPE5[0], 1593475201000),  # milliseconds
                          TYPE5[1]]) + "\n"
        proc, msgs = convert(text, "log.nmea")
        self.assertEqual(proc.returncode, 0, proc.stdout)
        self.assertEqual([m.header.stamp.to_sec() for _, m, _ in msgs], [1593475200.0, 1593475201.0, 1593475201.0])
        self.assertTrue(all(topic == "/sim/nmea" for topic, _, _ in msgs))
        self.assertEqual([t.to_sec() for _, _, t in msgs], [m.header.stamp.to_sec() for _, m, _ in msgs])
        self.assertEqual(msgs[2][1].sentence, TYPE5[1])
        self.assertEqual(msgs[0][1].header.frame_id, "ais")
        self.assertIn("untimed 1", proc.stdout)
        self.assertIn("skipped 1", proc.stdout)

    def test_leading_time_column(self):
        proc, msgs = convert("2020-06-30T00:00:05Z " + TYPE1 + "\n2020-13-30T00:00:06Z " + TYPE1 + "\n1593475206.5," +
                             TYPE1 + "\n", "log.txt", "--topic", "/nmea")
        self.assertEqual(proc.returncode, 0, proc.stdout)
        self.assertEqual([m.header.stamp.to_sec() for _, m, _ in msgs], [1593475205.0, 1593475206.5])
        self.assertEqual(msgs[0][0], "/nmea")
        self.assertEqual(msgs[0][1].sentence, TYPE1)
        self.assertIn("skipped 1", proc.stdout)  # month 13: not a time, the line is not guessed

    def test_marine_cadastre_csv(self):
        header = ("BaseDateTime,LON,LAT,MMSI,SOG,COG,Heading,VesselName,IMO,CallSign,VesselType,Status,"
                  "Length,Width,Draft,Cargo,TranscieverClass,ETA\n")
        rows = ("2020-06-30T00:00:30,-74.02433,40.54291,366999618,19.0,-61.8,349.0,CG SHRIKE,,NPBG,90.0,0.0,"
                "26.0,5.0,,,B,\n"
                "2020-06-30T00:01:00,-74.07157,40.64409,367000140,10.0,90.0,511.0,NEWHOUSE,,WYR3371,60.0,0.0,"
                "94.0,21.0,,69.0,A,\n")
        proc, msgs = convert(header + rows, "log.csv")
        self.assertEqual(proc.returncode, 0, proc.stdout)
        sentences = "\n".join(m.sentence for _, m, _ in msgs) + "\n"
        decoded = subprocess.run([devel_tool("asv_ais_decode"), "-u", "-s"], input=sentences,
                                 stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout
        objs = [json.loads(line) for line in decoded.splitlines()]
        self.assertEqual([o["type"] for o in objs], [18, 24, 24, 1, 5])
        b = objs[0]
        self.assertEqual((b["mmsi"], b["lat"], b["lon"], b["speed"], b["course"], b["heading"]),
                         (366999618, 24325746, -44414598, 190, 3478, 349))
        self.assertEqual(objs[1]["shipname"], "CG SHRIKE")
        self.assertEqual((objs[2]["to_bow"], objs[2]["to_stern"], objs[2]["to_port"]), (13, 13, 3))
        self.assertEqual(objs[3]["heading"], 511)  # Heading 511: not available, kept so
        self.assertEqual(msgs[-1][1].header.stamp.to_sec(), 1593475260.0)

    GPSD = "\n".join([
        '{"class":"AIS","device":"stdin","type":5,"repeat":0,"mmsi":351759000,"scaled":true,"imo":9134270,'
        '"callsign":"3FOF8","shipname":"EVER DIADEM","shiptype":70,"to_bow":225,"to_stern":70,"to_port":1,'
        '"to_starboard":31,"epfd":1,"draught":12.2,"destination":"NEW YORK","dte":0}',
        '{"class":"AIS","device":"stdin","type":1,"repeat":0,"mmsi":351759000,"scaled":true,"status":0,'
        '"turn":0,"speed":12.3,"accuracy":true,"lon":-74.0475,"lat":40.6175,"course":224.0,"heading":215}',
        '{"class":"TPV","device":"/dev/ttyUSB0","mode":3,"time":"2020-06-30T00:00:10.500Z","lat":40.6,"lon":-74.0}',
        '{"class":"AIS","device":"stdin","type":1,"repeat":0,"mmsi":351759000,"scaled":true,"status":0,'
        '"turn":0,"speed":12.3,"accuracy":true,"lon":-74.0475,"lat":40.6175,"course":224.0,"heading":215}',
        '2020-06-30 00:00:20: {"class":"AIS","device":"stdin","type":18,"repeat":0,"mmsi":338000001,'
        '"scaled":false,"speed":1023,"accuracy":false,"lon":-44428500,"lat":24370500,"course":3600,'
        '"heading":511,"second":60}']) + "\n"

    def decode(self, msgs, *flags):
        sentences = "\n".join(m.sentence for _, m, _ in msgs) + "\n"
        out = subprocess.run([devel_tool("asv_ais_decode")] + list(flags), input=sentences,
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout
        return [json.loads(line) for line in out.splitlines()]

    def test_gpsd_json(self):
        proc, msgs = convert(self.GPSD, "gpspipe.json")
        self.assertEqual(proc.returncode, 0, proc.stdout)
        self.assertIn("untimed 1", proc.stdout)
        self.assertEqual([m.header.stamp.to_sec() for _, m, _ in msgs][0], 1593475210.0)
        self.assertEqual(msgs[-1][1].header.stamp.to_sec(), 1593475220.0)
        objs = self.decode(msgs, "-u", "-s")
        self.assertEqual([o["type"] for o in objs], [1, 5, 18, 24, 24])
        a = objs[0]
        self.assertEqual((a["mmsi"], a["lat"], a["lon"], a["speed"], a["course"], a["heading"]),
                         (351759000, 24370500, -44428500, 123, 2240, 215))
        self.assertEqual((objs[1]["shipname"], objs[1]["to_bow"], objs[1]["to_stern"]), ("EVER DIADEM", 148, 148))
        self.assertEqual((objs[2]["mmsi"], objs[2]["speed"], objs[2]["course"], objs[2]["heading"]),
                         (338000001, 1023, 3600, 511))

    def test_gpsd_json_round_trip_through_gpsdecode(self):
        gpsdecode = shutil.which("gpsdecode")
        if gpsdecode is None:
            self.skipTest("gpsdecode (gpsd-clients) not installed: scripts/setup installs it")
        proc, msgs = convert(self.GPSD, "gpspipe.json")
        self.assertEqual(proc.returncode, 0, proc.stdout)
        sentences = "\n".join(m.sentence.split("\\")[-1] for _, m, _ in msgs) + "\n"  # without tag blocks
        gpsd = subprocess.run([gpsdecode], input=sentences, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                              text=True).stdout
        first = [json.loads(line) for line in gpsd.splitlines()]
        timed = "".join("2020-06-30 00:00:%02d: %s\n" % (k, line) for k, line in enumerate(gpsd.splitlines()))
        proc2, msgs2 = convert(timed, "gpsdecode.json")
        self.assertEqual(proc2.returncode, 0, proc2.stdout)
        again = [json.loads(line) for line in subprocess.run(
            [gpsdecode], input="\n".join(m.sentence.split("\\")[-1] for _, m, _ in msgs2) + "\n",
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout.splitlines()]
        keys = ("mmsi", "lat", "lon", "speed", "course", "heading")
        pos = lambda objs: [tuple(o[k] for k in keys) for o in objs if o["type"] in (1, 18)]
        self.assertEqual(len(pos(first)), 2)
        self.assertEqual(pos(again), pos(first))


if __name__ == "__main__":
    rosunit.unitrun("asv_bringup", "nmea_to_bag", NmeaToBag)
