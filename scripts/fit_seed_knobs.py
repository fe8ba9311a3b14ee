#!/usr/bin/env python3
"""Fits the two knobs of the default device that are matched to the seed paper's UNCOMPENSATED
figures, and nothing else:

  coil.midpoint_offset_m            (quadrupole length asymmetry: the default's only Shupe source)
  errors.radial_gradient_dph_per_C  (elasto-optic / thermal-stress coefficient, unsourced)

Every other device value is the default (docs/reference/simulator.md gives its source or its reasoning). The
targets are three figures of the seed paper on its own run (`seed` profile, simulated at 10 Hz,
noise seed 20240501, the datasets' seed), as fog-paper computes them (the paper's method):
  - uncompensated 100 s bias stability 0.114857 deg/h and range of 100 s averages 0.5082 deg/h;
  - M1 (poly5 of one inner thermistor) in-sample 100 s stability 0.104111 deg/h: the part of the
    uncompensated error that is a function of temperature alone.
Why the third: the two uncompensated figures alone leave a flat valley (with hub_to_inner 0.055
W/K: offset 5 m with coefficient 0 .. 0.05, or offset 2 m with 0.14, all within ~10-27 %); they
do not say how the error splits between the Shupe term and the static gradient. M1 does: a large
Shupe term from a large offset is mostly a function of T on the seed profile and M1 then removes
half of it (the paper: 9 %). So M1 is FITTED too and is no longer an independent check of the
simulator (docs/reference/simulator.md says so). The objective is the sum of the squared log ratios of the three,
minimised over a grid. Noise seeds 1-10 are NOT used here: the long test DefaultDeviceSweep
checks the picked values on them (held out), and run B (profile B) is never used.

  scripts/fit_seed_knobs.py [--fog-sim build/apps/fog-sim] [--fog-paper build/apps/fog-paper] [--device BASE.yaml]
                            [--offsets 0.5:3:0.5] [--coefs 0.1:0.14:0.01] [--json OUT.json]

--device adds a YAML overlay under the knobs (e.g. thermal: {hub_to_inner_W_K: 0.055} to fit for
a changed thermal network before it becomes the default). Prints the grid and the best pair.
"""
import argparse, json, math, os, subprocess, sys, tempfile

SEED_STABILITY_DPH = 0.114857  # seed paper, uncompensated 100 s bias stability
SEED_RANGE_DPH = 0.5082        # seed paper, uncompensated range of 100 s averages
SEED_M1_DPH = 0.104111         # seed paper, M1 (poly5(T), one thermistor) 100 s stability


def frange(spec):
    lo, hi, step = (float(x) for x in spec.split(":"))
    n = int(round((hi - lo) / step))
    return [round(lo + i * step, 10) for i in range(n + 1)]


def run(sim, paper, base_yaml, offset_m, coef, tmp):
    dev = os.path.join(tmp, "dev.yaml")
    with open(dev, "w") as f:
        f.write(base_yaml)
        f.write("coil: {midpoint_offset_m: %r}\nerrors: {radial_gradient_dph_per_C: %r}\n" % (offset_m, coef))
    log = os.path.join(tmp, "a.rawlog")
    subprocess.run([sim, "-p", "seed", "--seed", "20240501", "--rate-hz", "10", "--device", dev, "-o", log],
                   check=True, stdout=subprocess.DEVNULL)
    js = os.path.join(tmp, "paper.json")
    # run B is not used: run A is passed as both so that nothing else is simulated
    subprocess.run([paper, "--run-a", log, "--run-b", log, "--json", js], check=True, stdout=subprocess.DEVNULL)
    with open(js) as f:
        ours = json.load(f)["ours"]["in_sample"]
    return ours["uncompensated"]["stability_dph"], ours["uncompensated"]["range_dph"], ours["M1"]["stability_dph"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--fog-sim", default="build/apps/fog-sim")
    ap.add_argument("--fog-paper", default="build/apps/fog-paper")
    ap.add_argument("--device", help="YAML overlay under the two knobs (no coil/errors keys)")
    ap.add_argument("--offsets", default="0.5:3:0.5", help="lo:hi:step of coil.midpoint_offset_m [m]")
    ap.add_argument("--coefs", default="0.1:0.14:0.01", help="lo:hi:step of radial_gradient_dph_per_C")
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
                s, r, m1 = run(a.fog_sim, a.fog_paper, base, off, c, tmp)
                cost = (math.log(s / SEED_STABILITY_DPH) ** 2 + math.log(r / SEED_RANGE_DPH) ** 2 +
                        math.log(m1 / SEED_M1_DPH) ** 2)
                rows.append({"midpoint_offset_m": off, "radial_gradient_dph_per_C": c,
                             "stability_dph": s, "range_dph": r, "m1_stability_dph": m1, "cost": cost})
                print("offset %5.2f m  coef %.3f  stability %.4f (%+5.1f %%)  range %.4f (%+5.1f %%)  M1 %.4f (%+5.1f %%)" %
                      (off, c, s, 100 * (s / SEED_STABILITY_DPH - 1), r, 100 * (r / SEED_RANGE_DPH - 1),
                       m1, 100 * (m1 / SEED_M1_DPH - 1)), flush=True)
    best = min(rows, key=lambda x: x["cost"])
    print("best: coil.midpoint_offset_m %g, errors.radial_gradient_dph_per_C %g -> stability %.4f deg/h (%+.1f %%), "
          "range %.4f deg/h (%+.1f %%), M1 %.4f deg/h (%+.1f %%)" % (
              best["midpoint_offset_m"], best["radial_gradient_dph_per_C"],
              best["stability_dph"], 100 * (best["stability_dph"] / SEED_STABILITY_DPH - 1),
              best["range_dph"], 100 * (best["range_dph"] / SEED_RANGE_DPH - 1),
              best["m1_stability_dph"], 100 * (best["m1_stability_dph"] / SEED_M1_DPH - 1)))
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"grid": rows, "best": best}, f, indent=1)


if __name__ == "__main__":
    main()
