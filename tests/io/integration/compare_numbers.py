#!/usr/bin/env python3
"""compare_numbers.py A B [REL_TOL]: the numbers of two text files (a calibration YAML, a --json
output) agree one by one within REL_TOL (default 1e-6, relative to max(|a|, |b|, 1e-3)); lines
naming input files are left out. Prints the count compared and the largest difference; exit 1
when a number differs, or the files hold different counts of numbers."""
import re
import sys

NUM = re.compile(r"-?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?")


def numbers(path):
    out = []
    for line in open(path):
        if re.search(r"\.(csv|rawlog|dat|txt|yaml)\b", line):
            continue  # paths of the inputs and outputs differ by design
        out += [float(x) for x in NUM.findall(line)]
    return out


a, b = numbers(sys.argv[1]), numbers(sys.argv[2])
tol = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-6
if len(a) != len(b):
    sys.exit("compare_numbers: %s holds %d numbers, %s %d" % (sys.argv[1], len(a), sys.argv[2], len(b)))
worst = 0.0
for x, y in zip(a, b):
    worst = max(worst, abs(x - y) / max(abs(x), abs(y), 1e-3))
print("compare_numbers: %d numbers, largest relative difference %.3g (tolerance %g)" % (len(a), worst, tol))
sys.exit(0 if worst <= tol else 1)
