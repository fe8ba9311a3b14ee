#!/usr/bin/env bash
# Usage: fog_paper_json.sh FOG_PAPER WORK_DIR
set -euo pipefail
APP=$1 WORK=$2
rm -rf "$WORK" && mkdir -p "$WORK/plots" && cd "$WORK"
"$APP" --json paper.json --plots plots --rate-hz 2 >summary.txt
python3 - <<'PY'
import json
j = json.load(open("paper.json"))
keys = ["uncompensated", "M1", "M2", "M3", "M4", "points_1", "points_2", "points_3", "points_4"]
for block in (j["paper"], j["ours"]["in_sample"], j["ours"]["held_out"]):
    for k in keys:
        for f in ("stability_dph", "range_dph"):
            v = block[k][f]
            assert isinstance(v, float) and v > 0, (k, f, v)
assert abs(j["paper"]["points_3"]["stability_dph"] - 0.0069472) < 1e-9
ins = j["ours"]["in_sample"]
assert ins["points_3"]["stability_dph"] * 10 < ins["uncompensated"]["stability_dph"], ins
print("ok")
PY
test -s plots/fig5_points.png
test -s plots/fig2_temperatures.png
"$APP" --selection best >/dev/null 2>err.txt && exit 1
grep -qF -- "--selection: selection must be 'auto' or 'none', got 'best'" err.txt
