#!/usr/bin/env python3
"""Splits the compensated heading error of simulated drives into its scale-factor and bias parts
with the simulator's truth (the heading error budget; numpy only).

    /usr/bin/python3 scripts/heading_budget_truth.py TRUTH.csv...

Each TRUTH.csv is written by drive-truth (build/tests/drive-truth --seed N --cabin C --cal CAL
-o TRUTH.csv): per 10 Hz sample the applied rate (yaw + Earth rate), raw and ideal gyro, the
scale-factor error the simulator applied (sf_true_ppm), the thermal bias it added
(bias_true_dph, with the constant bias), and the calibration's compensator (comp_bias_dph,
comp_dph). With E the vertical Earth rate (absorbed by the static calibration, added back as
fog-drift does) and s the compensator's scale factor ((raw - b) / comp - 1), the compensated rate
minus the ideal one is, to first order in s,
    scale-factor part  applied (sf_true - s) / (1 + s)
    bias part          (bias_true + E (1 + s) - b) / (1 + s)
Heading errors are their running integrals (the ideal gyro's is the integral of its noise), and
the figures are heading RMS over the drive divided by the ideal gyro's, per drive, then median
[quartiles]: comp/ideal (all parts; checks against fog-drift's), each part alone, and the drive
with one part removed (what a perfect bias or a perfect scale-factor model would leave).
Prints one line per drive and the medians; --json F writes them."""
import json
import sys

import numpy as np

EARTH_DPH = 15.041067 * np.sin(np.radians(40.0))


def load(path):
    d = np.genfromtxt(path, delimiter=",", names=True)
    need = ["t_s", "applied_dph", "raw_dph", "ideal_dph", "sf_true_ppm", "bias_true_dph", "comp_bias_dph", "comp_dph"]
    for n in need:
        if n not in d.dtype.names:
            sys.exit(f"heading_budget_truth: error: {path}: column {n} missing (written by drive-truth --cal)")
    if not np.all(np.isfinite(d["comp_dph"])):
        sys.exit(f"heading_budget_truth: error: {path}: comp_dph has empty values (drive-truth without --cal?)")
    return d


def figures(d):
    dt_h = np.diff(d["t_s"], prepend=d["t_s"][0]) / 3600.0
    b = d["comp_bias_dph"]
    s = (d["raw_dph"] - b) / d["comp_dph"] - 1.0
    s[~np.isfinite(s)] = 0.0
    sf = 1e-6 * d["sf_true_ppm"]
    part_sf = d["applied_dph"] * (sf - s) / (1 + s)
    part_b = (d["bias_true_dph"] + EARTH_DPH * (1 + s) - b) / (1 + s)
    h_ideal = np.cumsum((d["ideal_dph"] - d["applied_dph"]) * dt_h)
    h_sf = np.cumsum(part_sf * dt_h)
    h_b = np.cumsum(part_b * dt_h)
    rms = lambda x: float(np.sqrt(np.mean(x * x)))
    ri = rms(h_ideal)
    return {
        "heading_rms_ideal_deg": ri,
        "heading_rms_comp_deg": rms(h_ideal + h_sf + h_b),
        "comp_over_ideal": rms(h_ideal + h_sf + h_b) / ri,
        "scale_factor_part_alone_over_ideal": rms(h_sf) / ri,
        "bias_part_alone_over_ideal": rms(h_b) / ri,
        "perfect_scale_factor_over_ideal": rms(h_ideal + h_b) / ri,
        "perfect_bias_over_ideal": rms(h_ideal + h_sf) / ri,
    }


def main(argv):
    json_out = None
    if "--json" in argv:
        i = argv.index("--json")
        json_out = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    if not argv:
        sys.exit(__doc__)
    rows = []
    for p in argv:
        f = figures(load(p))
        f["file"] = p
        rows.append(f)
        print(f"{p}: comp/ideal {f['comp_over_ideal']:.2f}  scale-factor part {f['scale_factor_part_alone_over_ideal']:.2f}"
              f"  bias part {f['bias_part_alone_over_ideal']:.2f}  perfect SF {f['perfect_scale_factor_over_ideal']:.2f}"
              f"  perfect bias {f['perfect_bias_over_ideal']:.2f}")
    summary = {}
    for k in ["comp_over_ideal", "scale_factor_part_alone_over_ideal", "bias_part_alone_over_ideal",
              "perfect_scale_factor_over_ideal", "perfect_bias_over_ideal"]:
        v = np.array([r[k] for r in rows])
        q1, med, q3 = np.percentile(v, [25, 50, 75])
        summary[k] = {"median": float(med), "q1": float(q1), "q3": float(q3)}
        print(f"median {k:36s} {med:.2f} [{q1:.2f}, {q3:.2f}]")
    if json_out:
        with open(json_out, "w") as fh:
            json.dump({"drives": rows, "over_drives": summary}, fh, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
