#!/usr/bin/env bash
# The test sweep_friction: contrib/sweep.sh on prm/hertz_friction.prm (one
# cycle) for the friction coefficients F = 0.1, 0.3, 0.5, collecting the
# stick nodes. Passes if the table has one row per value, in order, each
# run's parameters.prm holds its value, the stick zone grows with F (on this
# mesh 1, 21, 35 of 63 nodes in contact: friction holds more of the surface
# as F rises), and the figure is written when gnuplot is installed.
#   bash check_sweep.sh <source dir> <dualcontact> <work dir>
set -euo pipefail
source_dir="$1"
program="$2"
work="$3"
rm -rf "$work"
mkdir -p "$work"
cd "$work"

SCENE="$source_dir/prm/hertz_friction.prm" VALUES="0.1 0.3 0.5" \
  COLUMN=stick_nodes NP=1 PROGRAM="$program" OUT=sweep \
  bash "$source_dir/contrib/sweep.sh" --set "Refinement/Number of cycles=1"

fail() {
  echo "check_sweep: $*" >&2
  exit 1
}
[ "$(head -1 sweep/sweep.csv)" = "Friction/Coefficient,stick_nodes,cells,dofs" ] ||
  fail "unexpected header: $(head -1 sweep/sweep.csv)"
[ "$(tail -n +2 sweep/sweep.csv | cut -d, -f1 | tr '\n' ' ')" = "0.1 0.3 0.5 " ] ||
  fail "the table does not have one row per value, in order"
k=0
for value in 0.1 0.3 0.5; do
  grep -q "^ *set Coefficient *= $value " "sweep/run_$k/parameters.prm" ||
    fail "sweep/run_$k/parameters.prm does not hold Coefficient = $value"
  k=$((k + 1))
done
tail -n +2 sweep/sweep.csv | awk -F, '
  NR > 1 && !($2 > previous) { bad = 1 }
  { previous = $2 }
  END { exit bad }' || fail "the stick nodes do not grow with F: $(cat sweep/sweep.csv)"
if command -v gnuplot > /dev/null; then
  grep -q "<svg" sweep/sweep.svg || fail "no figure sweep/sweep.svg"
fi
echo "check_sweep: passed"
cat sweep/sweep.csv
