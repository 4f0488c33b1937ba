#!/usr/bin/env bash
# Every scene at the edges of the documented solver ranges, on 1 and 2 MPI
# ranks: tight Uzawa tolerances, which double precision may not reach, and
# large augmentation parameters. Does each run end with exit 0, at its
# tolerance or at the round-off floor, and what does it cost?
#
#   bash benchmarks/solver_limits_sweep.sh
#
# Runs each prm/<name>.prm (SCENES="a b" picks some) once per setting of
# SETTINGS (default: <Solver/Uzawa tolerance> = 1e-13 and 1e-14, and
# <Solver/Augmentation parameter> = 100, 1000 and 1e4, each with the
# scene's other entries) on 1 and 2 ranks (RANKS), with
#   Refinement/Number of cycles = $CYCLES (default 1: the first mesh),
#   Output/Directory = a temporary folder, Output/Write vtu = false,
# and the entries of tests/regression/<name>.prm where that file exists (the
# regression tests' cheaper version of a scene). A scene keeps its own load
# path. Writes doc/benchmarks/solver_limits_sweep.md: per scene and setting
# the exit status on each rank count, the DoFs, Uzawa and Newton steps of
# the last mesh (the last load step of a path), whether the Uzawa iteration
# stopped at the round-off floor and the accuracy it reached there, the
# relative equilibrium imbalance, the wall time, and the largest relative
# difference of the contact force between 1 and 2 ranks. SKIP (an extended
# regular expression) leaves out the runs whose "<scene>:<setting>:<ranks>"
# matches it; TIME_LIMIT (default 600) stops a run after that many seconds.
# The program is $DUALCONTACT if set, else <repository>/build/dualcontact;
# extra mpirun options in $MPIRUN_FLAGS. Needs bash, awk and mpirun.
set -euo pipefail
export LC_ALL=C

# benchmarks, repo, doc, bin, bin_shown, repo_path
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" solver_limits_sweep
settings="${SETTINGS:-Solver/Uzawa tolerance=1e-13;Solver/Uzawa tolerance=1e-14;Solver/Augmentation parameter=100;Solver/Augmentation parameter=1000;Solver/Augmentation parameter=1e4}"
ranks="${RANKS:-1 2}"
cycles="${CYCLES:-1}"
skip="${SKIP:-}"
time_limit="${TIME_LIMIT:-600}"
if [ -n "${SCENES:-}" ]; then
  scenes="$SCENES"
else
  scenes="$(cd "$repo/prm" && ls -- *.prm | sed 's/\.prm$//')"
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work="$(mktemp -d)"
trap 'rm -rf -- "$work"' EXIT
out="$doc/benchmarks/solver_limits_sweep.md"

# The value of column $2 in the last row of the CSV file $1 ('' if absent).
last_value() {
  awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
    { v = (c ? $c : "") } END { print v }' "$1"
}

