#!/usr/bin/env python3
"""Summary of scripts/turn_on_refinement.sh's outputs (docs/validation/turn-on-refinement.md)."""
import json
import os
import statistics
import sys

out = sys.argv[1]  # then optionally --check: exit 1 when a target is missed


def drives(name):
    p = os.path.join(out, name)
    if not os.path.exists(p):
        return None
    j = json.load(open(p))
    return j["drives"] if "drives" in j else [j]


def fig(d, key, v):
    x = d[key][v]
    return float("nan") if x is None else x


for part in ["bundled", "plus03", "sweep", "sweepsf", "nostill"]:
    rows = {}
    for mode in ["thermal", "refined"]:
        rows[mode] = drives(f"{part}_{mode}.json")
    if rows["refined"] is None:
        continue
    print(f"== {part}")
    for mode in ["thermal", "refined"]:
        ds = rows[mode]
        comp = [fig(d, "heading_error_rms_deg", "compensated") for d in ds]
        ideal = [fig(d, "heading_error_rms_deg", "ideal") for d in ds]
        raw = [fig(d, "heading_error_rms_deg", "raw") for d in ds]
        ratio = [c / i for c, i in zip(comp, ideal)]
        print(f"  {mode:8s} heading RMS comp " + " ".join(f"{c:.5f}" for c in comp))
        print(f"  {mode:8s} comp/ideal       " + " ".join(f"{r:.2f}" for r in ratio))
        if len(ds) > 1:
            print(f"  {mode:8s} median comp {statistics.median(comp):.5f}, ideal {statistics.median(ideal):.5f}, "
                  f"raw {statistics.median(raw):.4f}, comp/ideal median {statistics.median(ratio):.2f} "
                  f"[{sorted(ratio)[len(ratio) // 4]:.2f} .. {sorted(ratio)[(3 * len(ratio)) // 4]:.2f}]")
        if mode == "refined":
            for d in ds:
                fr = d.get("field_refinement", {})
                ups = fr.get("updates", [])
                print(f"    {os.path.basename(d['input'])}: {len(ups)} updates, offset {fr.get('offset_dph', float('nan')):+.4f} "
                      f"+- {fr.get('offset_sigma_dph', float('nan')):.4f} deg/h; {fr.get('note')}")
if os.path.exists(os.path.join(out, "nostill_cmp.txt")):
    t = open(os.path.join(out, "nostill_cmp.txt")).read().strip()
    print("== nostill: per-sample errors (--csv) with and without refinement " + ("identical (cmp)" if t == "" else "DIFFER: " + t))
for c in ["cal_wu", "cal_refined"]:
    ds = drives(f"aging_{c}.json")
    if ds is None:
        continue
    comp = [fig(d, "heading_error_rms_deg", "compensated") for d in ds]
    ideal = [fig(d, "heading_error_rms_deg", "ideal") for d in ds]
    print(f"== aging, {c} (days 120, 150, 180; standstill updates off): heading RMS comp "
          + " ".join(f"{x:.4f}" for x in comp) + " ; comp/ideal " + " ".join(f"{a / b:.1f}" for a, b in zip(comp, ideal)))
if os.path.exists(os.path.join(out, "refine.json")):
    r = json.load(open(os.path.join(out, "refine.json")))
    fo = r["field_offset"]
    print("== fog-refine: logs " + ", ".join(f"{l['offset_dph']:+.4f}+-{l['sigma_dph']:.4f}" for l in r["logs"] if l["measured"])
          + f"; field offset {fo['offset_dph']:+.4f} +- {fo['sigma_dph']:.4f} deg/h at day 90, trend "
          f"{fo['aging_dph_per_day'] * 365.25:+.3f} +- {fo['aging_sigma_dph_per_day'] * 365.25:.3f} deg/h per year (truth 1.0)")

if "--check" in sys.argv:
    # the targets of docs/validation/turn-on-refinement.md (ctest nav.turn_on_refinement, label long)
    def comp(name, mode):
        return [fig(d, "heading_error_rms_deg", "compensated") for d in drives(f"{name}_{mode}.json")]
    failures = []
    if comp("plus03", "refined")[0] > 0.01:
        failures.append("bundled + 0.3 deg/h: heading RMS > 0.01 deg")
    if comp("bundled", "refined")[0] > 0.0012:
        failures.append("bundled drive: heading RMS > 0.0012 deg")
    ds = drives("sweep_refined.json")
    if statistics.median(fig(d, "heading_error_rms_deg", "compensated") / fig(d, "heading_error_rms_deg", "ideal") for d in ds) > 3:
        failures.append("sweep: median comp/ideal > 3")
    if open(os.path.join(out, "nostill_cmp.txt")).read().strip() != "":
        failures.append("no-standstill drive: output differs with refinement")
    if drives("aging_cal_refined.json") is not None:
        refined = [fig(d, "heading_error_rms_deg", "compensated") for d in drives("aging_cal_refined.json")]
        original = [fig(d, "heading_error_rms_deg", "compensated") for d in drives("aging_cal_wu.json")]
        if not all(r < o for r, o in zip(refined, original)):
            failures.append("aging: the refined calibration is not better on every later drive")
    for f in failures:
        print("FAILED: " + f)
    sys.exit(1 if failures else 0)
