#!/usr/bin/env python3
"""Fits the two knobs of the default device that are matched to the seed paper's UNCOMPENSATED
figures, and nothing else:

  coil.midpoint_offset_m            (quadrupole length asymmetry: the default's only Shupe source)
  errors.radial_gradient_dph_per_C  (elasto-optic / thermal-stress coefficient, unsourced)

Every other device value is the default (docs/sim.md gives its source or its reasoning). The
figures are fog-sim's own 100 s bias stability and range of 100 s averages of the uncompensated
output (table rate removed) on the `seed` profile, 10 Hz, noise seed 20240501 (the datasets'
seed). Target: the seed paper's 0.114857 / 0.5082 deg/h. The objective is the sum of the squared
log ratios (stability/0.114857, range/0.5082), minimised over a grid; ties are not possible in
practice. Noise seeds 1-10 are NOT used here: the long test DefaultDeviceSweep checks the picked
values on them (held out).

  scripts/fit_seed_knobs.py [--fog-sim build/apps/fog-sim] [--device BASE.yaml]
                            [--offsets 0:5:0.5] [--coefs 0.04:0.2:0.01] [--json OUT.json]

--device adds a YAML overlay under the knobs (e.g. thermal: {hub_to_inner_W_K: 0.055} to fit for
a changed thermal network before it becomes the default). Prints the grid and the best pair.
"""
import argparse, json, math, os, subprocess, sys, tempfile

SEED_STABILITY_DPH = 0.114857  # seed paper, uncompensated 100 s bias stability
SEED_RANGE_DPH = 0.5082        # seed paper, uncompensated range of 100 s averages


def frange(spec):
    lo, hi, step = (float(x) for x in spec.split(":"))
    n = int(round((hi - lo) / step))
    return [round(lo + i * step, 10) for i in range(n + 1)]


def run(sim, base_yaml, offset_m, coef, tmp):
    dev = os.path.join(tmp, "dev.yaml")
    with open(dev, "w") as f:
        f.write(base_yaml)
        f.write("coil: {midpoint_offset_m: %r}\nerrors: {radial_gradient_dph_per_C: %r}\n" % (offset_m, coef))
    js = os.path.join(tmp, "run.json")
    subprocess.run([sim, "-p", "seed", "--seed", "20240501", "--rate-hz", "10", "--device", dev,
                    "-o", os.path.join(tmp, "run.csv"), "--json", js], check=True, stdout=subprocess.DEVNULL)
    with open(js) as f:
        u = json.load(f)["uncompensated"]
    return u["stability_dph"], u["range_dph"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fog-sim", default="build/apps/fog-sim")
    ap.add_argument("--device", help="YAML overlay under the two knobs (no coil/errors keys)")
    ap.add_argument("--offsets", default="0:5:0.5", help="lo:hi:step of coil.midpoint_offset_m [m]")
    ap.add_argument("--coefs", default="0.04:0.2:0.01", help="lo:hi:step of radial_gradient_dph_per_C")
    ap.add_argument("--json", help="write the grid and the best pair here")
    a = ap.parse_args()
    base = ""
    if a.device:
        with open(a.device) as f:
            base = f.read()
        if any(line.startswith(("coil", "errors")) for line in base.splitlines()):
            sys.exit("fit_seed_knobs: error: %s: must not set coil or errors (the fitted knobs live there)" % a.device)
        if base and not base.endswith("\n"):
            base += "\n"
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for off in frange(a.offsets):
            for c in frange(a.coefs):
                s, r = run(a.fog_sim, base, off, c, tmp)
                cost = math.log(s / SEED_STABILITY_DPH) ** 2 + math.log(r / SEED_RANGE_DPH) ** 2
                rows.append({"midpoint_offset_m": off, "radial_gradient_dph_per_C": c,
                             "stability_dph": s, "range_dph": r, "cost": cost})
                print("offset %5.2f m  coef %.3f  stability %.4f (%+5.1f %%)  range %.4f (%+5.1f %%)" %
                      (off, c, s, 100 * (s / SEED_STABILITY_DPH - 1), r, 100 * (r / SEED_RANGE_DPH - 1)), flush=True)
    best = min(rows, key=lambda x: x["cost"])
    print("best: coil.midpoint_offset_m %g, errors.radial_gradient_dph_per_C %g -> stability %.4f deg/h (%+.1f %%), "
          "range %.4f deg/h (%+.1f %%)" % (best["midpoint_offset_m"], best["radial_gradient_dph_per_C"],
                                          best["stability_dph"], 100 * (best["stability_dph"] / SEED_STABILITY_DPH - 1),
                                          best["range_dph"], 100 * (best["range_dph"] / SEED_RANGE_DPH - 1)))
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"grid": rows, "best": best}, f, indent=1)


if __name__ == "__main__":
    main()
