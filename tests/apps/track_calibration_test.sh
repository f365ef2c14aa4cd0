#!/usr/bin/env bash
# `tendril track` never deploys on a limb without a calibration, and runs the same on the limb's
# firmware over the host bridge as on the twin: the PID's 60 steps on the circle through the real
# firmware in simavr (`tendril robot emulate limb`, robot time paused while the host answers)
# equal the twin's byte for byte, both starting from a rest read as ≈ (0°, 0°) on the calibration.
#   track_calibration_test.sh <source dir> <tendril program> <scratch dir>
set -u
source=$1 tendril=$2 scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch" && cd "$scratch" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
calibration=$source/configs/sma_limb/calibration_stiff.yaml

# No calibration: refused before anything runs or is written.
"$tendril" track circle --steps 5 -o none.csv >log 2>&1
rc=$?
[ $rc -ne 0 ] && grep -q -- "--calibration FILE" log && [ ! -e none.csv ] ||
  fail "no calibration: rc=$rc, $(tail -1 log)"
# Its robot parameters come from one place: --set may not set the calibration.
"$tendril" track circle --calibration "$calibration" --set env.params.calibration=none >log 2>&1
rc=$?
[ $rc -ne 0 ] && grep -q "own option for calibration" log || fail "--set calibration: rc=$rc"

"$tendril" track circle --calibration "$calibration" --steps 60 -o twin.csv >log 2>&1 ||
  fail "the twin: $(tail -1 log)"
# The first reading, at rest: within 1° of zero on the calibrated limb (raw: (−10°, −12°)).
awk -F, 'NR == 2 { exit !($4 * $4 < 1 && $5 * $5 < 1) }' twin.csv ||
  fail "the rest reads $(sed -n 2p twin.csv)"

"$tendril" robot emulate limb --link "$scratch/limb" --pace lockstep >emulator.log 2>&1 &
emulator=$!
trap 'kill $emulator 2>/dev/null; wait $emulator 2>/dev/null' EXIT
for _ in $(seq 50); do [ -e "$scratch/limb" ] && break; sleep 0.1; done
"$tendril" track circle --calibration "$calibration" --steps 60 -o bridge.csv \
  --set env.params.backend=bridge --set env.params.bridge.port="$scratch/limb" >log 2>&1 ||
  fail "over the bridge: $(tail -1 log)"
grep -q "limb (bridge)" log || fail "not on the bridge: $(head -1 log)"
cmp -s twin.csv bridge.csv || fail "the bridge's run differs from the twin's"
[ $failures -eq 0 ] && echo "ok: track refuses an uncalibrated limb and runs the same over the bridge"
exit $failures
