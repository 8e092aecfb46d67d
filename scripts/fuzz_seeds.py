#!/usr/bin/env python3
"""Writes the byte-level seeds of scripts/fuzz.sh into WORK/: VLP-16 data packets and the
replies of a Hokuyo (SCIP 2.0) to MRPT's start-up commands followed by streamed scans."""
import os
import struct
import sys

work = sys.argv[1]

# VLP-16: 12 blocks of (0xFFEE, azimuth in 0.01 deg, 32 x (distance 2 mm, intensity)), then a
# 4-byte timestamp and the factory bytes (0x37 strongest return, 0x22 VLP-16).
def vlp16_packet(azimuth0, t_us):
    out = b""
    for b in range(12):
        az = (azimuth0 + 40 * b) % 36000
        out += struct.pack("<HH", 0xEEFF, az)
        for k in range(32):
            out += struct.pack("<HB", 1500 + 37 * k + 11 * b, 40 + k)
    return out + struct.pack("<IBB", t_us, 0x37, 0x22)

os.makedirs(f"{work}/velodyne", exist_ok=True)
with open(f"{work}/velodyne/two_packets.bin", "wb") as f:
    f.write(vlp16_packet(100, 1000) + vlp16_packet(580, 2327))

# SCIP 2.0: every line after the echo ends with a sum char: (byte sum & 0x3f) + 0x30.
def line(s):
    return s + chr((sum(s.encode()) & 0x3F) + 0x30) + "\n"

def reply(cmd, status="00", data=()):
    return cmd + "\n" + line(status) + "".join(line(d) for d in data) + "\n"

def enc(v, n):
    return "".join(chr(((v >> (6 * (n - 1 - i))) & 0x3F) + 0x30) for i in range(n))

pp = ["MODL:UTM-30LX;", "DMIN:23;", "DMAX:30000;", "ARES:1440;", "AMIN:0;", "AMAX:20;",
      "AFRT:540;", "SCAN:2400;"]
vv = ["VEND:Hokuyo;", "PROD:UTM-30LX;", "FIRM:1.0;", "PROT:SCIP 2.0;", "SERI:H1;"]
session = reply("QT") + reply("QT") + reply("SCIP2.0") + reply("BM") + reply("HS0")
session += reply("PP", data=pp) + reply("VV", data=vv)
md = "MD0000002001000"
session += reply(md)
for k in range(3):
    ranges = "".join(enc(1000 + 10 * i + k, 3) for i in range(21))
    session += md[:-2] + "99" + "\n" + line("99") + line(enc(25 * k, 4)) + line(ranges) + "\n"
os.makedirs(f"{work}/scip", exist_ok=True)
with open(f"{work}/scip/session.txt", "w") as f:
    f.write(session)
