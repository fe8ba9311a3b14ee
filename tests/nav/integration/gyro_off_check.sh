#!/usr/bin/env bash
# fog-drift on drives with the gyro off in places (power 0 rows; a 5 min power-off gave a heading RMS of tens of degrees, the turn made while
# the gyro was off, integrated as "no turn").
#  1. The closed-form circle drive of tests/nav/drive/TestDrive.cpp with the gyro off for
#     400 < t < 650 s (FOG: empty rate; FOG_IDEAL: 0 deg/h with power 0): the stretch and the
#     truth's 300 deg turn over it are reported, each powered span is re-aligned from the truth,
#     the figures are those of the powered spans in closed form (nav_test_drive check-gap), the
#     same streamed and --in-memory (with --csv/--plots/--odometry-out: the in-memory path's
#     concatenated series), and the text says so.
#  2. fog-sim's drive with a power-off cabin profile: no rate is written while the gyro is off
#     (an empty cell), and fog-drift's two paths agree.
#   gyro_off_check.sh NAV_TEST_DRIVE FOG_DRIFT FOG_SIM WORK_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
GEN=$1 DRIFT=$2 SIM=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK"
"$GEN" write-gap gap.rawlog cal.yaml >/dev/null
"$DRIFT" -q -i gap.rawlog --cal cal.yaml --json s.json >s.txt
"$DRIFT" -q -i gap.rawlog --cal cal.yaml --json m.json --in-memory >m.txt
"$DRIFT" -q -i gap.rawlog --cal cal.yaml --json o.json --csv gap.csv --plots plots --odometry-out odo.rawlog >o.txt
cmp s.json m.json || { echo "JSON differs: streamed vs --in-memory"; diff s.json m.json | head; exit 1; }
cmp s.txt m.txt || { echo "text differs: streamed vs --in-memory"; diff s.txt m.txt | head; exit 1; }
cmp s.json o.json || { echo "JSON differs with --csv/--plots/--odometry-out"; diff s.json o.json | head; exit 1; }
# --csv alone streams (its series spilled): the same CSV as the in-memory path's, across the stretch
"$DRIFT" -q -i gap.rawlog --cal cal.yaml --csv gap_s.csv >/dev/null
"$DRIFT" -q -i gap.rawlog --cal cal.yaml --csv gap_m.csv --in-memory >/dev/null
cmp gap_s.csv gap_m.csv || { echo "--csv differs: streamed vs --in-memory"; diff gap_s.csv gap_m.csv | head; exit 1; }
cmp gap_s.csv gap.csv || { echo "--csv differs from the --plots/--odometry-out run's"; exit 1; }
# --odometry-out streams too (the compensated trajectory and rates spilled): the same rawlog
"$DRIFT" -q -i gap.rawlog --cal cal.yaml --odometry-out odo_s.rawlog >odo_s.txt
"$DRIFT" -q -i gap.rawlog --cal cal.yaml --odometry-out odo_m.rawlog --in-memory >odo_m.txt
cmp odo_s.rawlog odo_m.rawlog || { echo "--odometry-out differs: streamed vs --in-memory"; exit 1; }
cmp odo_s.rawlog odo.rawlog || { echo "--odometry-out differs from the --csv/--plots run's"; exit 1; }
grep -q "gyro off 250.0 s in 1 stretch: heading not observable there" s.txt || { echo "no gyro-off line:"; cat s.txt; exit 1; }
grep -q "truth heading change 300.0 deg" s.txt || { echo "no truth heading change:"; cat s.txt; exit 1; }
"$GEN" check-gap s.json
# the CSV leaves the stretch out (no error where the heading is not observable)
awk -F, 'NR > 1 && $1 > 401 && $1 < 649 && $3 != "" { bad = 1 } END { exit bad }' gap.csv || { echo "CSV has errors inside the gyro-off stretch"; exit 1; }

"$SIM" -p drive --cabin "$here/cabin_power_off.yaml" --rate-hz 2 -o sim.rawlog >/dev/null 2>&1
"$SIM" -p drive --cabin "$here/cabin_power_off.yaml" --rate-hz 2 -o sim.csv >/dev/null 2>&1
# power 0 rows carry no rate (column 2 empty), power 1 rows a number
awk -F, '!/^#/ && NR > 1 && $1 != "time_s" { if ($NF == 0 && $2 != "") bad = 1; if ($NF == 1 && $2 == "") bad = 1; if ($NF == 0) off++ }
  END { if (bad || off < 400) { print "fog-sim CSV: off rows " off ", bad " bad; exit 1 } }' sim.csv
"$DRIFT" -q -i sim.rawlog --json sim_s.json >sim_s.txt
"$DRIFT" -q -i sim.rawlog --json sim_m.json --in-memory >sim_m.txt
cmp sim_s.json sim_m.json || { echo "fog-sim drive: JSON differs"; diff sim_s.json sim_m.json | head; exit 1; }
cmp sim_s.txt sim_m.txt || { echo "fog-sim drive: text differs"; exit 1; }
grep -q "gyro off 240.5 s in 1 stretch" sim_s.txt || { echo "fog-sim drive: no gyro-off line"; cat sim_s.txt; exit 1; }
echo "gyro off: reported, powered spans re-aligned, closed form met, streamed == in memory"
