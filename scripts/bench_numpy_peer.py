#!/usr/bin/python3
"""Peer comparison of the thermal-bias least-squares fit: mrpt_fog's streaming QR fit
(bench/bench_fit_peer.cpp, BM_FitDesignMatrix_Multipoint4) against NumPy's lstsq (LAPACK
gelsd, Debian python3-numpy) on the SAME design matrix: the 33-term multipoint features of a
synthetic chamber run, exported by bench_fit_peer --export.

Reports the rows per second of both, the speed ratio (on the 33-term matrix), and the agreement
of the coefficients and of the fitted bias on two design matrices: the seed's plain 33-term
multipoint model (ill-conditioned, cond(X) ~ 3e8) and the 17-term two-thermistor model.

Coefficient agreement criterion (stated before measuring, not tuned): two backward-stable
least-squares solvers each have a norm-wise relative coefficient error of order cond(X) x eps
(plus a cond(X)^2 x |r| / (|X| |b|) term, reported as well); they are declared to agree when
|b_mrpt_fog - b_numpy| / |b_numpy| <= 10 x cond(X) x eps (eps = 2.2e-16; the factor 10 covers the
dimension-dependent constants of the perturbation bound). The script exits 1 if a design fails.
Usage:
    /usr/bin/python3 scripts/bench_numpy_peer.py [--build build-model] [--json out.json]
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build", help="CMake build directory holding bench/bench_fit_peer")
    ap.add_argument("--repeats", type=int, default=5, help="NumPy timing: best of N runs")
    ap.add_argument("--json", help="write the figures as JSON")
    a = ap.parse_args()
    exe = os.path.join(a.build, "bench", "bench_fit_peer")
    if not os.path.exists(exe):
        sys.exit(f"bench_numpy_peer: error: {exe} not found (build the target bench_fit_peer)")
    out = subprocess.run([exe, "--benchmark_format=json", "--benchmark_repetitions=3",
                          "--benchmark_report_aggregates_only=true"], check=True, capture_output=True, text=True)
    bench = json.loads(out.stdout)
    med = [b for b in bench["benchmarks"] if b.get("aggregate_name") == "median"][0]
    ours_rows_per_s = med["items_per_second"]
    figures = {"mrpt_fog_rows_per_s": ours_rows_per_s, "numpy_version": np.__version__, "models": {}}
    for preset in ("multipoint", "multipoint:Ti1,To1"):
        with tempfile.TemporaryDirectory() as d:
            subprocess.run([exe, "--export", d, preset], check=True, stdout=subprocess.DEVNULL)
            rows, cols = map(int, open(os.path.join(d, "shape.txt")).read().split())
            X = np.fromfile(os.path.join(d, "X.f64"), dtype=np.float64).reshape(rows, cols)
            y = np.fromfile(os.path.join(d, "y.f64"), dtype=np.float64)
            ours = np.loadtxt(os.path.join(d, "coef_mrpt_fog.txt"))
        best = float("inf")
        for _ in range(a.repeats):
            t0 = time.process_time()
            coef, *_ = np.linalg.lstsq(X, y, rcond=None)
            best = min(best, time.process_time() - t0)
        pred_ours, pred_np = X @ ours, X @ coef
        m = {
            "rows": rows,
            "cols": cols,
            "condition_number_X": float(np.linalg.cond(X)),
            "numpy_lstsq_rows_per_s": rows / best,
            "max_abs_coef_diff_dph": float(np.max(np.abs(ours - coef))),
            "max_rel_coef_diff": float(np.max(np.abs(ours - coef)) / np.max(np.abs(coef))),
            "normwise_rel_coef_diff": float(np.linalg.norm(ours - coef) / np.linalg.norm(coef)),
            "max_abs_fitted_bias_diff_dph": float(np.max(np.abs(pred_ours - pred_np))),
            "rms_residual_mrpt_fog_dph": float(np.sqrt(np.mean((y - pred_ours) ** 2))),
            "rms_residual_numpy_dph": float(np.sqrt(np.mean((y - pred_np) ** 2))),
        }
        eps = float(np.finfo(np.float64).eps)
        cond = m["condition_number_X"]
        m["coef_tolerance_10_cond_eps"] = 10 * cond * eps
        m["residual_term_cond2_r_over_Xb"] = float(cond ** 2 * eps * np.linalg.norm(y - pred_np)
                                                   / (np.linalg.norm(X, 2) * np.linalg.norm(coef)))
        m["coefficients_agree"] = m["normwise_rel_coef_diff"] <= m["coef_tolerance_10_cond_eps"]
        figures["models"][preset] = m
        print(f"[{preset}] design matrix {rows} x {cols}, cond(X) = {m['condition_number_X']:.3g}")
        print(f"  NumPy lstsq: {m['numpy_lstsq_rows_per_s'] / 1e6:.3f} M rows/s (CPU time, best of {a.repeats})")
        print(f"  coefficients: max |diff| = {m['max_abs_coef_diff_dph']:.3g} deg/h "
              f"(relative to the largest coefficient: {m['max_rel_coef_diff']:.3g})")
        print(f"  coefficients, norm-wise: |diff| / |b| = {m['normwise_rel_coef_diff']:.3g}; tolerance 10 cond(X) eps = "
              f"{m['coef_tolerance_10_cond_eps']:.3g} ({m['normwise_rel_coef_diff'] / (cond * eps):.3g} x cond(X) eps; "
              f"residual term cond^2 eps |r|/(|X||b|) = {m['residual_term_cond2_r_over_Xb']:.3g}): "
              f"{'AGREE' if m['coefficients_agree'] else 'DO NOT AGREE'}")
        print(f"  fitted bias: max |diff| = {m['max_abs_fitted_bias_diff_dph']:.3g} deg/h; residual RMS "
              f"{m['rms_residual_mrpt_fog_dph']:.7g} (mrpt_fog) vs {m['rms_residual_numpy_dph']:.7g} (NumPy) deg/h")
    ratio = ours_rows_per_s / figures["models"]["multipoint"]["numpy_lstsq_rows_per_s"]
    figures["speed_ratio_mrpt_fog_over_numpy_33_terms"] = ratio
    print(f"mrpt_fog streaming fit (33 terms): {ours_rows_per_s / 1e6:.2f} M rows/s (CPU time, median of 3); "
          f"speed ratio mrpt_fog / NumPy = {ratio:.2f}")
    if a.json:
        with open(a.json + ".tmp", "w") as f:
            json.dump(figures, f, indent=2)
        os.replace(a.json + ".tmp", a.json)
    if not all(m["coefficients_agree"] for m in figures["models"].values()):
        sys.exit(1)


if __name__ == "__main__":
    main()
