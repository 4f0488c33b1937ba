#!/usr/bin/env bash
# Work-precision study: accuracy of the contact pressure against the cost of
# reaching it, for the three refinement strategies (global, kelly, contact),
# each with nested iteration and from a cold start (6 runs).
#
#   bash benchmarks/work_precision.sh
#
# Runs prm/$SCENE.prm (default prm/hertz_adaptive.prm: Hertz cylinder, exact
# pressure known) once per strategy x {nested, cold}, with these entries
# overridden:
#   Refinement/Strategy = <strategy>, Refinement/Number of cycles = <cycles>,
#   Refinement/Nested iteration = true | false,
#   Output/Directory = a temporary folder, Output/Write vtu = false,
#   Output/Print timing = true.
# Writes
#   doc/results.md                          tables, fits, figures embedded
#   doc/figures/data/<strategy>_<nested|cold>.csv   cycles.csv of each run
#   doc/figures/work_precision.gp           gnuplot script for the figures
#                                           (cd doc/figures && gnuplot work_precision.gp)
#   doc/figures/pressure_error_vs_time.svg
#   doc/figures/pressure_error_vs_dofs.svg
#   doc/figures/peak_and_width_error_vs_dofs.svg
# If doc/results_discussion.md exists, its text becomes the section
# "## Discussion" of doc/results.md (so the discussion survives re-runs).
# TAG=<tag> writes doc/results_<tag>.md and doc/figures/<tag>/ instead (and
# reads doc/results_<tag>_discussion.md), so that studies of other scenes
# (SCENE) stay beside this one.
#
# Environment (all optional):
#   DUALCONTACT      the program (default <repository>/build/dualcontact)
#   SCENE            prm/<SCENE>.prm (default hertz_adaptive); needs an
#                    exact contact pressure (column pressure_error)
#   CYCLES_GLOBAL    cycles of the global runs   (default 5: 1.4e3 -> 3.5e5 DoFs)
#   CYCLES_ADAPTIVE  cycles of kelly and contact (default 10: 1.4e3 -> 3.9e5 DoFs)
#   QUICK=1          a check of the script: 3 global and 5 adaptive cycles
#   STRATEGIES       default "global kelly contact"
#   NP               MPI ranks (default 2); MPIRUN_FLAGS extra mpirun options
#   REPEAT           runs per configuration (default 1); the tables use the
#                    fastest repeat, all total times are listed (noisy machines)
#   FIT_FROM         first cycle in the least-squares fits (default 1)
#   FIT_TO           last cycle in the fits (default: the last cycle run)
#   TARGET_ERROR     target pressure error (default: the finest error of the
#                    global nested run); 1e-2 is always reported as well
#   EXTRA_PRM        further entries appended to the parameter file
#   KEEP_OUTPUT=1    keep the temporary folder (screen logs, cycles.csv)
# Paths written into doc/ are relative to the repository root.
# Works from any directory; needs bash, awk, mpirun; gnuplot for the figures
# (Debian/Ubuntu: apt-get install gnuplot-nox); without gnuplot the tables
# are still written.
set -euo pipefail
export LC_ALL=C

# benchmarks, repo, doc, bin, bin_shown, repo_path
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" work_precision

scene="${SCENE:-hertz_adaptive}"
scene_prm="$repo/prm/$scene.prm"
if [ ! -f "$scene_prm" ]; then
  echo "work_precision: no parameter file '$scene_prm' (SCENE=$scene)" >&2
  exit 2
fi

if [ "${QUICK:-0}" = 1 ]; then
  cycles_global="${CYCLES_GLOBAL:-3}"
  cycles_adaptive="${CYCLES_ADAPTIVE:-5}"
else
  cycles_global="${CYCLES_GLOBAL:-5}"
  cycles_adaptive="${CYCLES_ADAPTIVE:-10}"
fi
strategies="${STRATEGIES:-global kelly contact}"
np="${NP:-2}"
fit_from="${FIT_FROM:-1}"
fit_to="${FIT_TO:-}"
repeat="${REPEAT:-1}"
target_env="${TARGET_ERROR:-}"
for v in "$cycles_global" "$cycles_adaptive" "$np" "$repeat"; do
  case "$v" in ''|*[!0-9]*|0) echo "work_precision: cycle counts and NP must be positive integers, not '$v'" >&2; exit 2 ;; esac
