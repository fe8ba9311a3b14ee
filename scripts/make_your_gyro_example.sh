#!/bin/sh
# Regenerates examples/your_gyro/chamber_run1.csv and chamber_run2.csv: the bundled chamber runs A
# and B, means of 100 samples (10 s), in a logger's layout (scripts/vendor_layout.py).
# usage: scripts/make_your_gyro_example.sh   (from the repository root)
set -eu
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 scripts/vendor_layout.py datasets/chamber_A.csv.gz --every 100 --average --temp-unit C --logger-digits --preamble 1 \
  --native "$tmp/a.csv" --vendor examples/your_gyro/chamber_run1.csv
python3 scripts/vendor_layout.py datasets/chamber_B.csv.gz --every 100 --average --temp-unit C --logger-digits --preamble 1 \
  --native "$tmp/b.csv" --vendor examples/your_gyro/chamber_run2.csv
