#!/usr/bin/env bash
# Regenerates the documented validation figures and compares each with its documented value.
#   scripts/validate.sh --list                 the figures: name, documented value, tolerance, cost
#   scripts/validate.sh [NAME ...]             those figures (default: every "cheap" one)
#   scripts/validate.sh --all                  every figure, the expensive ones too (~1 h of CPU)
# Options: --out DIR (default validate-out/; each figure's files go to DIR/work/, the table of
# results to DIR/results.tsv), --build DIR (default build/; the programs must be built).
# The figures, their commands, documented values and tolerances: docs/validation/figures.tsv
# (a figure is "name <TAB> documented <TAB> tolerance <TAB> evidence <TAB> cost <TAB> command";
# the tolerance is absolute, or relative with a % sign; the command prints the figure as the
# last line of its output and runs from the repository root with $FOG = the programs' folder,
# $WORK = the shared work folder, $ROOT = the repository, `json FILE KEY.PATH` and
# `ratio A B` available). Prints every figure that moved from its documented value and exits 1
# if one left its tolerance (or its command failed).
set -uo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
table="$ROOT/docs/validation/figures.tsv"
out="$ROOT/validate-out"
build="$ROOT/build"
mode=cheap
names=()
while [ $# -gt 0 ]; do
	case $1 in
		--list) mode=list ;;
		--all) mode=all ;;
		--out) out=$2; shift ;;
		--build) build=$2; shift ;;
		-h | --help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
		-*) echo "validate.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
		*) names+=("$1") ;;
	esac
	shift
done

rows() { grep -v '^#' "$table" | grep -v '^[[:space:]]*$'; }

if [ "$mode" = list ]; then
	printf '%-36s %12s %10s %-9s %s\n' name documented tolerance cost evidence
	rows | while IFS=$'\t' read -r name value tol evidence cost cmd; do
		printf '%-36s %12s %10s %-9s %s\n' "$name" "$value" "$tol" "$cost" "$evidence"
	done
	exit 0
fi

for n in "${names[@]}"; do
	rows | cut -f1 | grep -qx "$n" || { echo "validate.sh: no figure '$n' (see --list)" >&2; exit 2; }
done
FOG="$build/apps"
[ -x "$FOG/fog-calibrate" ] || { echo "validate.sh: $FOG/fog-calibrate not built (cmake --build $build)" >&2; exit 2; }
WORK="$out/work"
rm -rf "$WORK"  # figures of this run only, never files of an earlier build
mkdir -p "$WORK"
export ROOT FOG WORK BUILD="$build"
json() {  # json FILE KEY.PATH: the value at a dotted path (list indices as numbers)
	python3 - "$1" "$2" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))
parts = sys.argv[2].split(".")
while parts:  # keys may hold dots themselves ("ratio.x"): the shortest key that exists
    for n in range(1, len(parts) + 1):
        k = ".".join(parts[:n])
        if isinstance(v, list) and k.isdigit():
            v = v[int(k)]; break
        if isinstance(v, dict) and k in v:
            v = v[k]; break
    else:
        sys.exit("no key " + ".".join(parts) + " in " + sys.argv[1])
    parts = parts[n:]
print(v)
PY
}
ratio() { python3 -c "import sys; print(float(sys.argv[1]) / float(sys.argv[2]))" "$1" "$2"; }
export -f json ratio

results="$out/results.tsv"
printf 'name\tdocumented\tmeasured\ttolerance\tstatus\n' > "$results"
status=0
moved=()
while IFS=$'\t' read -r name value tol evidence cost cmd; do
	if [ ${#names[@]} -gt 0 ]; then
		printf '%s\n' "${names[@]}" | grep -qx "$name" || continue
	elif [ "$mode" = cheap ] && [ "$cost" != cheap ]; then
		continue
	fi
	t0=$(date +%s)
	log="$WORK/$name.log"
	measured=$(cd "$ROOT" && bash -c "$cmd" 2>"$log" | tail -1)
	rc=$?
	verdict=$(python3 - "$value" "$tol" "$measured" <<'PY'
import math, sys
doc, tol, got = sys.argv[1], sys.argv[2], sys.argv[3]
try:
    d, g = float(doc), float(got)
except ValueError:
    print("FAILED"); sys.exit()
t = abs(d) * float(tol[:-1]) / 100 if tol.endswith("%") else float(tol)
if not math.isfinite(g) or abs(g - d) > t: print("LEFT-TOLERANCE")
else:  # moved: the figure no longer rounds to the documented value (its stated digits)
    decimals = len(doc.split(".")[1]) if "." in doc else 0
    print("same" if round(g, decimals) == d else "moved")
PY
)
	[ $rc -eq 0 ] || verdict=FAILED
	printf '%-36s documented %-10s measured %-12s tolerance %-8s %s (%ss)\n' "$name" "$value" "$measured" "$tol" \
		"$verdict" "$(($(date +%s) - t0))"
	printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$value" "$measured" "$tol" "$verdict" >> "$results"
	case $verdict in
		FAILED) status=1; echo "   command failed, see $log" ;;
		LEFT-TOLERANCE) status=1; moved+=("$name: $value -> $measured (tolerance $tol) OUT OF TOLERANCE, evidence $evidence") ;;
		moved) moved+=("$name: $value -> $measured (within $tol)") ;;
	esac
done < <(rows)
if [ ${#moved[@]} -gt 0 ]; then
	echo "moved:"
	printf '  %s\n' "${moved[@]}"
fi
echo "validate.sh: results in $results; $([ $status -eq 0 ] && echo "every figure within its tolerance" || echo "SOME FIGURE LEFT ITS TOLERANCE OR FAILED")"
exit $status