done
case "$fit_from" in ''|*[!0-9]*) echo "work_precision: FIT_FROM must be a non-negative integer, not '$fit_from'" >&2; exit 2 ;; esac
case "$fit_to" in *[!0-9]*) echo "work_precision: FIT_TO must be a non-negative integer, not '$fit_to'" >&2; exit 2 ;; esac
for s in $strategies; do
  case "$s" in global|kelly|contact) ;; *) echo "work_precision: unknown strategy '$s' (global, kelly, contact)" >&2; exit 2 ;; esac
done

have_gnuplot=1
if ! command -v gnuplot > /dev/null 2>&1; then
  have_gnuplot=0
  echo "work_precision: gnuplot not found; the figures are skipped (install it: apt-get install gnuplot-nox), the tables are still written" >&2
fi

# TAG=<tag> keeps another study beside the default one: doc/results_<tag>.md,
# doc/figures/<tag>/, doc/results_<tag>_discussion.md
tag="${TAG:-}"
case "$tag" in *[!A-Za-z0-9_-]*) echo "work_precision: TAG may hold letters, digits, _ and - only, not '$tag'" >&2; exit 2 ;; esac
figures_rel="figures${tag:+/$tag}"
figures="$doc/$figures_rel"
data="$figures/data"
md="$doc/results${tag:+_$tag}.md"
discussion="results${tag:+_$tag}_discussion.md"
mkdir -p "$data"

tmp="$(mktemp -d "${TMPDIR:-/tmp}/work_precision.XXXXXX")"
if [ "${KEEP_OUTPUT:-0}" = 1 ]; then
  echo "work_precision: keeping the screen logs and outputs in $tmp"
else
  trap 'rm -rf "$tmp"' EXIT
fi

# Open MPI refuses to run as root without these.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# ---- machine and source-tree facts, before the runs ----
date_run="$(date -u '+%Y-%m-%d %H:%M UTC')"
cores="$(nproc 2>/dev/null || echo '?')"
cpu="$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)"
mem_gb="$(awk '/^MemTotal/ {printf "%.0f", $2 / 1048576}' /proc/meminfo 2>/dev/null || true)"
load_before="$(cut -d" " -f1-3 /proc/loadavg 2>/dev/null || echo "?")"
bin_date="$(date -u -r "$bin" '+%Y-%m-%d %H:%M UTC' 2>/dev/null || echo "?")"
commit="$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no -- source include CMakeLists.txt "prm/$scene.prm" 2>/dev/null)" ]; then
  commit="$commit (with local changes to the code or the scene)"
fi
# the command line, with the settings that were given
invocation=""
for v in QUICK SCENE CYCLES_GLOBAL CYCLES_ADAPTIVE STRATEGIES NP REPEAT FIT_FROM FIT_TO TARGET_ERROR MPIRUN_FLAGS; do
  if [ -n "${!v:-}" ]; then
    case "${!v}" in *[[:space:]]*) invocation="$invocation$v=\"${!v}\" " ;; *) invocation="$invocation$v=${!v} " ;; esac
  fi
done
if [ -n "${DUALCONTACT:-}" ]; then invocation="${invocation}DUALCONTACT=$bin_shown "; fi
if [ -n "${EXTRA_PRM:-}" ]; then invocation="${invocation}EXTRA_PRM=... "; fi
invocation="${invocation}bash benchmarks/work_precision.sh"

# The exact solution the scene compares with (last 'set' wins).
exact_entry() {
  awk -v key="$1" '
    /^[ \t]*subsection[ \t]+Exact solution/ { inside = 1; next }
    inside && /^[ \t]*end[ \t]*$/ { inside = 0; next }
    inside && $0 ~ "^[ \t]*set[ \t]+" key "[ \t]*=" { sub(/^[^=]*=[ \t]*/, ""); sub(/[ \t]+$/, ""); v = $0 }
    END { print v }' "$scene_prm"
}
exact_pressure="$(exact_entry 'Contact pressure')"
exact_width="$(exact_entry 'Contact half-width')"
exact_peak="$(exact_entry 'Peak pressure')"

