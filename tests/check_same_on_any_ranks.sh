#!/usr/bin/env bash
# A scene solved on 1, 2, 3 and 4 ranks (3 and 4 oversubscribed on a 2-core
# machine), in each of the variants given: "name|Entry=value|Entry=value"
# (the entries as --set takes them). Passes if, for each variant, every
# number of ranks gives on every cycle the same cells, DoFs, contact nodes
# and active nodes as 1 rank, and the same contact force, largest pressure
# and ||u||_L2 to 1e-8 relative (the solvers' tolerances leave differences
# of 1e-9 at most).
#   bash check_same_on_any_ranks.sh <dualcontact> <mpirun> <scene> <work dir>
#        <variant>...
# The tests (tests/CMakeLists.txt):
# - adaptive_same_on_any_ranks: tests/prm/adaptive_block.prm (a block on the
#   foundation under a uniform traction and its own weight, whose refinement
#   indicators tie along every row of cells) refined adaptively over 5
#   cycles, with 'contact' and with 'kelly' coarsening 10 % of the cells.
#   Marking the cells by the round-off of their indicators, or smoothing the
#   mesh with the flags each rank sees, gives 512 cells on the third mesh on
#   1 rank and 488 on 2.
# - simplices_same_on_any_ranks: prm/hertz_friction.prm on triangles, whose
#   mesh every rank holds whole and partitions by itself.
# - pairs_same_on_any_ranks: prm/two_cylinders.prm, two bodies in contact,
#   graded and refined adaptively.
# - pairs_3d_same_on_any_ranks, spheres_same_on_any_ranks: the same in 3D,
#   prm/two_blocks_patch_3d.prm (hexahedra, tetrahedra) and
#   prm/two_spheres.prm (graded, then refined adaptively).
set -euo pipefail
program="$1"
mpirun="$2"
scene="$3"
work="$4"
shift 4
[ $# -gt 0 ] || { echo "check_same_on_any_ranks: no variant given" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
  echo "check_same_on_any_ranks: $*" >&2
  exit 1
}

# the columns of cycles.csv that must agree: exactly, then to 1e-8 relative
exact="cycle cells dofs contact_nodes active_nodes"
near="contact_force max_pressure u_l2"

for variant in "$@"; do
  IFS='|' read -r -a fields <<< "$variant"
  name="${fields[0]}"
  settings=()
  for entry in "${fields[@]:1}"; do
    settings+=(--set "$entry")
  done
  for np in 1 2 3 4; do
    out="${name}_np$np"
    "$mpirun" --oversubscribe -np "$np" "$program" "$scene" \
      "${settings[@]}" \
      --set "Output/Directory=$out" > "$out.log" 2>&1 ||
      fail "the run '$name' on $np rank(s) failed (see $work/$out.log)"
    [ -f "$out/cycles.csv" ] || fail "no $out/cycles.csv"
  done
  echo "$name (cells/DoFs per cycle):"
  for np in 1 2 3 4; do
    echo "  $np rank(s): $(awk -F, 'NR > 1 { printf " %s/%s", $2, $3 }' "${name}_np$np/cycles.csv")"
  done
  for np in 2 3 4; do
    awk -F, -v exact="$exact" -v near="$near" -v np="$np" '
      FNR == 1 { for (i = 1; i <= NF; ++i) column[$i] = i; next }
      FILENAME == ARGV[1] { one[FNR] = $0; rows = FNR; next }
      {
        if (!(FNR in one)) { print "cycle " FNR - 2 " exists only on " np " ranks"; bad = 1; next }
        split(one[FNR], a, ",")
        n = split(exact, names, " ")
        for (k = 1; k <= n; ++k)
          if (a[column[names[k]]] != $column[names[k]]) {
            print "cycle " a[1] ": " names[k] " " a[column[names[k]]] " on 1 rank, " $column[names[k]] " on " np
            bad = 1
          }
        n = split(near, names, " ")
        for (k = 1; k <= n; ++k) {
          x = a[column[names[k]]] + 0; y = $column[names[k]] + 0
          d = x > y ? x - y : y - x; m = (x < 0 ? -x : x)
          if (d > 1e-8 * m) {
            print "cycle " a[1] ": " names[k] " " a[column[names[k]]] " on 1 rank, " $column[names[k]] " on " np
            bad = 1
          }
        }
        last = FNR
      }
      END { if (last != rows) { print "the run on " np " ranks has " last - 1 " cycles, on 1 rank " rows - 1; bad = 1 }
            exit bad }' "${name}_np1/cycles.csv" "${name}_np$np/cycles.csv" >&2 ||
      fail "'$name' on $np ranks differs from 1 rank"
  done
done
echo "check_same_on_any_ranks: passed"
