#!/usr/bin/env bash
# The test multigrid_same_solution: contrib/benchmark_multigrid.cc solves the
# Newton matrix of prm/hertz.prm (K + chi M + the contact terms of the zone
# |x| < 0.1) with the program's AMG and with the geometric multigrid, on the
# scene's first mesh and once refined (5078 and 19538 DoFs), on 2 ranks.
# Passes if
#   - both preconditioners give the same solution: |x| agrees to 1e-8
#     relative (CG to 1e-10 of the load; a wrong level matrix, transfer or
#     contact term would change |x| or stall CG);
#   - the geometric multigrid's CG count stays at most 20 on both meshes
#     (measured 16 and 18; 18-19 up to 1.2e6 DoFs, where the AMG takes 37,
#     doc/benchmark_multigrid.md) and below the AMG's (23 and 27).
#   bash check_multigrid.sh <source dir> <benchmark_multigrid> <mpirun> <work dir>
set -euo pipefail
source_dir="$1"
program="$2"
mpirun="$3"
work="$4"
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
  echo "check_multigrid: $*" >&2
  exit 1
}
# the value of a key on the RESULT line of a run's output
value() { awk -v key="$2" '$1 == "RESULT" { for (i = 2; i < NF; i += 2) if ($i == key) print $(i + 1) }' "$1"; }

for refinements in 0 1; do
  for kind in amg gmg; do
    "$mpirun" -np 2 "$program" "$source_dir/prm/hertz.prm" "$refinements" "$kind" \
      > "${kind}_$refinements.out" || fail "the $kind run with $refinements refinement(s) failed"
    cat "${kind}_$refinements.out"
    [ -n "$(value "${kind}_$refinements.out" x_norm)" ] || fail "no RESULT line from the $kind run"
  done
  amg=$(value "amg_$refinements.out" x_norm)
  gmg=$(value "gmg_$refinements.out" x_norm)
  awk -v a="$amg" -v g="$gmg" 'BEGIN { d = (a > g ? a - g : g - a); exit !(a > 0 && d <= 1e-8 * a) }' ||
    fail "|x| differs: $amg (AMG) against $gmg (geometric multigrid), $refinements refinement(s)"
done
cg0=$(value gmg_0.out cg)
cg1=$(value gmg_1.out cg)
[ "$cg0" -le 20 ] && [ "$cg1" -le 20 ] ||
  fail "the geometric multigrid took $cg0 and $cg1 CG iterations (at most 20 expected)"
for refinements in 0 1; do
  [ "$(value gmg_$refinements.out cg)" -lt "$(value amg_$refinements.out cg)" ] ||
    fail "the geometric multigrid took no fewer CG iterations than the AMG ($refinements refinement(s))"
done
echo "check_multigrid: same solution with both preconditioners; CG: AMG $(value amg_0.out cg), $(value amg_1.out cg), geometric multigrid $cg0, $cg1"
