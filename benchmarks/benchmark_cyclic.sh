#!/usr/bin/env bash
# A long cyclic load path, Mindlin-Deresiewicz's: the cylinder of
# prm/cattaneo_mindlin.prm pressed, then sheared back and forth between +d
# and -d for many cycles. After the first closed cycle every cycle must
# dissipate the same energy (Masing: the steady state of an elastic body
# with Coulomb friction under a periodic tangential load at constant normal
# load), and a step of the last cycles must cost what one of the first
# cycles costs, in time and in memory.
#
#   bash benchmarks/benchmark_cyclic.sh [cycles] [ranks]
#
# The scene's first mesh (<Refinement/Number of cycles> = 1, 5078 DoFs),
# pressed in four steps to t = 1, sheared to +d at t = 2, then cycles
# [2k, 2k + 2] of 8 steps each (+d -> -d -> +d, d = 0.002), k = 1 ..
# cycles (default 50) on `ranks` MPI ranks (default 1), with <Load
# path/Output interval> = 8 (the fields once per cycle). The page gives the
# energy each cycle dissipates and its spread, the mean wall time per step
# and the peak memory over the first and the last ten cycles, and the files
# written. Writes doc/benchmarks/benchmark_cyclic.{md,log}. About 3 minutes
# at 50 cycles on 1 rank.
# The program is $DUALCONTACT if set, else <repository>/build/dualcontact.
set -euo pipefail
export LC_ALL=C

cycles="${1:-50}"
ranks="${2:-1}"
case "$cycles" in ''|*[!0-9]*|0|1) echo "benchmark_cyclic: the number of cycles must be an integer >= 2, not '$cycles'" >&2; exit 2 ;; esac
case "$ranks" in ''|*[!0-9]*|0) echo "benchmark_cyclic: the number of ranks must be a positive integer, not '$ranks'" >&2; exit 2 ;; esac
# benchmarks, repo, doc, bin, bin_shown, repo_path, last_value
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" benchmark_cyclic
log="$doc/benchmarks/benchmark_cyclic.log"
md="$doc/benchmarks/benchmark_cyclic.md"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/benchmark_cyclic.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

# the times: 0.25 .. 2 (pressing, first shear), then 8 steps per cycle
end=$((2 + 2 * cycles))
times="$(awk -v end="$end" 'BEGIN { s = ""; for (i = 1; 0.25 * i <= end + 1e-12; ++i) s = s (i > 1 ? ", " : "") 0.25 * i; print s }')"
# the clamp: down by 0.01 over t in [0, 1]; sideways 0 up to t = 1, to +d
# at t = 2, then the triangle wave of period 2 between +d and -d
shear='0.002 * if(t <= 1, 0, if(t <= 2, t - 1, 2 * abs((t - 2) - 2 * floor((t - 2) / 2) - 1) - 1))'

export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
commit="$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no -- source include 2>/dev/null)" ]; then
  commit="$commit (with local changes to the code)"
fi
cpu="$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)"
load_before="$(cut -d' ' -f1-3 /proc/loadavg)"

echo "benchmark_cyclic: $cycles cycles on $ranks rank(s)"
start=$(date +%s.%N)
mpirun -np "$ranks" --oversubscribe "$bin" "$repo/prm/cattaneo_mindlin.prm" \
  --set "Refinement/Number of cycles=1" \
  --set "Boundary conditions/Displacements=1: $shear; -0.01 * min(t, 1)" \
  --set "Load path/Times=$times" \
  --set "Load path/Output interval=8" \
  --set "Output/Directory=$tmp/output" \
  --set "Output/Verbosity=quiet" > "$tmp/screen.log"
wall=$(echo "$(date +%s.%N) - $start" | bc -l)
load_after="$(cut -d' ' -f1-3 /proc/loadavg)"
{
  head -n 30 "$tmp/screen.log"
  echo "[... $(($(wc -l < "$tmp/screen.log") - 60)) lines ...]"
  tail -n 30 "$tmp/screen.log"
} | sed "s|$tmp|<temporary folder>|g" > "$log"

