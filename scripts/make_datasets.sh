#!/usr/bin/env bash
# Regenerates every file in datasets/ bit for bit with fog-sim, and rewrites datasets/MANIFEST.md
# (what each file is, the exact command, seed, sha256).
#
#   scripts/make_datasets.sh [BUILD_DIR]        (default BUILD_DIR: ./build)
#
# Builds fog-sim in BUILD_DIR first (configuring it if needed). OUT_DIR=dir writes elsewhere
# (used by the reproducibility test); the manifest is then written there too. FOG_SIM=path uses
# that fog-sim instead of building one.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=${1:-$ROOT/build}
OUT=${OUT_DIR:-$ROOT/datasets}
SEED=20240501
RATE=10

if [ -n "${FOG_SIM:-}" ]; then
	SIM="$FOG_SIM"  # a ready fog-sim (the reproducibility test passes its own)
else
	if [ ! -f "$BUILD/CMakeCache.txt" ]; then
		cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
	fi
	cmake --build "$BUILD" -j2 --target fog-sim >/dev/null
	SIM="$BUILD/apps/fog-sim"
fi
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
cd "$ROOT"  # profiles given as files are named relative to the repository (datasets/*.yaml)

# name | profile | seed | csv twin (yes/no) | description
# ratetable_A: same (default) device as chamber_A, its own noise seed (SEED + 1) so that a joint
# calibration (-i chamber_A.rawlog -i ratetable_A.rawlog) does not see the same noise sequence twice.
RUNS=(
	"chamber_A|seed|$SEED|yes|Chamber run A: the seed paper's profile (25 C -> -40 C at 1 C/min, soak 2 h, -> 60 C at 1 C/min, soak 2 h; 6.75 h), gyro on and settled at t = 0."
	"chamber_B|B|$SEED|yes|Chamber run B (held-out validation): 20 C, 0.5 C/min down to -30 C, 1 h soak, step to -10 C, 2 C/min up to 50 C, log-swept sine (8 C, periods 60 -> 4 min, 90 min), 1.5 C/min to 25 C; 7.4 h."
	"warmup|warmup|$SEED|yes|Room-temperature warm-up: unpowered soak at 23 C, power on at t = 0, 3 h."
	"drive|drive|$SEED|no|Vehicle drive, 70.5 min: winter cold start (cabin -15 C -> 20 C at 2 C/min -> 24 C), gyro powered at t = 0; streams FOG (thermal error), FOG_IDEAL (same noise, no thermal error), ODOMETRY (CObservationOdometry), GROUND_TRUTH (CObservationRobotPose)."
	"ratetable_A|ratetable|$((SEED + 1))|no|Rate-table run, same device as chamber_A (scale factor vs temperature, IEEE Std 952 style): 90 min soaks at -40, -15, 10, 35, 60 C (2 C/min between), at each the table turns +-1, +-10, +-100 deg/s for 4 min each (table_rate_dph in the FOG observations); 10.9 h."
	"ratetable_transient|datasets/ratetable_transient.yaml|$((SEED + 2))|no|Rate table in temperature transients, same device (the coil temperature the scale factor follows, which no thermistor reads in a transient): the table alternates +-100 deg/s every 2 min through a cold turn-on at -30 C (40 min), a ramp to 50 C at 1 C/min, 30 min at 50 C, 1 h off and a turn-on at 50 C (30 min), a ramp to -30 C at 2 C/min and 20 min there; 5 h. Profile: datasets/ratetable_transient.yaml."
	"warmup_B|warmup|$((SEED + 3))|no|Second room-temperature warm-up, same profile and device as warmup.rawlog, its own noise seed (SEED + 3): with two warm-up runs fog-calibrate chooses the warm-up term's number of exponentials by held-out error, each run left out in turn (--warmup-run warmup.rawlog --warmup-run warmup_B.rawlog)."
	"chamber_C|datasets/chamber_C.yaml|$((SEED + 4))|no|Second chamber run of the same device as chamber_A, for a two-run calibration: 30 min soak at 5 C, a sine of +-20 C (period 30 min, 3 cycles), 2 C/min to -35 C, 45 min soak, 3 C/min to 55 C, 45 min soak; 4.3 h (the coil reaches about -26 and 45 C). It changes temperature on the time scale of minutes, which chamber_A's 1 C/min ramps never do: \`fog-calibrate -i chamber_A.rawlog -i chamber_C.rawlog --model multipoint -o cal.yaml --validate chamber_B.rawlog\`. Profile: datasets/chamber_C.yaml."
)

