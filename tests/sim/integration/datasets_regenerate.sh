#!/usr/bin/env bash
# Regenerates every bundled dataset into a scratch directory and checks each file against the
# sha256 in datasets/MANIFEST.md: the datasets are reproducible bit for bit by the documented
# command. Usage: datasets_regenerate.sh FOG_SIM SOURCE_DIR WORK_DIR
set -euo pipefail
SIM=$1 SRC=$2 WORK=$3
rm -rf "$WORK" && mkdir -p "$WORK"
OUT_DIR="$WORK" FOG_SIM="$SIM" "$SRC/scripts/make_datasets.sh" >/dev/null
cd "$WORK"
awk '/^```sha256/{f=1;next}/^```/{f=0}f' "$SRC/datasets/MANIFEST.md" >expected.sha256
test "$(wc -l <expected.sha256)" -ge 7
sha256sum -c expected.sha256
