#!/usr/bin/env python3
"""Writes power_cycle.csv: a small chamber run in which the gyro is switched off for 15 min while
the thermistors keep logging (power 0, empty rate cell), for the power-off tests
(tests/io/integration/power_off_programs.cmake, tests/io/test_FogCsv.cpp).

2 h at 0.25 Hz. Chamber air: 25 C soak 10 min, ramp to 5 C at 0.5 C/min, soak, ramp to 40 C
at 0.5 C/min, soak. Ti1 / To1: first-order lags of the air (900 s / 300 s), quantised to 0.01 C.
Gyro off from t = 3000 s to t = 3900 s (225 rows with an empty rate cell).
Gyro z rate [deg/h] = 9.67 + 0.004 (To1 - 20) + 6 dTi1/dt [C/s] + white noise sigma 0.05 deg/h.
Fixed seed: the file is reproducible byte for byte.
"""
import random

random.seed(20261201)
dt = 4.0
n = int(2 * 3600 / dt)


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


ti, to = 25.0, 25.0
with open("power_cycle.csv", "w") as f:
    f.write("# sensor: FOG\n# latitude_deg: 40\n")
    f.write("# thermistor Ti1: side=inner angle_deg=0\n# thermistor To1: side=outer angle_deg=0\n")
    f.write("time_s,rate_z_dph,temp_Ti1_C,temp_To1_C,power\n")
    for k in range(n):
        t = k * dt
        a = air(t)
        ti_prev = ti
        ti += (a - ti) * dt / 900.0
        to += (a - to) * dt / 300.0
        on = not (3000 <= t < 3900)
        rate = 9.67 + 0.004 * (to - 20) + 6 * (ti - ti_prev) / dt + random.gauss(0, 0.05)
        cell = "%.5f" % rate if on else ""
        f.write("%g,%s,%.2f,%.2f,%d\n" % (t, cell, round(ti, 2), round(to, 2), 1 if on else 0))
