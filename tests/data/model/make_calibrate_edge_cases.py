#!/usr/bin/env python3
"""Writes the small logs of fog-calibrate's edge-case test (tests/model/integration/
calibrate_edge_cases.cmake): an independent generator with known parameters.

All: chamber air 25 C soak 10 min, ramp to 5 C at 0.5 C/min, soak 10 min, ramp to 40 C at
0.5 C/min, soak; Ti1 / To1 first-order lags of the air (900 s / 300 s) quantised to 0.01 C; 5 s
samples. Gyro z rate [deg/h] = 9.67 + 0.004 (To1 - 20) + 6 dTi1/dt [C/s] + white noise 0.05.
- warmup_small.csv (3 h): gyro off for the first 10 min (power 0, empty rate cell), switched on
  at t = 600 s (a 0 -> 1 step) with a warm-up 2.0 exp(-(t - 600) / 600 s) deg/h.
- all_off.csv (1 h): gyro off throughout, metadata power_on_time_s 0 (a turn-on that never
  powers a sample).
- field_one_sample.csv (2 h): field_uT 0 everywhere but one sample (50 uT), gyro without any
  magnetic sensitivity: a magnetic term fitted from it has nothing behind it.
Fixed seed: the files are reproducible byte for byte.
"""
import math
import random


def air(t):
    if t < 600:
        return 25.0
    t -= 600
    if t < 40 * 60:
        return 25.0 - t / 120.0
    t -= 40 * 60
    if t < 10 * 60:
        return 5.0
    t -= 10 * 60
    return min(40.0, 5.0 + t / 120.0)


def write(name, hours, power_of, extra_meta="", warmup=None, field_of=None, seed=1):
    random.seed(seed)
    dt = 5.0
    n = int(hours * 3600 / dt)
    ti, to = 25.0, 25.0
    with open(name, "w") as f:
        f.write("# sensor: FOG\n# latitude_deg: 40\n" + extra_meta)
        f.write("# thermistor Ti1: side=inner angle_deg=0\n# thermistor To1: side=outer angle_deg=0\n")
        cols = "time_s,rate_z_dph,temp_Ti1_C,temp_To1_C" + (",field_uT" if field_of else "") + ",power\n"
        f.write(cols)
        for k in range(n):
            t = k * dt
            a = air(t)
            ti_prev = ti
            ti += (a - ti) * dt / 900.0
            to += (a - to) * dt / 300.0
            on = power_of(t)
            rate = 9.67 + 0.004 * (to - 20) + 6 * (ti - ti_prev) / dt + random.gauss(0, 0.05)
            if warmup and t >= warmup[0]:
                rate += warmup[1] * math.exp(-(t - warmup[0]) / warmup[2])
            cell = "%.5f" % rate if on else ""
            field = ("," + "%g" % field_of(k)) if field_of else ""
            f.write("%g,%s,%.2f,%.2f%s,%d\n" % (t, cell, round(ti, 2), round(to, 2), field, 1 if on else 0))


write("warmup_small.csv", 3, lambda t: t >= 600, warmup=(600.0, 2.0, 600.0), seed=20261203)
write("all_off.csv", 1, lambda t: False, extra_meta="# power_on_time_s: 0\n", seed=20261204)
write("field_one_sample.csv", 2, lambda t: True, field_of=lambda k: 50.0 if k == 700 else 0.0, seed=20261205)
