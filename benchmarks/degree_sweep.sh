#!/usr/bin/env bash
# Every scene at every polynomial degree, on 1 and 2 MPI ranks: does it run,
# what does it cost, and do the ranks agree?
#
#   bash benchmarks/degree_sweep.sh
#
# Runs each prm/<name>.prm (SCENES="a b" picks some) at <Discretization/
# Polynomial degree> = 1, 2, 3 (DEGREES) on 1 and 2 ranks (RANKS) with these
# entries overridden:
#   Discretization/Polynomial degree = <k>, Refinement/Number of cycles =
#   $CYCLES (default 1: the scene's first mesh), Output/Directory = a
#   temporary folder, Output/Write vtu = false, Output/Print timing = true,
#   and the entries of tests/regression/<name>.prm where that file exists
#   (the regression tests' cheaper version of a scene).
# A scene keeps its own load path. Writes
# doc/benchmarks/degree_sweep.md: per scene and degree the exit status, the
# DoFs of the last mesh, the contact force, Uzawa and Newton steps, CG
# iterations per Newton step, the relative equilibrium imbalance, the wall
# time and the memory per DoF on each rank count, and the largest relative
# difference of the contact force between 1 and 2 ranks. A scene that the
# run-size estimate refuses at a degree (exit status 6: the mesh would not
# fit the machine's memory) is listed as such. The rows of the runs are
# kept in doc/benchmarks/degree_sweep.rows; SCENES="a b" (and DEGREES="3")
# re-runs those scenes (at those degrees) and rewrites the page with the
# other rows as they were.
# SKIP (an extended regular expression) leaves out the runs whose
# "<scene>:<k>:<ranks>" matches it, e.g. SKIP='_3d:3:1|sphere.*:3:1' for the
# 3D scenes at degree 3 on one rank; TIME_LIMIT (default 900) stops a run
# after that many seconds. Both are listed in the page.
# The program is $DUALCONTACT if set, else <repository>/build/dualcontact;
# extra mpirun options in $MPIRUN_FLAGS. Needs bash, awk and mpirun.
set -euo pipefail
export LC_ALL=C

# benchmarks, repo, doc, bin, bin_shown, repo_path
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" degree_sweep
degrees="${DEGREES:-1 2 3}"
ranks="${RANKS:-1 2}"
cycles="${CYCLES:-1}"
skip="${SKIP:-}"
time_limit="${TIME_LIMIT:-900}"
if [ -n "${SCENES:-}" ]; then
  scenes="$SCENES"
else
  scenes="$(cd "$repo/prm" && ls -- *.prm | sed 's/\.prm$//')"
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work="$(mktemp -d)"
trap 'rm -rf -- "$work"' EXIT
out="$repo/doc/benchmarks/degree_sweep.md"

# the rows of every run, kept beside the page: a sweep of some scenes or
# degrees (SCENES, DEGREES) replaces their rows and keeps the others'
rows="$repo/doc/benchmarks/degree_sweep.rows"
if { [ -n "${SCENES:-}" ] || [ -n "${DEGREES:-}" ]; } && [ -f "$rows" ]; then
  awk -v scenes=" $(echo $scenes) " -v degrees=" $(echo $degrees) " \
    'index(scenes, " " $1 " ") == 0 || index(degrees, " " $2 " ") == 0' "$rows" > "$work/kept"
  mv "$work/kept" "$rows"
else
  : > "$rows"
