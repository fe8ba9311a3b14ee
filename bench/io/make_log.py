#!/usr/bin/env python3
"""Writes a synthetic FOG chamber log of N samples as lab CSV on stdout (for the I/O throughput
bench; not physics: a slow 4-thermistor temperature cycle, a bias that follows it, white noise).
  make_log.py N [rate_hz]"""
import math
import random
import sys

n = int(float(sys.argv[1]))
rate = float(sys.argv[2]) if len(sys.argv) > 2 else 100.0
rnd = random.Random(20261201)
out = sys.stdout
out.write("# sensor: FOG\n# epoch_s: 1700000000\n# latitude_deg: 45.5\n")
for name, side, ang in (("Ti1", "inner", 0), ("To1", "outer", 0), ("Ti2", "inner", 180), ("To2", "outer", 180)):
    out.write(f"# thermistor {name}: side={side} angle_deg={ang}\n")
out.write("time_s,rate_z_dph,temp_Ti1_C,temp_To1_C,temp_Ti2_C,temp_To2_C,table_rate_dph,power\n")
buf = []
for k in range(n):
    t = k / rate
    c = 25.0 + 30.0 * math.sin(2 * math.pi * t / 20000.0)
    ti, to = c - 0.3, c + 0.4
    bias = 10.0 + 0.02 * c + 0.5 * math.cos(2 * math.pi * t / 20000.0) + rnd.gauss(0, 0.05)
    buf.append(f"{t:.2f},{bias:.5f},{ti:.3f},{to:.3f},{ti + 0.1:.3f},{to - 0.1:.3f},0,1\n")
    if len(buf) == 10000:
        out.write("".join(buf))
        buf.clear()
out.write("".join(buf))
