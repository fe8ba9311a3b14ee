#!/usr/bin/env python3
"""Writes chamber_small.csv: a small synthetic thermal-chamber run with a KNOWN bias law, for the
fog-evaluate integration test with --cal (tests/integration/metrics.cmake).

2.5 h at 0.5 Hz. Chamber air: 25 C soak 10 min, ramp to -5 C at 1 C/min, soak 20 min, ramp to
+45 C at 1 C/min, soak to the end. Inner (Ti1) and outer (To1) thermistors are first-order lags
of the air (time constants 900 s and 300 s), quantised to 0.01 C.
Gyro z rate [deg/h] = 9.67 (constant, e.g. Earth rate) + 0.004 (To1 - 20) + 6 dTi1/dt [C/s]
                      + white noise of sigma 0.05 deg/h (ARW = 0.05 / (60 sqrt(0.5)) =
                      1.18e-3 deg/sqrt(h); its 100 s averages have sigma 0.05/sqrt(50) = 0.0071).
Fixed seed: the file is reproducible byte for byte.
"""
import math
import random

random.seed(20261121)
dt = 2.0
n = int(2.5 * 3600 / dt)


def air(t):
    if t < 600:
        return 25.0
    t -= 600
    if t < 30 * 60:
        return 25.0 - t / 60.0
    t -= 30 * 60
    if t < 20 * 60:
        return -5.0
    t -= 20 * 60
    return min(45.0, -5.0 + t / 60.0)


ti, to = 25.0, 25.0
with open("chamber_small.csv", "w") as f:
    f.write("# sensor: FOG\n# latitude_deg: 40\n")
    f.write("# thermistor Ti1: side=inner angle_deg=0\n# thermistor To1: side=outer angle_deg=0\n")
    f.write("time_s,rate_z_dph,temp_Ti1_C,temp_To1_C\n")
    for k in range(n):
        t = k * dt
        a = air(t)
        dti = (a - ti) / 900.0
        ti += dti * dt
        to += (a - to) / 300.0 * dt
        rate = 9.67 + 0.004 * (to - 20.0) + 6.0 * dti + random.gauss(0.0, 0.05)
        f.write(f"{t:.1f},{rate:.5f},{round(ti, 2):.2f},{round(to, 2):.2f}\n")
