#!/usr/bin/python3
"""Writes gnss_log.nmea: 40 s of a ship's own sensors, one epoch a second (RMC, GGA, HDT), for the
own_ship_node rostest. The ship sails 090 at 10 kn from 48 07.038' N 011 31.000' E. Longitudes from the
WGS84 prime-vertical radius (east metres / (N cos lat)), independent of the node's GeographicLib.
Epoch 20 carries a GGA 0.5' north of the truth (a receiver glitch the node must reject); epoch 25 an RMC
with status V (no fix). Run from this folder: ./make_gnss_log.py > gnss_log.nmea
"""
import math

A, F = 6378137.0, 1 / 298.257223563
E2 = F * (2 - F)
LAT0, LON0 = 48 + 7.038 / 60, 11 + 31.0 / 60
SPEED = 10 * 1852 / 3600  # m/s


def cs(body):
    x = 0
    for c in body:
        x ^= ord(c)
    return "%02X" % x


def sentence(body):
    return "$%s*%s" % (body, cs(body))


def lon_field(lon):
    d = int(lon)
    return "%03d%07.4f,E" % (d, (lon - d) * 60)


def lat_field(lat):
    d = int(lat)
    return "%02d%07.4f,N" % (d, (lat - d) * 60)


def main():
    n = A / math.sqrt(1 - E2 * math.sin(math.radians(LAT0)) ** 2)
    for k in range(40):
        t = "1235%02d.00" % (k % 60)
        lon = LON0 + math.degrees(SPEED * k / (n * math.cos(math.radians(LAT0))))
        lat = LAT0 + (0.5 / 60 if k == 20 else 0.0)
        status = "V" if k == 25 else "A"
        print(sentence("GPRMC,%s,%s,%s,%s,010.0,090.0,031226,,,A" % (t, status, lat_field(LAT0), lon_field(lon))))
        print(sentence("GPGGA,%s,%s,%s,1,09,0.9,12.0,M,47.0,M,," % (t, lat_field(lat), lon_field(lon))))
        print(sentence("HEHDT,090.0,T"))


if __name__ == "__main__":
    main()