for run in "${RUNS[@]}"; do
	IFS='|' read -r name profile seed csv _ <<<"$run"
	"$SIM" --profile "$profile" --seed "$seed" --rate-hz "$RATE" -o "$OUT/$name.rawlog" >/dev/null
	if [ "$csv" = yes ]; then
		"$SIM" --profile "$profile" --seed "$seed" --rate-hz "$RATE" -o "$OUT/$name.csv.gz" >/dev/null
	fi
done

{
	echo "# datasets/ manifest"
	echo
	echo "Simulated with \`fog-sim\` (mrpt_fog simulator, default device; see docs/reference/simulator.md). Every file is"
	echo "regenerated bit for bit by \`scripts/make_datasets.sh\` (seed $SEED unless the command says"
	echo "otherwise, $RATE Hz, all error effects on)."
	echo "Rawlogs hold CObservationFOG (label FOG: rate_z in deg/h, thermistors Ti1/To1 at 0 deg and"
	echo "Ti2/To2 at 180 deg, power); the simulator configuration is in the metadata (sim.*, latitude_deg)."
	echo "The .csv.gz twins hold the same FOG stream in the lab CSV format. The drive has no CSV twin:"
	echo "its odometry and ground truth only fit a rawlog. ratetable_A has none either (size); its"
	echo "rawlog carries table_rate_dph. It is the same device as chamber_A (the default device) with"
	echo "its own noise seed, for a joint calibration:"
	echo "\`fog-calibrate -i chamber_A.rawlog -i ratetable_A.rawlog --model multipoint -o cal.yaml\`."
	echo "ratetable_transient (no CSV twin either) adds table segments in transients and turn-ons, where"
	echo "the thermistors disagree, so that fog-calibrate can fit the scale factor in a weighted sum of"
	echo "them (docs/validation/navigation.md): \`fog-calibrate -i chamber_A.rawlog -i ratetable_A.rawlog -i"
	echo "ratetable_transient.rawlog -i warmup.rawlog -o cal_full.yaml\`."
	echo
	echo "Bit-for-bit regeneration holds on the same platform (made on x86-64 Linux, GCC, glibc libm,"
	echo "Eigen 3.4, MRPT 2.5). Another C library or compiler can change the last bits of floating-point"
	echo "results (std::log/sin/cos in the noise generator, Eigen's eigen-decomposition), and then the"
	echo "checksums differ even though the physics is the same."
	echo
	echo "| file | what | command |"
	echo "|---|---|---|"
	for run in "${RUNS[@]}"; do
		IFS='|' read -r name profile seed csv what <<<"$run"
		echo "| $name.rawlog | $what | \`fog-sim --profile $profile --seed $seed --rate-hz $RATE -o $name.rawlog\` |"
		if [ "$csv" = yes ]; then
			echo "| $name.csv.gz | CSV twin of $name.rawlog | \`fog-sim --profile $profile --seed $seed --rate-hz $RATE -o $name.csv.gz\` |"
		fi
	done
	echo
	echo "## sha256"
	echo
	echo '```sha256'
	(cd "$OUT" && for run in "${RUNS[@]}"; do
		IFS='|' read -r name _ _ csv _ <<<"$run"
		sha256sum "$name.rawlog"
		if [ "$csv" = yes ]; then sha256sum "$name.csv.gz"; fi
	done)
	echo '```'
	echo
	echo "Check: \`awk '/^\`\`\`sha256/{f=1;next}/^\`\`\`/{f=0}f' MANIFEST.md | sha256sum -c\` inside datasets/."
} >"$OUT/MANIFEST.md.tmp"
mv "$OUT/MANIFEST.md.tmp" "$OUT/MANIFEST.md"
du -ch "$OUT"/*.rawlog "$OUT"/*.csv.gz | tail -1