fi
for scene in $scenes; do
  prm="$repo/prm/$scene.prm"
  [ -f "$prm" ] || { echo "degree_sweep: no scene '$prm'" >&2; exit 2; }
  overrides=()
  if [ -f "$repo/tests/regression/$scene.prm" ]; then
    # (an entry may be set once: the sweep's own cycles win)
    while IFS= read -r entry; do
      case "$entry" in "Refinement/Number of cycles="*) continue ;; esac
      overrides+=(--set "$entry")
    done < <(awk -f "$benchmarks/prm_overrides.awk" "$repo/tests/regression/$scene.prm")
  fi
  for k in $degrees; do
    for np in $ranks; do
      dir="$work/$scene.$k.$np"
      if [ -n "$skip" ] && printf '%s\n' "$scene:$k:$np" | grep -Eq -- "$skip"; then
        echo "$scene $k $np skipped - - - - - - - -" >> "$rows"
        continue
      fi
      start=$(date +%s.%N)
      status=0
      # shellcheck disable=SC2086
      timeout "$time_limit" mpirun ${MPIRUN_FLAGS:-} -np "$np" "$bin" "$prm" "${overrides[@]}" \
        --set "Discretization/Polynomial degree=$k" \
        --set "Refinement/Number of cycles=$cycles" \
        --set "Output/Directory=$dir" --set "Output/Write vtu=false" \
        --set "Output/Print timing=true" > "$work/log" 2>&1 || status=$?
      wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
      csv="$dir/cycles.csv"
      [ -f "$dir/steps.csv" ] && csv="$dir/steps.csv"
      if [ "$status" -eq 0 ] && [ -f "$csv" ]; then
        dofs=$(last_value "$csv" dofs)
        force=$(last_value "$csv" contact_force)
        uzawa=$(last_value "$csv" uzawa_steps)
        newton=$(last_value "$csv" newton_steps)
        cg=$(last_value "$csv" linear_iterations)
        imbalance=$(last_value "$csv" equilibrium_imbalance)
        memory=$(last_value "$csv" memory_mb)
      else
        dofs=- force=- uzawa=- newton=- cg=- imbalance=- memory=-
        grep -m1 'error' "$work/log" | cut -c1-160 >&2 || true
      fi
      echo "$scene $k $np $status $dofs $force $uzawa $newton $cg $imbalance $wall $memory" >> "$rows"
      echo "degree_sweep: $scene, degree $k, $np rank(s): exit $status, $dofs DoFs, $wall s" >&2
    done
  done
done
# the page lists the scenes by name, then degree and ranks, whichever run
# wrote the rows
sort -k1,1 -k2,2n -k3,3n -o "$rows" "$rows"

{
  echo "# Every scene at degrees 1, 2 and 3 on 1 and 2 ranks"
  echo
  echo "Generated by \`bash benchmarks/degree_sweep.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "(the scenes of its last run: $(echo $scenes))"
  echo "($(nproc) cores). Each scene of \`prm/\` with its own load path, on"
  echo "$cycles refinement cycle(s) (\`tests/regression/<name>.prm\` applied where it"
  echo "exists), at \`<Discretization/Polynomial degree>\` = k. Figures of the last mesh (the"
  echo "last load step of a path); \"CG/Newton\" is CG iterations per Newton step,"
  echo "\"imbalance\" the relative equilibrium imbalance, \"1 vs 2\" the relative"
  echo "difference of the contact force between 1 and 2 ranks, \"mem/DoF\" the"
  echo "peak resident memory of all ranks per DoF. Exit status 6 is the run-size"
  echo "estimate refusing a mesh that would not fit the machine, 124 a run"
  echo "stopped after $time_limit s, \"skipped\" a run left out${skip:+ (SKIP of the last run: '$skip')}."
  echo
  echo "| scene | k | exit (1, 2 ranks) | DoFs | contact force | Uzawa | Newton | CG/Newton | imbalance | time 1 rank [s] | time 2 ranks [s] | mem/DoF [kB] | 1 vs 2 |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  awk '
    { key = $1 " " $2; if (!(key in seen)) { order[++n] = key; seen[key] = 1 }
      st[key, $3] = $4; dofs[key, $3] = $5; f[key, $3] = $6; uz[key, $3] = $7
      nw[key, $3] = $8; cg[key, $3] = $9; imb[key, $3] = $10; t[key, $3] = $11; mem[key, $3] = $12 }
    END {
      for (i = 1; i <= n; ++i) {
        key = order[i]; split(key, p, " ")
        r = (("" key SUBSEP "2") in st) ? 2 : 1
        s1 = ((key SUBSEP 1) in st) ? st[key, 1] : "-"
        s2 = ((key SUBSEP 2) in st) ? st[key, 2] : "-"
        cgn = (nw[key, r] != "-" && nw[key, r] > 0) ? sprintf("%.1f", cg[key, r] / nw[key, r]) : "-"
        mpd = (mem[key, r] != "-" && dofs[key, r] > 0) ? sprintf("%.1f", 1024 * mem[key, r] / dofs[key, r]) : "-"
        diff = "-"
        if (s1 == 0 && s2 == 0 && f[key, 1] != 0) { d = (f[key, 1] - f[key, 2]) / f[key, 1]; if (d < 0) d = -d; diff = sprintf("%.1e", d) }
        printf "| %s | %s | %s, %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", p[1], p[2], s1, s2,
          dofs[key, r], f[key, r], uz[key, r], nw[key, r], cgn, imb[key, r],
          ((key SUBSEP 1) in t) ? t[key, 1] : "-", ((key SUBSEP 2) in t) ? t[key, 2] : "-", mpd, diff
      }
    }' "$rows"
} > "$out"
echo "degree_sweep: wrote ${out#"$repo"/}" >&2
