#!/usr/bin/env bash
# What each step of a load path costs after the first, in units of one
# linear elasticity solve on the same mesh (doc/theory.md §11).
#
#   bash benchmarks/benchmark_load_path.sh [ranks]
#
#   ranks   number of MPI ranks (default 2)
#
# SCENE=<name> runs prm/<name>.prm (default cattaneo_mindlin: pressed in
# four steps, then sheared to Q*, -Q* and Q* again in twelve); TAG=<tag>
# names doc/benchmarks/benchmark_load_path_<tag>.{log,md} (default: the
# scene's name); EXTRA_PRM adds entries to the parameter file.
# The scene runs with Output/Write vtu = false, Output/Directory = a
# temporary folder and Solver/Time a reference linear solve = true: after
# each step's contact solve the program times one linear solve with the
# same matrix and preconditioner settings (AMG set-up + CG from zero), and
# steps.csv has both. The page gives, per step, the loops' counts, the
# step's solve time and the reference's, and their ratio; then the mean
# ratio over the later steps.
# The program is $DUALCONTACT if set, else <repository>/build/dualcontact.
# Extra mpirun options (e.g. --oversubscribe) may be given in $MPIRUN_FLAGS.
set -euo pipefail
export LC_ALL=C

np="${1:-2}"
case "$np" in ''|*[!0-9]*|0) echo "benchmark_load_path: ranks must be a positive integer, not '$np'" >&2; exit 2 ;; esac
# benchmarks, repo, doc, bin, bin_shown, repo_path
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" benchmark_load_path
scene="${SCENE:-cattaneo_mindlin}"
tag="${TAG:-$scene}"
if [ ! -f "$repo/prm/$scene.prm" ]; then
  echo "benchmark_load_path: no parameter file 'prm/$scene.prm' (SCENE=$scene)" >&2
  exit 2
fi
log="$repo/doc/benchmarks/benchmark_load_path_${tag}.log"
md="$repo/doc/benchmarks/benchmark_load_path_${tag}.md"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/benchmark_load_path.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
out="$tmp/output"

overrides="$tmp/overrides.prm"
cat > "$overrides" <<PRM
subsection Output
  set Directory = $out
  set Write vtu = false
end
subsection Solver
  set Time a reference linear solve = true
end
PRM
if [ -n "${EXTRA_PRM:-}" ]; then
  printf '%s\n' "$EXTRA_PRM" >> "$overrides"
fi
set_args=()
while IFS= read -r entry; do
  set_args+=(--set "$entry")
done < <(awk -f "$benchmarks/prm_overrides.awk" "$overrides")

export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
invocation="${SCENE:+SCENE=$SCENE }${TAG:+TAG=$TAG }${EXTRA_PRM:+EXTRA_PRM=... }bash benchmarks/benchmark_load_path.sh $np"
commit="$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no -- source include 2>/dev/null)" ]; then
  commit="$commit (with local changes to the code)"
fi
cpu="$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)"

echo "benchmark_load_path: running prm/$scene.prm on $np ranks"
mpirun ${MPIRUN_FLAGS:-} -np "$np" "$bin" "${set_args[@]}" "$repo/prm/$scene.prm" | tee "$tmp/screen.log"
sed "s|$tmp|<temporary folder>|g" "$tmp/screen.log" > "$log"

{
  echo "# Cost of the steps of a load path: prm/$scene.prm"
  echo
  echo "Regenerate with \`$invocation\` (program at commit $commit, $np MPI ranks"
  echo "on $(nproc) cores${cpu:+, $cpu}; $(date -u '+%Y-%m-%d')). The screen output is"
  echo "[benchmark_load_path_${tag}.log](benchmark_load_path_${tag}.log)."
  echo
  echo "Per step: the loops' counts, the contact solve's wall time, the time of one"
  echo "linear elasticity solve with the same matrix (AMG set-up and CG from zero:"
  echo "\`Solver/Time a reference linear solve\`), and their ratio, the cost of the step"
  echo "in linear solves. Step 1 runs the refinement cycles; its row is the last"
  echo "mesh's solve, which nested iteration starts from the previous mesh."
  echo
  awk -F, '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    {
      ratio = $col["time_solve"] / $col["time_reference"]
      cg = $col["linear_iterations"] / $col["reference_iterations"]
      rows[NR] = sprintf("| %d | %.4g | %d | %d | %d | %d | %d | %d | %.3f | %.3f | %.1f | %.1f |",
        $col["step"], $col["time"], $col["dofs"], ("slip_nodes" in col) ? $col["slip_nodes"] : 0,
        $col["uzawa_steps"], $col["newton_steps"], $col["linear_iterations"], $col["amg_setups"],
        $col["time_solve"], $col["time_reference"], ratio, cg)
      if ($col["step"] > 1) { n++; sum += ratio; cgsum += cg; if (ratio > worst) worst = ratio; if (best == "" || ratio < best) best = ratio }
    }
    END {
      print "| step | t | DoFs | slip nodes | Uzawa | Newton | CG | AMG set-ups | solve [s] | linear solve [s] | cost [linear solves] | CG / linear solve CG |"
      print "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
      for (i = 2; i <= NR; ++i) print rows[i]
      print ""
      if (n > 0)
        printf "Steps 2 to %d: a step costs %.1f linear solves on average (%.1f to %.1f), its CG iterations %.1f times those of one linear solve.\n", n + 1, sum / n, best, worst, cgsum / n
    }' "$out/steps.csv"
} > "$md"
echo "benchmark_load_path: wrote $(realpath --relative-to="$repo" "$md") and $(realpath --relative-to="$repo" "$log")"