# ---- the runs ----
rm -f "$data"/*_nested.csv "$data"/*_cold.csv
runs=""
for strategy in $strategies; do runs="$runs ${strategy}_nested ${strategy}_cold"; done
declare -A best_time=() rep_times=()
start_all=$(date +%s)
for rep in $(seq 1 "$repeat"); do
  for run in $runs; do
    strategy="${run%_*}"; mode="${run##*_}"
    if [ "$strategy" = global ]; then cycles=$cycles_global; else cycles=$cycles_adaptive; fi
    if [ "$mode" = nested ]; then nested=true; else nested=false; fi
    prm="$tmp/$run.$rep.prm"
    out="$tmp/$run.$rep"
    log="$tmp/$run.$rep.log"
    # The overrides go to the program as --set arguments (the scene may set
    # the same entries, and a second 'set' in one file is an input error).
    cat > "$prm" <<EOF

# ---- overrides of benchmarks/work_precision.sh ----
subsection Refinement
  set Number of cycles = $cycles
  set Strategy         = $strategy
  set Nested iteration = $nested
end

subsection Output
  set Directory    = $out
  set Write vtu    = false
  set Print timing = true
end
EOF
    if [ -n "${EXTRA_PRM:-}" ]; then printf '%s\n' "$EXTRA_PRM" >> "$prm"; fi
    set_args=()
    while IFS= read -r entry; do
      set_args+=(--set "$entry")
    done < <(awk -f "$benchmarks/prm_overrides.awk" "$prm")

    if [ "$repeat" -gt 1 ]; then printf 'work_precision: [%d/%d] %-16s %2d cycles ... ' "$rep" "$repeat" "$run" "$cycles"
    else printf 'work_precision: %-16s %2d cycles ... ' "$run" "$cycles"; fi
    t0=$(date +%s)
    status=0
    # shellcheck disable=SC2086
    mpirun ${MPIRUN_FLAGS:-} -np "$np" "$bin" "$scene_prm" "${set_args[@]}" > "$log" 2>&1 || status=$?
    t1=$(date +%s)
    if [ "$status" -ne 0 ] || [ ! -s "$out/cycles.csv" ]; then
      echo "FAILED (exit status $status)"
      echo "work_precision: the run $run failed; the end of its screen log:" >&2
      tail -n 30 "$log" >&2
      exit 1
    fi
    t_total="$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next } { t = $c["time_total"] } END { printf "%.2f", t }' "$out/cycles.csv")"
    rep_times[$run]="${rep_times[$run]:-}${rep_times[$run]:+, }$t_total"
    # keep the fastest repeat (same meshes and errors, the least disturbed times)
    if [ -z "${best_time[$run]:-}" ] || awk -v a="$t_total" -v b="${best_time[$run]}" 'BEGIN { exit !(a + 0 < b + 0) }'; then
      best_time[$run]="$t_total"
      cp "$out/cycles.csv" "$data/$run.csv"
    fi
    echo "$((t1 - t0)) s, $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
                       { d = $c["dofs"]; e = $c["pressure_error"] }
                       END { printf "last cycle %d DoFs, pressure error %.2e", d, e }' "$out/cycles.csv"), time_total $t_total s"
  done
done
repeat_note=""
if [ "$repeat" -gt 1 ]; then
  repeat_note="Each configuration was run $repeat times (REPEAT=$repeat), interleaved; the tables and figures use the repeat with the smallest total time. Total times of the repeats [s]:"
  for run in $runs; do repeat_note="$repeat_note ${run%_*} ${run##*_}: ${rep_times[$run]};"; done
  repeat_note="${repeat_note%;}."
fi
runs="${runs# }"
elapsed=$(( $(date +%s) - start_all ))
load_after="$(cut -d" " -f1-3 /proc/loadavg 2>/dev/null || echo "?")"
echo "work_precision: all runs took $elapsed s"

# ---- target error ----
first_run="${runs# }"; first_run="${first_run%% *}"
if [ -n "$target_env" ]; then
  target="$target_env"; target_what="set by TARGET_ERROR"
elif [ -f "$data/global_nested.csv" ]; then
  target="$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next } { e = $c["pressure_error"] } END { print e }' "$data/global_nested.csv")"
  target_what="the error of the finest global mesh (global, nested, last cycle)"
else
  target="$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next } { e = $c["pressure_error"] } END { print e }' "$data/$first_run.csv")"
  target_what="the error of the last cycle of $first_run"
fi

# ---- figures ----
# The gnuplot script is written in any case, so that the figures can be made
# later from doc/figures/data; stale figures are removed.
figure_note=""
gp="$figures/work_precision.gp"
rm -f "$figures/pressure_error_vs_time.svg" "$figures/pressure_error_vs_dofs.svg" "$figures/peak_and_width_error_vs_dofs.svg"
{
  cat <<EOF
# Generated by benchmarks/work_precision.sh on $date_run; run it in doc/figures:
#   cd doc/figures && gnuplot work_precision.gp
# It reads the cycles.csv files of the runs, copied to data/<strategy>_<mode>.csv.
set datafile separator ','
set terminal svg size 900,640 dynamic noenhanced font 'Helvetica,13' background rgb 'white'
set logscale xy
set format x '%g'
set format y '%g'
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set key outside right top box opaque
target = $target
EOF
  # one style per run: colour per strategy, solid/filled nested, dashed/open cold
  i=0
  for run in $runs; do
    i=$((i + 1))
    strategy="${run%_*}"; mode="${run##*_}"
    case "$strategy" in global) colour='#1f5fbf'; pt=5 ;; kelly) colour='#2a9d3a'; pt=9 ;; *) colour='#c8302c'; pt=7 ;; esac
    # cold: dashed, open and larger points, so they stay visible around the
    # filled points of the nested run where both give the same results
    if [ "$mode" = nested ]; then dt=1; ps=1.0; else dt=2; ps=1.7; pt=$((pt - 1)); fi
    echo "set style line $i lc rgb '$colour' lw 2 dt $dt pt $pt ps $ps"
  done
  plot_runs() {  # $1 = using clause
    local i=0 sep="plot"
    for run in $runs; do
      i=$((i + 1))
      printf '%s %s using %s with linespoints ls %d title "%s"' "$sep" "'data/$run.csv'" "$1" "$i" "${run%_*}, ${run##*_}"
      sep=", \\"$'\n    '
    done
  }
  cat <<EOF

set output 'pressure_error_vs_time.svg'
set title "$scene: pressure error against cost ($np MPI ranks)"
set xlabel 'cumulative wall time of all cycles up to this one [s]'
set ylabel 'relative L2 error of the contact pressure [-]'
EOF
  plot_runs '"time_total":"pressure_error"'
  printf ', \\\n    target with lines lc rgb "#888888" dt 3 lw 1.5 title sprintf("target %%.2e", target)\n'
  cat <<EOF

set output 'pressure_error_vs_dofs.svg'
set title "$scene: pressure error against degrees of freedom"
set xlabel 'degrees of freedom [-]'
set ylabel 'relative L2 error of the contact pressure [-]'
EOF
  plot_runs '"dofs":"pressure_error"'
  printf ', \\\n    target with lines lc rgb "#888888" dt 3 lw 1.5 title sprintf("target %%.2e", target)\n'
  # cycles.csv has the error of the peak pressure and of the half-width only
  # where <Exact solution> gives them: a panel for each one known
  panels=0
  [ -n "$exact_peak" ] && panels=$((panels + 1))
  [ -n "$exact_width" ] && panels=$((panels + 1))
  if [ "$panels" -gt 0 ]; then
    cat <<EOF

set output 'peak_and_width_error_vs_dofs.svg'
set terminal svg size $((650 * panels)),560 dynamic noenhanced font 'Helvetica,13' background rgb 'white'
set multiplot layout 1,$panels title "$scene: errors of the peak pressure and of the contact half-width"
unset key
set xlabel 'degrees of freedom [-]'
EOF
    if [ -n "$exact_peak" ]; then
      echo "set title 'peak pressure (zero errors are not drawn)'"
      echo "set ylabel '|relative error of the peak pressure| [-]'"
      [ "$panels" = 1 ] && echo "set key outside right top box opaque"
      plot_runs '"dofs":(abs(column("peak_pressure_error")) > 0 ? abs(column("peak_pressure_error")) : NaN)'
      echo
    fi
    if [ -n "$exact_width" ]; then
      echo "set key outside right top box opaque"
      echo "set title 'contact half-width (zero errors are not drawn)'"
      echo "set ylabel '|relative error of the contact half-width| [-]'"
      plot_runs '"dofs":(abs(column("half_width_error")) > 0 ? abs(column("half_width_error")) : NaN)'
      echo
    fi
    echo "unset multiplot"
  fi
} > "$gp"
if [ "$have_gnuplot" = 1 ]; then
  if (cd "$figures" && gnuplot work_precision.gp) > "$tmp/gnuplot.log" 2>&1; then
    echo "work_precision: wrote the figures in $figures"
  else
    echo "work_precision: gnuplot failed; the tables are written without figures:" >&2
    cat "$tmp/gnuplot.log" >&2
    have_gnuplot=0
    figure_note="(gnuplot failed on this run; no figures.)"
  fi
else
  figure_note="(gnuplot was not installed when this file was generated, so there are no figures; install it (\`apt-get install gnuplot-nox\`) and run \`cd doc/figures && gnuplot work_precision.gp\`, or re-run the script.)"
fi

# ---- results.md ----
files=()
for run in $runs; do files+=("$data/$run.csv"); done

{
  cat <<EOF
# Work and precision: refinement strategies and nested iteration

Generated by \`$invocation\` on $date_run
(source tree at commit $commit; program \`$bin_shown\` built $bin_date).
Do not edit: re-run the script. The discussion at the end is kept in
\`doc/$discussion\`.

Machine: $cores cores${cpu:+ ($cpu)}${mem_gb:+, $mem_gb GB}; $np MPI ranks; the runs one after the other.
Load average (1, 5, 15 min) just before the runs: $load_before; just after: $load_after
(other work on the machine inflates the wall times).
Total run time of the $(( $(wc -w <<< "$runs") * repeat )) runs: $elapsed s.${repeat_note:+
$repeat_note}

**Scene** \`prm/$scene.prm\`, run once per strategy ($strategies) with
\`Nested iteration = true\` (*nested*: each mesh starts from the solution
of the previous one) and \`= false\` (*cold*: each mesh starts from zero);
$cycles_global cycles for global refinement, $cycles_adaptive for the adaptive
strategies, \`Write vtu = false\`; all other entries as in the file.
EOF
  if [ -n "$exact_pressure" ]; then
    cat <<EOF
The exact solution it compares with (section \`Exact solution\`): contact pressure
\`p(x) = $exact_pressure\`${exact_width:+, contact half-width a = $exact_width}${exact_peak:+, peak pressure p0 = $exact_peak}.
EOF
  fi
  if [ "$scene" = hertz_adaptive ]; then
    cat <<'EOF'
This is Hertz's solution for a cylinder (R = 1, E = 1000, nu = 0.3, plane
strain) pressed on a rigid plane: a = 0.05, p0 = 27.4725,
p(x) = p0 sqrt(1 - x^2/a^2). Hertz's formulas assume a half-space
(a << R); for the finite disc (a/R = 0.05) they are a very good but not an
exact reference, so the measured errors may level off at the size of that
model error instead of going to zero.
EOF
  fi
  cat <<EOF

Errors: *pressure error* = relative L2 error of the contact pressure on
Gamma_C; *half-width* and *peak* errors are signed relative errors.
*Cost* = \`time_total\` of cycles.csv: the wall time of all phases (set-up,
assembly, solve, refinement, output) of all cycles up to and including
this one, i.e. the cost of reaching this cycle's accuracy from scratch.

Data: \`doc/$figures_rel/data/<strategy>_<nested|cold>.csv\` (the cycles.csv of each run);
figures: \`cd doc/$figures_rel && gnuplot work_precision.gp\`.

## Figures

EOF
  if [ "$have_gnuplot" = 1 ]; then
    cat <<EOF
Pressure error against the cumulative wall time (solid, filled: nested; dashed, open: cold):

![pressure error vs time]($figures_rel/pressure_error_vs_time.svg)

Pressure error against the number of degrees of freedom (nested and cold
runs give the same meshes and errors, up to the solver tolerance, so their
curves lie on top of each other):

![pressure error vs DoFs]($figures_rel/pressure_error_vs_dofs.svg)
EOF
    if [ "$panels" -gt 0 ]; then
      cat <<EOF

Errors of the peak pressure and of the contact half-width:

![peak and half-width errors vs DoFs]($figures_rel/peak_and_width_error_vs_dofs.svg)
EOF
    fi
  else
    echo "$figure_note"
  fi

  # All the tables from the csv files, in one awk program.
  awk -F, -v fit_from="$fit_from" -v fit_to="$fit_to" -v target="$target" -v target_what="$target_what" '
    function lg(x) { return log(x) }
    function fmt_time(t) { return sprintf("%.2f", t) }
    function fit(r, xcol,    i, n, sx, sy, sxx, sxy, syy, x, y, d, slope, r2) {
      # least squares ln(err) = c + slope ln(x) over fit_from <= cycle <= fit_to
      n = sx = sy = sxx = sxy = syy = 0
      for (i = 1; i <= nrow[r]; ++i) {
        if (val[r, i, "cycle"] < fit_from) continue
        if (fit_to != "" && val[r, i, "cycle"] > fit_to + 0) continue
        if (val[r, i, xcol] <= 0 || val[r, i, "pressure_error"] <= 0) continue
        x = lg(val[r, i, xcol]); y = lg(val[r, i, "pressure_error"])
        ++n; sx += x; sy += y; sxx += x * x; sxy += x * y; syy += y * y
      }
      fit_n = n
      if (n < 2) { fit_s = ""; fit_r2 = ""; return }
      d = n * sxx - sx * sx
      if (d <= 0) { fit_s = ""; fit_r2 = ""; return }
      slope = (n * sxy - sx * sy) / d
      fit_s = -slope
      r2 = (n * syy - sy * sy > 0) ? (n * sxy - sx * sy)^2 / (d * (n * syy - sy * sy)) : 1
      fit_r2 = r2
    }
    function halving(s) { return (s == "" || s <= 0) ? "n/a" : sprintf("%.2f", 2^(1 / s)) }
    function expo(s)    { return (s == "") ? "n/a" : sprintf("%.2f", s) }
    function reach(r, e,    i) {
      for (i = 1; i <= nrow[r]; ++i)
        if (val[r, i, "pressure_error"] <= e * (1 + 1e-9)) return i
      return 0
    }
    FNR == 1 {
      name = FILENAME; sub(/.*\//, "", name); sub(/\.csv$/, "", name)
      r = ++nrun; run[r] = name
      strat[r] = name; sub(/_[^_]*$/, "", strat[r])
      mode[r] = name;  sub(/.*_/, "", mode[r])
      idx[strat[r], mode[r]] = r
      if (!(strat[r] in seen)) { seen[strat[r]] = 1; slist[++ns] = strat[r] }
      delete c
      for (i = 1; i <= NF; ++i) c[$i] = i
      next
    }
    {
      k = ++nrow[r]
      split("cycle cells dofs contact_nodes pressure_error half_width_error peak_pressure_error threshold_steps uzawa_steps newton_steps linear_iterations time_solve time_total", cols, " ")
      for (j in cols) {
        col = cols[j]
        val[r, k, col] = (col in c) ? $c[col] + 0 : 0
      }
    }
    END {
      # ---- convergence tables ----
      print ""
      print "## Convergence of each run"
      print ""
      print "Columns: contact nodes = nodes on Gamma_C; rate = convergence order of the"
      print "pressure error against the DoFs from the previous cycle, -ln(e_k/e_(k-1)) / ln(N_k/N_(k-1))"
      print "(0.5 is O(h) on uniform meshes in 2D); threshold / Uzawa / Newton = steps of the three"
      print "loops and CG = conjugate-gradient iterations, summed over the cycle; solve = wall time"
      print "of the contact solve of this cycle; cumulative = time_total."
      for (r = 1; r <= nrun; ++r) {
        print ""
        print "### " strat[r] ", " mode[r]
        print ""
        print "| cycle | cells | DoFs | contact nodes | pressure error | rate | half-width error | peak error | threshold | Uzawa | Newton | CG | solve [s] | cumulative [s] |"
        print "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        for (i = 1; i <= nrow[r]; ++i) {
          rate = "";
          if (i > 1 && val[r, i, "dofs"] > val[r, i - 1, "dofs"] && val[r, i, "pressure_error"] > 0 && val[r, i - 1, "pressure_error"] > 0)
            rate = sprintf("%.2f", -lg(val[r, i, "pressure_error"] / val[r, i - 1, "pressure_error"]) / lg(val[r, i, "dofs"] / val[r, i - 1, "dofs"]))
          printf "| %d | %d | %d | %d | %.2e | %s | %+.2e | %+.2e | %d | %d | %d | %d | %s | %s |\n",
            val[r, i, "cycle"], val[r, i, "cells"], val[r, i, "dofs"], val[r, i, "contact_nodes"],
            val[r, i, "pressure_error"], rate, val[r, i, "half_width_error"], val[r, i, "peak_pressure_error"],
            val[r, i, "threshold_steps"], val[r, i, "uzawa_steps"], val[r, i, "newton_steps"], val[r, i, "linear_iterations"],
            fmt_time(val[r, i, "time_solve"]), fmt_time(val[r, i, "time_total"])
        }
      }

      # ---- nested vs cold ----
      print ""
      print "## Nested iteration vs cold start"
      print ""
      print "Per refined cycle (cycle 0 is the same cold solve in both runs): steps and"
      print "solve time of the nested run / the cold run. The last column is the solve"
      print "time saved by nested iteration. Total = sum over the refined cycles; the"
      print "cumulative time of the whole run (all phases, all cycles) is given below each table."
      for (si = 1; si <= ns; ++si) {
        s = slist[si]
        if (!((s, "nested") in idx) || !((s, "cold") in idx)) continue
        a = idx[s, "nested"]; b = idx[s, "cold"]
        m = (nrow[a] < nrow[b]) ? nrow[a] : nrow[b]
        print ""
        print "### " s
        print ""
        print "| cycle | DoFs | pressure error nested / cold | Uzawa nested / cold | Newton nested / cold | CG nested / cold | solve nested / cold [s] | saved |"
        print "|---:|---:|---:|---:|---:|---:|---:|---:|"
        tu_a = tu_b = tn_a = tn_b = tc_a = tc_b = ts_a = ts_b = 0; meshdiff = 0
        for (i = 2; i <= m; ++i) {
          if (val[a, i, "dofs"] != val[b, i, "dofs"]) { dofs = sprintf("%d / %d", val[a, i, "dofs"], val[b, i, "dofs"]); ++meshdiff }
          else dofs = sprintf("%d", val[a, i, "dofs"])
          tu_a += val[a, i, "uzawa_steps"];       tu_b += val[b, i, "uzawa_steps"]
          tn_a += val[a, i, "newton_steps"];      tn_b += val[b, i, "newton_steps"]
          tc_a += val[a, i, "linear_iterations"]; tc_b += val[b, i, "linear_iterations"]
          ts_a += val[a, i, "time_solve"];        ts_b += val[b, i, "time_solve"]
          saved = (val[b, i, "time_solve"] > 0) ? sprintf("%.0f%%", 100 * (1 - val[a, i, "time_solve"] / val[b, i, "time_solve"])) : "n/a"
          printf "| %d | %s | %.3e / %.3e | %d / %d | %d / %d | %d / %d | %.2f / %.2f | %s |\n",
            val[a, i, "cycle"], dofs, val[a, i, "pressure_error"], val[b, i, "pressure_error"],
            val[a, i, "uzawa_steps"], val[b, i, "uzawa_steps"],
            val[a, i, "newton_steps"], val[b, i, "newton_steps"],
            val[a, i, "linear_iterations"], val[b, i, "linear_iterations"],
            val[a, i, "time_solve"], val[b, i, "time_solve"], saved
        }
        saved = (ts_b > 0) ? sprintf("%.0f%%", 100 * (1 - ts_a / ts_b)) : "n/a"
        printf "| **total** | | | **%d / %d** | **%d / %d** | **%d / %d** | **%.2f / %.2f** | **%s** |\n",
          tu_a, tu_b, tn_a, tn_b, tc_a, tc_b, ts_a, ts_b, saved
        print ""
        printf "Cumulative wall time of the whole run (cycles 0 to %d): nested %.2f s, cold %.2f s (%s less with nested iteration).",
          val[a, m, "cycle"], val[a, m, "time_total"], val[b, m, "time_total"],
          (val[b, m, "time_total"] > 0) ? sprintf("%.0f%%", 100 * (1 - val[a, m, "time_total"] / val[b, m, "time_total"])) : "n/a"
        if (meshdiff > 0) printf " The meshes differ in %d cycle(s): the refinement indicators see the (slightly different) discrete solutions.", meshdiff
        else printf " Both runs refine to the same meshes."
        print ""
      }

      # ---- what accuracy costs ----
      print ""
      print "## What accuracy costs"
      print ""
      printf "Least-squares fit of ln(pressure error) against ln(cumulative time) and against\n"
      printf "ln(DoFs) over the cycles %d to %s%s, giving\n", fit_from,
        (fit_to == "") ? "the last of each run" : fit_to,
        (fit_from == 1) ? " (cycle 0, whose cost is mostly start-up, is left out)" : ((fit_from == 0 && fit_to == "") ? " (all cycles)" : "")
      printf "error ~ time^(-s) and error ~ DoFs^(-r). Halving the\n"
      printf "error costs a factor 2^(1/s) in time and 2^(1/r) in DoFs (smaller is better;\n"
      printf "on uniform meshes in 2D an O(h) error gives r = 0.5, a DoF factor of 4). R^2 is the\n"
      printf "coefficient of determination of each fit (1 = the points lie on a straight line).\n"
      print ""
      print "| strategy | start | cycles fitted | s (time) | R^2 | time factor per halving | r (DoFs) | R^2 | DoF factor per halving | last error | last DoFs | last cumulative time [s] |"
      print "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
      for (r = 1; r <= nrun; ++r) {
        fit(r, "time_total"); st = fit_s; rt = fit_r2; nt = fit_n
        fit(r, "dofs");       sd = fit_s; rd = fit_r2
        n = nrow[r]
        printf "| %s | %s | %d | %s | %s | %s | %s | %s | %s | %.2e | %d | %.2f |\n",
          strat[r], mode[r], nt, expo(st), (rt == "") ? "n/a" : sprintf("%.3f", rt), halving(st),
          expo(sd), (rd == "") ? "n/a" : sprintf("%.3f", rd), halving(sd),
          val[r, n, "pressure_error"], val[r, n, "dofs"], val[r, n, "time_total"]
      }

      # targets
      ntarget = 0
      if (target + 0 < 1e-2) tlist[++ntarget] = 1e-2
      tlist[++ntarget] = target + 0
      print ""
      print "### Cost of reaching a target error"
      print ""
      printf "The first cycle whose pressure error is at or below the target: its DoFs and\n"
      if (ntarget == 2) printf "the cumulative wall time up to it. Targets: 1.00e-02, and %.2e = %s.\n", target, target_what
      else printf "the cumulative wall time up to it. Target: %.2e = %s.\n", target, target_what
      for (t = 1; t <= ntarget; ++t) {
        e = tlist[t]
        print ""
        printf "**Target %.2e**\n\n", e
        print "| strategy | start | cycle | DoFs | pressure error | cumulative time [s] | time / fastest |"
        print "|---|---|---:|---:|---:|---:|---:|"
        best = -1
        for (r = 1; r <= nrun; ++r) {
          hit[r] = reach(r, e)
          if (hit[r] > 0 && (best < 0 || val[r, hit[r], "time_total"] < best)) best = val[r, hit[r], "time_total"]
        }
        for (r = 1; r <= nrun; ++r) {
          i = hit[r]
          if (i == 0) printf "| %s | %s | not reached | | (last %.2e) | | |\n", strat[r], mode[r], val[r, nrow[r], "pressure_error"]
          else printf "| %s | %s | %d | %d | %.2e | %.2f | %.1f |\n", strat[r], mode[r], val[r, i, "cycle"], val[r, i, "dofs"],
                 val[r, i, "pressure_error"], val[r, i, "time_total"], (best > 0) ? val[r, i, "time_total"] / best : 1
        }
      }

      # monotonicity of the pressure error
      print ""
      print "### Where the pressure error does not decrease"
      print ""
      any = 0
      for (r = 1; r <= nrun; ++r)
        for (i = 2; i <= nrow[r]; ++i)
          if (val[r, i, "pressure_error"] >= val[r, i - 1, "pressure_error"]) {
            printf "- %s, %s: cycle %d (%.3e) after cycle %d (%.3e)\n", strat[r], mode[r],
              val[r, i, "cycle"], val[r, i, "pressure_error"], val[r, i - 1, "cycle"], val[r, i - 1, "pressure_error"]
            any = 1
          }
      if (!any) print "The pressure error decreases from every cycle to the next in all runs."
    }' "${files[@]}"

  echo
  echo "## Discussion"
  echo
  if [ -f "$doc/$discussion" ]; then
    cat "$doc/$discussion"
  else
    echo "(written by hand after the run)"
  fi
} > "$md"

echo "work_precision: wrote $md"
