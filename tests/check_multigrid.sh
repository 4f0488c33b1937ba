#!/usr/bin/env bash
# The test benchmark_multigrid_same_solution (registered with
# -DDUALCONTACT_BUILD_BENCHMARKS=ON): benchmarks/benchmark_multigrid.cc
# solves the Newton matrix of prm/hertz.prm (K + chi M + the contact terms
# of the zone |x| < 0.1) with the program's AMG, with the geometric
# multigrid on assembled level matrices (gmg) and with the matrix-free one
# (mf: no matrix stored, the operator by cell quadrature), on the scene's
# first mesh and once refined (5078 and 19538 DoFs), on 2 ranks. Passes if
#   - all three give the same solution: |x| agrees to 1e-8 relative (CG to
#     1e-10 of the load; the matrix-free operator and its condensed contact
#     terms are built apart from the assembled matrix, so a wrong term there
#     changes |x| (a mass 1 % too large does: 0.5220804 against 0.5220913);
#     a wrong level matrix, transfer or smoother stalls CG);
#   - each geometric multigrid's CG count stays at most 20 on both meshes
#     (measured 16, 18 and 15, 17; 17-19 up to 1.2e6 DoFs, where the AMG
#     takes 37, doc/benchmarks/benchmark_multigrid.md) and below the AMG's
#     (23, 27). Without the contact terms on the levels the assembled one
#     takes 95 and 140.
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
  for kind in amg gmg mf; do
    "$mpirun" -np 2 "$program" "$source_dir/prm/hertz.prm" "$refinements" "$kind" \
      > "${kind}_$refinements.out" || fail "the $kind run with $refinements refinement(s) failed"
    cat "${kind}_$refinements.out"
    [ -n "$(value "${kind}_$refinements.out" x_norm)" ] || fail "no RESULT line from the $kind run"
  done
  amg=$(value "amg_$refinements.out" x_norm)
  for kind in gmg mf; do
    x=$(value "${kind}_$refinements.out" x_norm)
    awk -v a="$amg" -v g="$x" 'BEGIN { d = (a > g ? a - g : g - a); exit !(a > 0 && d <= 1e-8 * a) }' ||
      fail "|x| differs: $amg (AMG) against $x ($kind), $refinements refinement(s)"
    cg=$(value "${kind}_$refinements.out" cg)
    [ "$cg" -le 20 ] || fail "$kind took $cg CG iterations, $refinements refinement(s) (at most 20 expected)"
    [ "$cg" -lt "$(value "amg_$refinements.out" cg)" ] ||
      fail "$kind took no fewer CG iterations than the AMG, $refinements refinement(s)"
  done
done
echo "check_multigrid: the same solution with all three; CG on the two meshes: AMG $(value amg_0.out cg), $(value amg_1.out cg); gmg $(value gmg_0.out cg), $(value gmg_1.out cg); mf $(value mf_0.out cg), $(value mf_1.out cg)"
