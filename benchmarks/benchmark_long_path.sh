#!/usr/bin/env bash
# What a step of a long load path costs, against the number of steps before
# it: a step's cost must not grow with the length of the path (each step's
# rows are appended to steps.csv and iterations.csv, nothing is rewritten),
# and neither must the memory.
#
#   bash benchmarks/benchmark_long_path.sh [largest number of steps]
#
# The scene is a block of 8 cells (2 x 1, 4 x 2 cells, 30 DoFs) on the plane
# y = 0 with Coulomb friction (F = 0.4), pressed and sheared in proportion
# along n uniform steps to t = 1; it runs on one rank, so that the solve is
# a few milliseconds and anything else a step costs shows. For n = 1, 100,
# 1000, 10000 (up to the largest, default 10000), the page gives the wall
# time of the run (the fastest of three), the time per step over the steps that the run has beyond
# the next shorter one ((wall(n) - wall(m)) / (n - m)), and the peak memory
# at the first and the last step (steps.csv's memory_mb). Writes
# doc/benchmarks/benchmark_long_path.{md,log} (the log: the first and last
# lines of each run's screen output). About a minute at 10000 steps.
# The program is $DUALCONTACT if set, else <repository>/build/dualcontact.
set -euo pipefail
export LC_ALL=C

largest="${1:-10000}"
case "$largest" in ''|*[!0-9]*|0) echo "benchmark_long_path: the number of steps must be a positive integer, not '$largest'" >&2; exit 2 ;; esac
# benchmarks, repo, doc, bin, bin_shown, repo_path, last_value
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" benchmark_long_path
log="$doc/benchmarks/benchmark_long_path.log"
md="$doc/benchmarks/benchmark_long_path.md"
tmp="$(mktemp -d "${TMPDIR:-/tmp}/benchmark_long_path.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT

cat > "$tmp/block.prm" <<PRM
subsection Geometry
  set Type                = rectangle
  set Lower left corner   = 0, 0
  set Upper right corner  = 2, 1
  set Subdivisions        = 4, 2
end
subsection Material
  set Young's modulus = 100
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Conditions = 2: contact, 3: traction
  set Tractions  = 3: 0.2 * t; -t
end
subsection Friction
  set Law         = coulomb
  set Coefficient = 0.4
end
subsection Output
  set Directory = $tmp/output
  set Write vtu = false
  set Verbosity = quiet
end
PRM

export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
commit="$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no -- source include 2>/dev/null)" ]; then
  commit="$commit (with local changes to the code)"
fi
cpu="$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)"

: > "$log"
rows=()
window_rows=()
previous_n=""
previous_wall=""
for n in 1 100 1000 10000 100000; do
  [ "$n" -le "$largest" ] || break
  echo "benchmark_long_path: $n steps"
  # the fastest of three runs: start-up alone takes about a second, and
  # a hundred steps a tenth of that
  wall=""
  for run in 1 2 3; do
    start=$(date +%s.%N)
    "$bin" "$tmp/block.prm" --set "Load path/Number of steps=$n" > "$tmp/screen.log"
    end=$(date +%s.%N)
    this=$(echo "$end - $start" | bc -l)
    if [ -z "$wall" ] || [ "$(echo "$this < $wall" | bc -l)" = 1 ]; then
      wall=$this
    fi
  done
  # the log: each run's first and last 25 lines (a step prints one line)
  {
    echo "=== $n steps"
    if [ "$(wc -l < "$tmp/screen.log")" -le 60 ]; then
      cat "$tmp/screen.log"
    else
      head -n 25 "$tmp/screen.log"
      echo "[... $(($(wc -l < "$tmp/screen.log") - 50)) lines ...]"
      tail -n 25 "$tmp/screen.log"
    fi
  } | sed "s|$tmp|<temporary folder>|g" >> "$log"
  steps_csv="$tmp/output/steps.csv"
  if [ "$n" -gt 1 ]; then
    first_mb=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "memory_mb") c = i; next } NR == 2 { print $c }' "$steps_csv")
    last_mb=$(last_value "$steps_csv" memory_mb)
    iterations=$(($(wc -l < "$tmp/output/iterations.csv") - 1))
  else
    first_mb=$(last_value "$tmp/output/cycles.csv" memory_mb)
    last_mb=$first_mb
    iterations=$(($(wc -l < "$tmp/output/iterations.csv") - 1))
  fi
  per_step="-"
  if [ -n "$previous_n" ]; then
    per_step=$(echo "($wall - $previous_wall) * 1000 / ($n - $previous_n)" | bc -l)
    per_step=$(printf '%.2f' "$per_step")
  fi
  rows+=("| $n | $(printf '%.2f' "$wall") | $per_step | $(printf '%.1f' "$first_mb") | $(printf '%.1f' "$last_mb") | $iterations |")
  # within the run: the wall time per step between steps 10^k and 10^(k+1)
  # (steps.csv's time_elapsed, everything included), with the Uzawa steps
  if [ "$n" -gt 1 ]; then
    windows=$(awk -F, -v n="$n" '
      NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
      { e[$c["step"]] = $c["time_elapsed"]; u[$c["step"]] = $c["uzawa_steps"] }
      END {
        for (a = 10; a < n; a *= 10) {
          b = (10 * a < n) ? 10 * a : n
          s = 0; for (k = a + 1; k <= b; ++k) s += u[k]
          printf "| %d | %d-%d | %.3f | %.2f |\n", n, a + 1, b, 1000 * (e[b] - e[a]) / (b - a), s / (b - a)
        }
      }' "$steps_csv")
    [ -z "$windows" ] || window_rows+=("$windows")
  fi
  previous_n=$n
  previous_wall=$wall
done

{
  echo "# Cost of a long load path: a 30-DoF block over 1 to $largest steps"
  echo
  echo "Regenerate with \`bash benchmarks/benchmark_long_path.sh $largest\` (program at commit $commit, 1 MPI rank"
  echo "on $(nproc) cores${cpu:+, $cpu}; $(date -u '+%Y-%m-%d')). The screen output is"
  echo "[benchmark_long_path.log](benchmark_long_path.log) (its first and last lines for each run)."
  echo
  echo "An 8-cell block (30 DoFs, Coulomb F = 0.4) pressed and sheared in proportion"
  echo "along n uniform steps to t = 1. Per run: the wall time of the whole run (the"
  echo "fastest of three), the"
  echo "time per step over the steps it has beyond the run above it ((wall(n) - wall(m))"
  echo "/ (n - m): start-up and the first step cancel), the peak memory of the run at"
  echo "its first and at its last step, and the rows of iterations.csv. A step costs"
  echo "the same however many came before when the time per step stays flat down the"
  echo "column."
  echo
  echo "| steps | wall [s] | per step [ms] | memory at step 1 [MB] | memory at the last step [MB] | rows of iterations.csv |"
  echo "|---:|---:|---:|---:|---:|---:|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "Within each run: the wall time per step between the steps 10^k and 10^(k+1)"
  echo "(steps.csv's \`time_elapsed\`, everything a step costs: solve, output, tables),"
  echo "and the mean Uzawa steps of those steps (the extrapolation from the third step"
  echo "on makes the later steps of this proportional path cheaper than the first ones)."
  echo
  echo "| run of | steps | per step [ms] | Uzawa steps per step |"
  echo "|---:|---:|---:|---:|"
  printf '%s\n' "${window_rows[@]}"
} > "$md"
echo "benchmark_long_path: wrote $(repo_path "$md") and $(repo_path "$log")"