rows="$work/rows"
: > "$rows"
IFS=';' read -r -a setting_list <<< "$settings"
for scene in $scenes; do
  prm="$repo/prm/$scene.prm"
  [ -f "$prm" ] || { echo "solver_limits_sweep: no scene '$prm'" >&2; exit 2; }
  for setting in "${setting_list[@]}"; do
    entry="${setting%%=*}"
    overrides=()
    if [ -f "$repo/tests/regression/$scene.prm" ]; then
      # (an entry may be set once: the sweep's own entries win)
      while IFS= read -r line; do
        case "$line" in "Refinement/Number of cycles="* | "$entry="*) continue ;; esac
        overrides+=(--set "$line")
      done < <(awk -f "$benchmarks/prm_overrides.awk" "$repo/tests/regression/$scene.prm")
    fi
    label="${setting#Solver/}"
    for np in $ranks; do
      dir="$work/run"
      rm -rf -- "$dir"
      if [ -n "$skip" ] && printf '%s\n' "$scene:$label:$np" | grep -Eq -- "$skip"; then
        printf '%s\t%s\t%s\tskipped\t-\t-\t-\t-\t-\t-\t-\t-\n' "$scene" "$label" "$np" >> "$rows"
        continue
      fi
      start=$(date +%s.%N)
      status=0
      # shellcheck disable=SC2086
      timeout "$time_limit" mpirun ${MPIRUN_FLAGS:-} -np "$np" "$bin" "$prm" "${overrides[@]}" \
        --set "$setting" --set "Refinement/Number of cycles=$cycles" \
        --set "Output/Directory=$dir" --set "Output/Write vtu=false" \
        > "$work/log" 2>&1 || status=$?
      wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
      csv="$dir/cycles.csv"
      [ -f "$dir/steps.csv" ] && csv="$dir/steps.csv"
      floor=no
      reached=-
      if grep -q 'stopped at the round-off floor' "$work/log"; then
        floor=yes
        reached=$(grep -o 'accuracy reached [0-9.e+-]*' "$work/log" | tail -1 | awk '{ print $3 }')
      fi
      if [ "$status" -eq 0 ] && [ -f "$csv" ]; then
        dofs=$(last_value "$csv" dofs)
        force=$(last_value "$csv" contact_force)
        uzawa=$(last_value "$csv" uzawa_steps)
        newton=$(last_value "$csv" newton_steps)
        imbalance=$(last_value "$csv" equilibrium_imbalance)
      else
        dofs=- force=- uzawa=- newton=- imbalance=-
        grep -m1 'error' "$work/log" | cut -c1-160 >&2 || true
      fi
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$scene" "$label" "$np" "$status" \
        "$dofs" "$force" "${uzawa:--}" "${newton:--}" "$floor" "$reached" "${imbalance:--}" "$wall" >> "$rows"
      echo "solver_limits_sweep: $scene, $label, $np rank(s): exit $status, $dofs DoFs, $wall s" >&2
    done
  done
done

{
  echo "# Every scene at tight tolerances and large augmentation, on 1 and 2 ranks"
  echo
  echo "Generated by \`bash benchmarks/solver_limits_sweep.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "($(nproc) cores). Each scene of \`prm/\` with its own load path, on"
  echo "$cycles refinement cycle(s) (\`tests/regression/<name>.prm\` applied where it"
  echo "exists), with one entry changed per row. Figures of the last mesh (the last"
  echo "load step of a path) on 2 ranks where that run ended with exit 0, else on 1;"
  echo "\"floor\" says whether the Uzawa iteration stopped at the round-off floor of"
  echo "its inner solves, \"reached\" the relative change it stopped at there (the"
  echo "accuracy it names in the log), \"imbalance\" the relative equilibrium"
  echo "imbalance, \"1 vs 2\" the relative difference of the contact force between"
  echo "1 and 2 ranks. Exit status 124 is a run stopped after $time_limit s, \"skipped\""
  echo "a run left out${skip:+ (SKIP: '$skip')}."
  echo
  echo "| scene | setting | exit (1, 2 ranks) | DoFs | Uzawa | Newton | floor | reached | imbalance | time 1 rank [s] | time 2 ranks [s] | 1 vs 2 |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
  awk -F'\t' '
    { key = $1 "\t" $2; if (!(key in seen)) { order[++n] = key; seen[key] = 1 }
      st[key, $3] = $4; dofs[key, $3] = $5; f[key, $3] = $6; uz[key, $3] = $7
      nw[key, $3] = $8; fl[key, $3] = $9; re[key, $3] = $10; imb[key, $3] = $11; t[key, $3] = $12 }
    END {
      for (i = 1; i <= n; ++i) {
        key = order[i]; split(key, p, "\t")
        s1 = ((key SUBSEP 1) in st) ? st[key, 1] : "-"
        s2 = ((key SUBSEP 2) in st) ? st[key, 2] : "-"
        r = (s2 == "0") ? 2 : 1
        diff = "-"
        if (s1 == "0" && s2 == "0" && f[key, 1] != 0) { d = (f[key, 1] - f[key, 2]) / f[key, 1]; if (d < 0) d = -d; diff = sprintf("%.1e", d) }
        printf "| %s | %s | %s, %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", p[1], p[2], s1, s2,
          dofs[key, r], uz[key, r], nw[key, r], fl[key, r], re[key, r], imb[key, r],
          ((key SUBSEP 1) in t) ? t[key, 1] : "-", ((key SUBSEP 2) in t) ? t[key, 2] : "-", diff
      }
    }' "$rows"
} > "$out"
echo "solver_limits_sweep: wrote ${out#"$repo"/}" >&2
