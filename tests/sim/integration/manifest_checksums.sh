#!/usr/bin/env bash
# The files in datasets/ match the sha256 listed in datasets/MANIFEST.md, and every listed
# dataset is present. Usage: manifest_checksums.sh SOURCE_DIR
set -euo pipefail
cd "$1/datasets"
sums=$(awk '/^```sha256/{f=1;next}/^```/{f=0}f' MANIFEST.md)
test "$(echo "$sums" | wc -l)" -ge 7
for f in chamber_A.rawlog chamber_B.rawlog warmup.rawlog drive.rawlog ratetable_A.rawlog ratetable_transient.rawlog; do
	echo "$sums" | grep -q " $f\$" || { echo "MANIFEST.md does not list $f"; exit 1; }
done
echo "$sums" | sha256sum -c