steps_csv="$tmp/output/steps.csv"
# per cycle k (t in [2k, 2k + 2]): the dissipation, the mean time per step
# (time_elapsed), the mean Uzawa steps and the peak memory at its end
per_cycle="$(awk -F, -v cycles="$cycles" '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { t = $c["time"] + 0; d[t] = $c["dissipation_total"]; e[t] = $c["time_elapsed"]; m[t] = $c["memory_mb"]
    k = int((t - 2) / 2 - 1e-9) + 1; if (t > 2) { u[k] += $c["uzawa_steps"]; n[k] += 1 } }
  END {
    for (k = 1; k <= cycles; ++k) {
      a = 2 * k; b = a + 2
      printf "%d %.12e %.6f %.3f %.1f\n", k, d[b] - d[a], 1000 * (e[b] - e[a]) / n[k], u[k] / n[k], m[b]
    }
  }' "$steps_csv")"
echo "$per_cycle" > "$tmp/cycles.txt"
# the spread of the cycles after the first against the second
spread="$(awk 'NR == 2 { ref = $2 } NR >= 2 { r = ($2 - ref) / ref; if (r < 0) r = -r; if (r > worst) worst = r } END { printf "%.2e", worst }' "$tmp/cycles.txt")"
first_vs_second="$(awk 'NR == 1 { a = $2 } NR == 2 { r = (a - $2) / $2; printf "%.2e", r }' "$tmp/cycles.txt")"
mean_over() { # first|last: the mean ms per step and Uzawa steps, the memory
  awk -v which="$1" -v cycles="$cycles" '
    { k = $1; inside = (which == "first") ? (k <= 10) : (k > cycles - 10)
      if (inside) { s += $3; u += $4; n += 1; if (first_mem == "") first_mem = $5; last_mem = $5 } }
    END { printf "| %s ten cycles | %.2f | %.2f | %.1f | %.1f |\n", which, s / n, u / n, first_mem, last_mem }' "$tmp/cycles.txt"
}
n_contact_files=$(find "$tmp/output" -name 'contact_step_*.csv' | wc -l)
n_rows=$(($(wc -l < "$steps_csv") - 1))
output_kb=$(du -sk "$tmp/output" | cut -f1)

{
  echo "# A long cyclic path: $cycles Mindlin-Deresiewicz cycles"
  echo
  echo "Regenerate with \`bash benchmarks/benchmark_cyclic.sh $cycles $ranks\` (program at commit $commit,"
  echo "$ranks MPI rank(s) on $(nproc) cores${cpu:+, $cpu}; $(date -u '+%Y-%m-%d'); load average"
  echo "(1, 5, 15 min) $load_before before and $load_after after: other work on the"
  echo "machine inflates the times). The screen output is [benchmark_cyclic.log](benchmark_cyclic.log)."
  echo
  echo "The cylinder of \`prm/cattaneo_mindlin.prm\` on its first mesh (5078 DoFs, F = 0.3,"
  echo "nu = 0.45), pressed in four steps to t = 1, sheared to +d at t = 2, then"
  echo "$cycles cycles [2k, 2k + 2] of 8 steps each, +d to -d and back (d = 0.002,"
  echo "Q*/(FP) about 0.45); \`Output interval\` = 8. $n_rows steps in ${wall%.*} s."
  echo
  echo "**Masing.** Each cycle after the first dissipates the same energy: the"
  echo "largest relative difference of cycles 2 to $cycles from cycle 2 is $spread. Cycle 1"
  echo "differs from cycle 2 by $first_vs_second (relative)."
  echo
  echo "**Cost per step.** Mean wall time per step (steps.csv's \`time_elapsed\`,"
  echo "everything a step costs) and Uzawa steps per step over the first and the"
  echo "last ten cycles, and the peak memory of all ranks at the end of the first"
  echo "and of the last of those cycles:"
  echo
  echo "| cycles | per step [ms] | Uzawa steps per step | memory at the first [MB] | memory at the last [MB] |"
  echo "|---|---:|---:|---:|---:|"
  mean_over first
  mean_over last
  echo
  echo "**Output.** $n_contact_files files contact_step_*.csv for $n_rows steps (every"
  echo "8th listed time and the last), $n_rows rows of steps.csv, ${output_kb} kB in"
  echo "the output folder."
  echo
  echo "Every cycle: the energy it dissipates, the mean wall time and Uzawa steps"
  echo "per step, the peak memory at its end."
  echo
  echo "| cycle | dissipated | per step [ms] | Uzawa steps per step | memory [MB] |"
  echo "|---:|---:|---:|---:|---:|"
  awk '{ printf "| %d | %.10e | %.2f | %.2f | %.1f |\n", $1, $2, $3, $4, $5 }' "$tmp/cycles.txt"
} > "$md"
echo "benchmark_cyclic: wrote $(repo_path "$md") and $(repo_path "$log")"
