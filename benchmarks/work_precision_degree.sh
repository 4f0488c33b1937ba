#!/usr/bin/env bash
# Work-precision study by polynomial degree: the error of the contact
# pressure and of the displacement (energy norm) against the degrees of
# freedom and against the wall time, for FE_Q(k), k = 1, 2, 3, each with
# global and with contact refinement and nested iteration, on three scenes:
# the frictionless Hertz cylinder, the same cylinder with Coulomb friction
# (2D), and the rigid sphere pressed into a block (3D Hertz).
#
#   bash benchmarks/work_precision_degree.sh
#
# Runs prm/<scene>.prm once per degree x strategy, with these entries
# overridden:
#   Discretization/Polynomial degree = <k>,
#   Refinement/Strategy = <strategy>, Refinement/Number of cycles = <cycles>,
#   Refinement/Nested iteration = true,
#   Output/Directory = a work folder, Output/Write vtu = false,
#   Output/Print timing = true;
# and Refinement/Initial global refinement = 3 for hertz_friction and = 1 for
# indenter_sphere_3d (coarser than the scenes', so that every degree has two
# meshes or more below MAX_DOFS).
# The cycle counts are chosen per degree and dimension so that the last mesh
# stays below MAX_DOFS (FE_Q(2) has about 2^d and FE_Q(3) about 3^d times the
# DoFs of FE_Q(1) on one mesh); a run whose last mesh is larger is flagged on
# the page.
#
# Errors (each cycle):
#   pressure_error        relative L2 error of the contact pressure on
#                         Gamma_C against Hertz (the program's column)
#   pressure_difference   relative L2 difference of the pressure from the
#                         reference run's: the nodal pressures l1 of both
#                         (contact_NN.csv) joined by straight lines along
#                         the coordinate s, the square of the difference
#                         integrated exactly between the merged nodes; the
#                         error where Hertz is not the answer (friction);
#                         2D scenes only (empty in 3D)
#   half_width_error      the contact half-width (2D) or radius (3D) against
#                         Hertz's, where the scene gives it (the program's)
#   peak_difference       max l1 / the reference's max l1 - 1
#   energy_error          sqrt(2 |J(u_h) - J_ref|), J the column
#                         potential_energy (1/2 a(u,u) - f(u)), J_ref that of
#                         the reference run's last cycle
# The reference run of a scene is its contact run of the highest degree
# (the finest solution of the study); its last cycle is the reference, so
# its own errors there are zero and are not drawn or fitted.
#
# Writes
#   doc/results_degree.md                       tables, fits, answers, figures
#   doc/figures/degree/data/<scene>_<strategy>_k<k>.csv
#                                               cycles.csv of each run, with
#                                               the four columns above added
#   doc/figures/degree/work_precision_degree.gp gnuplot script of the figures
#                                               (cd doc/figures/degree &&
#                                                gnuplot work_precision_degree.gp)
#   doc/figures/degree/<scene>_*.svg
# doc/results_degree_discussion.md, if it exists, becomes the section
# "## Discussion" of the page (so that the discussion survives re-runs).
#
# Environment (all optional):
#   DUALCONTACT   the program (default <repository>/build/dualcontact)
#   SCENES        default "hertz_adaptive hertz_friction indenter_sphere_3d"
#   DEGREES       default "1 2 3"
#   STRATEGIES    default "global contact"
#   CYCLES_<STRATEGY>_<k>  cycles of one strategy and degree in 2D, e.g.
#                 CYCLES_GLOBAL_3=2 (defaults: global 5, 4, 3 and contact 9,
#                 7, 6 for k = 1, 2, 3); CYCLES_3D_<STRATEGY>_<k> in 3D
#                 (defaults: global 4, 3, 2 and contact 6, 5, 4)
#   MAX_DOFS      the cap the cycle counts keep to (default 400000)
#   NP            MPI ranks (default 2); MPIRUN_FLAGS extra mpirun options
#   FIT_FROM      first cycle of the least-squares fits (default 1)
#   EXTRA_PRM     further entries appended to every parameter file
#   WORK=<dir>    keep the runs' outputs (screen logs, cycles.csv,
#                 contact_NN.csv) in <dir> instead of a temporary folder;
#                 with REUSE=1 a run whose output is in <dir> is not run
#                 again (the page is rebuilt from it)
# Paths written into doc/ are relative to the repository root. Needs bash,
# awk, sort, mpirun; gnuplot for the figures (apt-get install gnuplot-nox).
set -euo pipefail
export LC_ALL=C

# benchmarks, repo, doc, bin, bin_shown, repo_path
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" work_precision_degree
say() { echo "work_precision_degree: $*"; }
fail() { echo "work_precision_degree: $*" >&2; exit 2; }

scenes="${SCENES:-hertz_adaptive hertz_friction indenter_sphere_3d}"
degrees="${DEGREES:-1 2 3}"
strategies="${STRATEGIES:-global contact}"
max_dofs="${MAX_DOFS:-400000}"
np="${NP:-2}"
fit_from="${FIT_FROM:-1}"
for s in $scenes; do [ -f "$repo/prm/$s.prm" ] || fail "no parameter file 'prm/$s.prm' (SCENES)"; done
for k in $degrees; do case "$k" in 1|2|3) ;; *) fail "DEGREES holds 1, 2 and 3 only, not '$k'" ;; esac; done
for s in $strategies; do case "$s" in global|kelly|contact) ;; *) fail "unknown strategy '$s' (global, kelly, contact)" ;; esac; done
for v in "$max_dofs" "$np" "$fit_from"; do
  case "$v" in ''|*[!0-9]*) fail "MAX_DOFS, NP and FIT_FROM must be non-negative integers, not '$v'" ;; esac
done

# the space dimension of a scene (Geometry/Dimension, 2 unless set)
dim_of() {
  awk '/^[ \t]*subsection[ \t]+Geometry/ { g = 1 } g && /^[ \t]*end/ { g = 0 }
       g && /^[ \t]*set[ \t]+Dimension[ \t]*=/ { sub(/^[^=]*=[ \t]*/, ""); d = $1 }
       END { print (d == "") ? 2 : d }' "$repo/prm/$1.prm"
}
# cycles of one strategy, degree and dimension: CYCLES_<STRATEGY>_<k> (2D),
# CYCLES_3D_<STRATEGY>_<k> (3D), or the default
cycles_of() {
  local var n
  if [ "$3" = 3 ]; then var="CYCLES_3D_${1^^}_$2"; else var="CYCLES_${1^^}_$2"; fi
  if [ -n "${!var:-}" ]; then n="${!var}"
  elif [ "$3" = 3 ] && [ "$1" = global ]; then n=$((5 - $2))
  elif [ "$3" = 3 ]; then n=$((7 - $2))
  elif [ "$1" = global ]; then n=$((6 - $2))
  else case "$2" in 1) n=9 ;; 2) n=7 ;; *) n=6 ;; esac
  fi
  case "$n" in ''|*[!0-9]*|0) fail "$var must be a positive integer, not '$n'" ;; esac
  echo "$n"
}
# entries a scene gets beyond the common ones (listed on the page)
scene_entries() {
  case "$1" in
    hertz_friction) printf 'subsection Refinement\n  set Initial global refinement = 3\nend\n' ;;
    indenter_sphere_3d) printf 'subsection Refinement\n  set Initial global refinement = 1\nend\n' ;;
  esac
}

have_gnuplot=1
command -v gnuplot > /dev/null 2>&1 || { have_gnuplot=0; say "gnuplot not found; the figures are skipped (apt-get install gnuplot-nox), the tables are still written" >&2; }

figures_rel="figures/degree"
figures="$doc/$figures_rel"
data="$figures/data"
md="$doc/results_degree.md"
discussion="results_degree_discussion.md"
mkdir -p "$data"

if [ -n "${WORK:-}" ]; then
  work="$WORK"; mkdir -p "$work"
else
  work="$(mktemp -d "${TMPDIR:-/tmp}/work_precision_degree.XXXXXX")"
  trap 'rm -rf "$work"' EXIT
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# ---- the runs ----
commit="$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no -- source include CMakeLists.txt prm 2>/dev/null)" ]; then
  commit="$commit (with local changes to the code or the scenes)"
fi
meta="$work/meta"
if [ "${REUSE:-0}" != 1 ] || [ ! -f "$meta" ]; then
  {
    echo "date_run=\"$(date -u '+%Y-%m-%d %H:%M UTC')\""
    echo "load_before=\"$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')\""
    echo "bin_date=\"$(date -u -r "$bin" '+%Y-%m-%d %H:%M UTC' 2>/dev/null || echo '?')\""
    echo "commit=\"$commit\""
  } > "$meta"
  start_all=$(date +%s)
fi
runs=""
for scene in $scenes; do
  for k in $degrees; do
    for strategy in $strategies; do
      run="${scene}_${strategy}_k$k"
      runs="$runs $run"
      out="$work/$run"
      if [ "${REUSE:-0}" = 1 ] && [ -s "$out/cycles.csv" ]; then continue; fi
      cycles="$(cycles_of "$strategy" "$k" "$(dim_of "$scene")")"
      prm="$work/$run.prm"
      {
        echo "subsection Discretization"
        echo "  set Polynomial degree = $k"
        echo "end"
        echo "subsection Refinement"
        echo "  set Number of cycles = $cycles"
        echo "  set Strategy         = $strategy"
        echo "  set Nested iteration = true"
        echo "end"
        echo "subsection Output"
        echo "  set Directory    = $out"
        echo "  set Write vtu    = false"
        echo "  set Print timing = true"
        echo "end"
        scene_entries "$scene"
        if [ -n "${EXTRA_PRM:-}" ]; then printf '%s\n' "$EXTRA_PRM"; fi
      } > "$prm"
      set_args=()
      while IFS= read -r entry; do set_args+=(--set "$entry"); done < <(awk -f "$benchmarks/prm_overrides.awk" "$prm")
      printf 'work_precision_degree: %-34s %2d cycles ... ' "$run" "$cycles"
      t0=$(date +%s); status=0
      # shellcheck disable=SC2086
      mpirun ${MPIRUN_FLAGS:-} -np "$np" "$bin" "$repo/prm/$scene.prm" "${set_args[@]}" > "$work/$run.log" 2>&1 || status=$?
      if [ "$status" -ne 0 ] || [ ! -s "$out/cycles.csv" ]; then
        echo "FAILED (exit status $status)"
        tail -n 30 "$work/$run.log" >&2
        exit 1
      fi
      echo "$(( $(date +%s) - t0 )) s, $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
        { d = $c["dofs"]; e = $c["pressure_error"] } END { printf "last cycle %d DoFs, pressure error %.2e", d, e }' "$out/cycles.csv")"
    done
  done
done
runs="${runs# }"
if [ -n "${start_all:-}" ]; then
  {
    echo "elapsed=$(( $(date +%s) - start_all ))"
    echo "load_after=\"$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')\""
  } >> "$meta"
fi
# what the runs found out about the machine (the file written above)
date_run='?' load_before='?' bin_date='?' load_after='' elapsed=''
# shellcheck disable=SC1090
. "$meta"
say "runs done; building the page"

# The scene's value of an entry in its section 'Exact solution' (last set wins).
exact_entry() {
  awk -v key="$2" '
    /^[ \t]*subsection[ \t]+Exact solution/ { inside = 1; next }
    inside && /^[ \t]*end[ \t]*$/ { inside = 0; next }
    inside && $0 ~ "^[ \t]*set[ \t]+" key "[ \t]*=" { sub(/^[^=]*=[ \t]*/, ""); sub(/[ \t]+$/, ""); v = $0 }
    END { print v }' "$repo/prm/$1.prm"
}
# Whether the scene has friction: Hertz's frictionless pressure is then not
# its answer, and the difference from the reference run measures the error.
has_friction() {
  awk '/^[ \t]*subsection[ \t]+Friction/ { f = 1 } f && /^[ \t]*set[ \t]+Law[ \t]*=/ { sub(/^[^=]*=[ \t]*/, ""); law = $1 }
       END { exit !(law != "" && law != "none") }' "$repo/prm/$1.prm"
}
# the nodes of a contact CSV sorted along Gamma_C: s, l1 (by the header's names)
nodes_s_l1() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next } { print $c["s"] "," $c["l1"] }' "$1" | sort -t, -k1,1g
}
# column value of the last row of a csv
last_value() {
  awk -F, -v col="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next } { v = $c[col] } END { print v }' "$1"
}

# ---- the data: cycles.csv with the errors against the reference run ----
declare -A ref_run=() primary=()
for scene in $scenes; do
  # the contact run of the highest degree, else the run with the most DoFs
  ref=""; best=0
  for run in $runs; do
    case "$run" in "${scene}"_*) ;; *) continue ;; esac
    d="$(last_value "$work/$run/cycles.csv" dofs)"
    case "$run" in "${scene}_contact_k"*) d=$((d + 1000000000 * (1 + ${run##*_k}))) ;; esac
    if [ "$d" -gt "$best" ]; then best="$d"; ref="$run"; fi
  done
  ref_run[$scene]="$ref"
  if has_friction "$scene"; then primary[$scene]=pressure_difference; else primary[$scene]=pressure_error; fi
  ref_contact="$(ls "$work/$ref"/contact_[0-9]*.csv | sort | tail -n 1)"
  j_ref="$(last_value "$work/$ref/cycles.csv" potential_energy)"
  dim="$(dim_of "$scene")"
  # the reference's nodes sorted along Gamma_C: s, l1
  nodes_s_l1 "$ref_contact" > "$work/$scene.reference"
  ref_peak="$(awk -F, 'NR == 1 || $2 > m { m = $2 } END { print m }' "$work/$scene.reference")"
  for run in $runs; do
    case "$run" in "${scene}"_*) ;; *) continue ;; esac
    out="$work/$run"
    : > "$work/$run.differences"
    for f in $(ls "$out"/contact_[0-9]*.csv | sort); do
      nodes_s_l1 "$f" > "$work/$run.nodes"
      # the L2 difference along s in 2D; in 3D Gamma_C is a surface and s no
      # coordinate on it: the difference is left empty, the peak kept
      awk -F, -v dim="$dim" -v is_ref="$([ "$f" = "$ref_contact" ] && echo 1 || echo 0)" '
        # the piecewise linear function through the nodes (s, l1) of list q at s
        function at(q, x,    lo, hi, mid) {
          if (x <= S[q, 1]) return L[q, 1]
          if (x >= S[q, N[q]]) return L[q, N[q]]
          lo = 1; hi = N[q]
          while (hi - lo > 1) { mid = int((lo + hi) / 2); if (S[q, mid] <= x) lo = mid; else hi = mid }
          return (S[q, hi] > S[q, lo]) ? L[q, lo] + (L[q, hi] - L[q, lo]) * (x - S[q, lo]) / (S[q, hi] - S[q, lo]) : L[q, lo]
        }
        FNR == 1 { ++q }
        { ++N[q]; S[q, N[q]] = $1 + 0; L[q, N[q]] = $2 + 0; all[$1 + 0] = 1 }
        END {
          peak = 0
          for (i = 1; i <= N[2]; ++i) if (L[2, i] > peak) peak = L[2, i]
          if (dim == 3) { printf "- %.10e\n", peak; exit }
          # both functions are linear between the merged nodes: the integrals
          # of (l1 - l1_ref)^2 and l1_ref^2 are exact on each piece
          n = 0
          for (x in all) xs[++n] = x + 0
          asort_n(xs, n)
          for (i = 1; i <= n; ++i) { d[i] = at(2, xs[i]) - at(1, xs[i]); p[i] = at(1, xs[i]) }
          for (i = 1; i < n; ++i) {
            h = xs[i + 1] - xs[i]
            num += h * (d[i] * d[i] + d[i] * d[i + 1] + d[i + 1] * d[i + 1]) / 3
            den += h * (p[i] * p[i] + p[i] * p[i + 1] + p[i + 1] * p[i + 1]) / 3
          }
          printf "%.10e %.10e\n", (is_ref || den <= 0) ? 0 : sqrt(num / den), peak
        }
        function asort_n(v, n,    i, j, t) {  # insertion sort (n is a few thousand)
          for (i = 2; i <= n; ++i) { t = v[i]; for (j = i - 1; j >= 1 && v[j] > t; --j) v[j + 1] = v[j]; v[j + 1] = t }
        }' "$work/$scene.reference" "$work/$run.nodes" >> "$work/$run.differences"
    done
    awk -F, -v j_ref="$j_ref" -v ref_peak="$ref_peak" -v is_ref_run="$([ "$run" = "$ref" ] && echo 1 || echo 0)" '
      NR == FNR { split($0, a, " "); diff[FNR] = a[1]; peak[FNR] = a[2]; nd = FNR; next }
      FNR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; print $0 ",pressure_difference,peak_difference,energy_error"; next }
      {
        k = FNR - 1
        j = $c["potential_energy"]
        last = (is_ref_run && k == nd)
        e = last ? 0 : sqrt(2 * ((j - j_ref) < 0 ? j_ref - j : j - j_ref))
        pd = last ? 0 : peak[k] / ref_peak - 1
        printf "%s,%s,%.10e,%.10e\n", $0, (diff[k] == "-") ? "" : sprintf("%.10e", diff[k]), pd, e
      }' "$work/$run.differences" "$out/cycles.csv" > "$data/$run.csv"
  done
  echo "j_ref_$scene=$j_ref" > "$work/$scene.jref"
done


# ---- figures ----
gp="$figures/work_precision_degree.gp"
rm -f "$figures"/*.svg
measure_title() {
  case "$1" in
    pressure_error) echo "relative L2 error of the contact pressure against Hertz [-]" ;;
    pressure_difference) echo "relative L2 difference of the pressure from the reference run [-]" ;;
  esac
}
# the peak error against Hertz where the scene gives p0, else against the
# reference run
peak_column() {
  if [ -n "$(exact_entry "$1" 'Peak pressure')" ]; then echo peak_pressure_error; else echo peak_difference; fi
}
plot_scene() {  # $1 scene, $2 x column, $3 y column
  local i=0 sep="plot" k strategy
  for k in $degrees; do
    for strategy in $strategies; do
      i=$((i + 1))
      printf '%s %s using "%s":(abs(column("%s")) > 0 ? abs(column("%s")) : NaN) with linespoints ls %d title "k = %s, %s"' \
        "$sep" "'data/${1}_${strategy}_k$k.csv'" "$2" "$3" "$3" "$i" "$k" "$strategy"
      sep=", \\"$'\n    '
    done
  done
  printf '\n'
}
{
  echo "# Generated by benchmarks/work_precision_degree.sh on $date_run; run it in"
  echo "# doc/$figures_rel:  gnuplot work_precision_degree.gp"
  echo "# It reads data/<scene>_<strategy>_k<degree>.csv (cycles.csv of each run with"
  echo "# pressure_difference, peak_difference and energy_error added). Zero errors"
  echo "# (the reference point) are not drawn."
  echo "set datafile separator ','"
  echo "set terminal svg size 900,640 dynamic noenhanced font 'Helvetica,13' background rgb 'white'"
  echo "set logscale xy"
  echo "set format x '%g'"
  echo "set format y '%g'"
  echo "set grid xtics ytics mxtics mytics lc rgb '#dddddd'"
  echo "set key outside right top box opaque"
  # colour per degree; contact refinement solid with filled points, global
  # dashed with open points
  i=0
  for k in $degrees; do
    for strategy in $strategies; do
      i=$((i + 1))
      case "$k" in 1) colour='#1f5fbf' ;; 2) colour='#2a9d3a' ;; *) colour='#c8302c' ;; esac
      case "$strategy" in global) dt=2; pt=6 ;; kelly) dt=3; pt=8 ;; *) dt=1; pt=7 ;; esac
      echo "set style line $i lc rgb '$colour' lw 2 dt $dt pt $pt ps 1.2"
    done
  done
  for scene in $scenes; do
    m="${primary[$scene]}"
    pk="$(peak_column "$scene")"
    echo
    echo "set output '${scene}_pressure_vs_dofs.svg'"
    echo "set title \"$scene: contact pressure against degrees of freedom\""
    echo "set xlabel 'degrees of freedom [-]'"
    echo "set ylabel '$(measure_title "$m")'"
    plot_scene "$scene" dofs "$m"
    echo
    echo "set output '${scene}_pressure_vs_time.svg'"
    echo "set title \"$scene: contact pressure against wall time ($np MPI ranks)\""
    echo "set xlabel 'cumulative wall time of all cycles up to this one [s]'"
    plot_scene "$scene" time_total "$m"
    echo
    echo "set output '${scene}_energy_vs_dofs.svg'"
    echo "set title \"$scene: displacement in the energy norm against degrees of freedom\""
    echo "set xlabel 'degrees of freedom [-]'"
    echo "set ylabel 'sqrt(2 |J(u_h) - J_ref|), J_ref: ${ref_run[$scene]}, last cycle'"
    plot_scene "$scene" dofs energy_error
    echo
    echo "set output '${scene}_energy_vs_time.svg'"
    echo "set title \"$scene: displacement in the energy norm against wall time ($np MPI ranks)\""
    echo "set xlabel 'cumulative wall time of all cycles up to this one [s]'"
    plot_scene "$scene" time_total energy_error
    echo
    echo "set output '${scene}_peak_vs_dofs.svg'"
    echo "set title \"$scene: peak pressure against degrees of freedom\""
    echo "set xlabel 'degrees of freedom [-]'"
    if [ "$pk" = peak_pressure_error ]; then
      echo "set ylabel '|relative error of the peak pressure against Hertz| [-]'"
    else
      echo "set ylabel '|peak pressure / the reference run''s peak - 1| [-]'"
    fi
    plot_scene "$scene" dofs "$pk"
  done
} > "$gp"
figure_note=""
if [ "$have_gnuplot" = 1 ]; then
  if (cd "$figures" && gnuplot work_precision_degree.gp) > "$work/gnuplot.log" 2>&1; then
    say "wrote the figures in $figures"
  else
    echo "work_precision_degree: gnuplot failed; the tables are written without figures:" >&2
    cat "$work/gnuplot.log" >&2
    have_gnuplot=0
    figure_note="(gnuplot failed on this run; no figures.)"
  fi
else
  figure_note="(gnuplot was not installed when this page was generated; run \`cd doc/$figures_rel && gnuplot work_precision_degree.gp\`.)"
fi

# ---- the page ----
invocation=""
for v in SCENES DEGREES STRATEGIES MAX_DOFS NP FIT_FROM MPIRUN_FLAGS; do
  if [ -n "${!v:-}" ]; then
    case "${!v}" in *[[:space:]]*) invocation="$invocation$v=\"${!v}\" " ;; *) invocation="$invocation$v=${!v} " ;; esac
  fi
done
for v in $(compgen -v CYCLES_ || true); do invocation="$invocation$v=${!v} "; done
if [ -n "${DUALCONTACT:-}" ]; then invocation="${invocation}DUALCONTACT=$bin_shown "; fi
if [ -n "${EXTRA_PRM:-}" ]; then invocation="${invocation}EXTRA_PRM=... "; fi
invocation="${invocation}bash benchmarks/work_precision_degree.sh"
# the cycle counts of each strategy for the degrees, in dimension $1
cycles_text() {
  local s k
  for s in $strategies; do
    printf '%s %s and ' "$s" "$(for k in $degrees; do printf '%s, ' "$(cycles_of "$s" "$k" "$1")"; done | sed 's/, $//')"
  done | sed 's/ and $//'
}
cores="$(nproc 2>/dev/null || echo '?')"
cpu="$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)"
n_runs=$(wc -w <<< "$runs")

{
  cat <<EOF
# Work and precision by polynomial degree

Generated by \`$invocation\` on $date_run
(source tree at commit $commit; program \`$bin_shown\` built $bin_date).
Do not edit: re-run the script. The discussion at the end is kept in
\`doc/$discussion\`.

Machine: $cores cores${cpu:+ ($cpu)}; $np MPI ranks; the runs one after the other.
Load average (1, 5, 15 min) just before the runs: $load_before; just after: ${load_after:-?}
(other work on the machine inflates the wall times). Total run time of the $n_runs runs: ${elapsed:-?} s.

Each scene is run with FE_Q(k) and a mapping of degree k, k = $(echo $degrees | sed 's/ /, /g'), each with the
refinement strategies $(echo $strategies | sed 's/ /, /g'), all with nested iteration (each mesh starts
from the solution of the one before) and \`Write vtu = false\`. The cycle counts
per degree keep the last mesh below MAX_DOFS = $max_dofs DoFs (FE_Q(2) has about 2^d and
FE_Q(3) about 3^d times the DoFs of FE_Q(1) on one mesh in d dimensions); cycles for
k = $(echo $degrees | sed 's/ /, /g'): $(cycles_text 2) in 2D; $(cycles_text 3) in 3D.

What is measured, per cycle:

- *pressure error*: the relative L2 error of the contact pressure on Gamma_C
  against Hertz's (column \`pressure_error\` of cycles.csv);
- *pressure difference*: the relative L2 difference of the pressure from
  that of the scene's *reference run*, the contact-refinement run of the
  highest degree (its last cycle): the nodal pressures l1 of both
  (contact_NN.csv) joined by straight lines along the tangential
  coordinate s, the square of their difference integrated exactly between
  the merged nodes. Where Hertz's frictionless pressure is not the answer
  (friction changes the pressure by several per cent) this is the error
  measure. In 3D (a surface Gamma_C, no coordinate s) it is not computed
  (n/a);
- *peak error*: the relative error of the largest nodal pressure, against
  Hertz's p0 where the scene gives it, else against the reference run's;
- *half-width error* (2D) or *radius error* (3D): the signed relative error
  of the contact zone's half-width or radius against Hertz's a, where the
  scene gives it (column \`half_width_error\`, the program's measure from
  the contact nodes; it moves in steps of the node spacing);
- *energy error*: sqrt(2 |J(u_h) - J_ref|), J(v) = 1/2 a(v, v) - f(v) the
  potential energy of the displacement (column \`potential_energy\`; f the
  body force and the tractions, the contact terms do not enter) and J_ref
  the reference run's last J. For the exact solution u of the frictionless
  problem and any v in K, J(v) - J(u) >= 1/2 |v - u|_a^2, so at k = 1
  (K_h inside K) the figure bounds the energy-norm error from above, up to
  the error of J_ref. At k >= 2 the discrete set is not inside K
  (doc/theory.md §4), and with friction u does not minimise J (the friction
  work enters the functional), so there it is an estimate of the
  energy-norm error, not a bound. The reference point itself has energy
  error 0 and is left out of the figures and fits;
- *time*: \`time_total\`, the wall time of all phases of all cycles up to
  this one (the cost of this cycle's accuracy from scratch); *CG / Newton*:
  \`linear_iterations / newton_steps\` of the cycle; *memory*: \`memory_mb\`,
  the peak resident memory of all ranks, and that per DoF (it includes the
  fixed cost of the program and its libraries, so it falls with the size).

Data: \`doc/$figures_rel/data/<scene>_<strategy>_k<degree>.csv\` (cycles.csv of each
run, with the columns \`pressure_difference\`, \`peak_difference\` and
\`energy_error\` added); figures: \`cd doc/$figures_rel && gnuplot work_precision_degree.gp\`.
EOF

  for scene in $scenes; do
    files=()
    for run in $runs; do case "$run" in "${scene}"_*) files+=("$data/$run.csv") ;; esac; done
    m="${primary[$scene]}"
    pk="$(peak_column "$scene")"
    extra="$(scene_entries "$scene" | awk '/^subsection/ { s = $2 } /set/ { sub(/^[ \t]*set[ \t]+/, ""); printf "%s<%s/%s>", sep, s, $0; sep = ", " }' | sed 's/ *= */ = /')"
    j_ref="$(last_value "$work/${ref_run[$scene]}/cycles.csv" potential_energy)"
    echo
    echo "## $scene"
    echo
    echo "\`prm/$scene.prm\`: $(awk 'NR == 1 { sub(/^# */, ""); print; exit }' "$repo/prm/$scene.prm")"
    if has_friction "$scene"; then
      echo "Hertz's frictionless pressure is not this scene's answer (friction narrows the"
      echo "zone and raises the peak by a few per cent), so the answer below is taken from"
      echo "the *pressure difference* from the reference run; the pressure error"
      echo "against Hertz is listed as well and levels off at that model difference."
    else
      echo "Hertz's formulas hold for a half-space (a << R); on the finite disc they are a"
      echo "very good but not an exact reference, so the pressure error against Hertz"
      echo "may level off at that model error. The answer below is taken from the"
      echo "*pressure error* against Hertz, as the scene's exact solution."
    fi
    [ -n "$extra" ] && echo "Entry set for this study beyond the common ones: $extra."
    echo "Reference run: \`${ref_run[$scene]}\`, last cycle, J_ref = $j_ref."
    echo
    echo "### Figures"
    echo
    if [ "$have_gnuplot" = 1 ]; then
      cat <<EOF
Colour: degree (blue k = 1, green k = 2, red k = 3); solid lines and filled
points: contact refinement; dashed lines and open points: global refinement.

![$scene pressure vs DoFs]($figures_rel/${scene}_pressure_vs_dofs.svg)

![$scene pressure vs time]($figures_rel/${scene}_pressure_vs_time.svg)

![$scene energy vs DoFs]($figures_rel/${scene}_energy_vs_dofs.svg)

![$scene energy vs time]($figures_rel/${scene}_energy_vs_time.svg)

![$scene peak vs DoFs]($figures_rel/${scene}_peak_vs_dofs.svg)
EOF
    else
      echo "$figure_note"
    fi
    awk -F, -v fit_from="$fit_from" -v primary="$m" -v peakcol="$pk" -v max_dofs="$max_dofs" -v dim="$(dim_of "$scene")" '
      # least squares ln|y| = c + b ln x over the cycles >= fit_from; a run
      # with fewer than two such cycles is fitted from cycle 0 (fit_all = 1)
      function fit(r, xcol, ycol) {
        fit_all = 0
        fit_over(r, xcol, ycol, fit_from)
        if (fit_b == "" && fit_from > 0) { fit_over(r, xcol, ycol, 0); fit_all = (fit_b != "") }
      }
      function fit_over(r, xcol, ycol, from,    i, n, sx, sy, sxx, sxy, x, y, d) {
        n = sx = sy = sxx = sxy = 0
        for (i = 1; i <= nrow[r]; ++i) {
          if (val[r, i, "cycle"] < from) continue
          y = val[r, i, ycol]; if (y == "na") continue; if (y < 0) y = -y
          if (val[r, i, xcol] <= 0 || y <= 0) continue
          x = log(val[r, i, xcol]); y = log(y)
          ++n; sx += x; sy += y; sxx += x * x; sxy += x * y
          if (n == 1) first = val[r, i, "cycle"]
          lastc = val[r, i, "cycle"]
        }
        fit_n = n
        d = n * sxx - sx * sx
        if (n < 2 || d <= 0) { fit_b = ""; return }
        fit_b = (n * sxy - sx * sy) / d
        fit_c = (sy - fit_b * sx) / n
        fit_first = first; fit_last = lastc
      }
      function rate(r, xcol, ycol) { fit(r, xcol, ycol); return (fit_b == "") ? "n/a" : sprintf(fit_all ? "%.2f*" : "%.2f", -fit_b) }
      function a(x) { return x < 0 ? -x : x }
      function err(x) { return (x == "na") ? "n/a" : (x == 0) ? "ref." : sprintf("%.2e", a(x)) }
      function serr(x) { return (x == "na") ? "n/a" : sprintf("%+.2e", x) }
      function name(r) { return "k = " deg[r] ", " strat[r] }
      BEGIN { width = (dim == 3) ? "radius" : "half-width" }
      FNR == 1 {
        f = FILENAME; sub(/.*\//, "", f); sub(/\.csv$/, "", f)
        r = ++nrun
        deg[r] = f; sub(/.*_k/, "", deg[r])
        strat[r] = f; sub(/_k[0-9]+$/, "", strat[r]); sub(/.*_/, "", strat[r])
        delete c
        for (i = 1; i <= NF; ++i) c[$i] = i
        next
      }
      {
        k = ++nrow[r]
        n = split("cycle dofs pressure_error pressure_difference peak_pressure_error peak_difference half_width_error energy_error time_total time_assembly time_solve newton_steps linear_iterations memory_mb", cols, " ")
        # a column the run does not have, or an empty field: "na"
        for (j = 1; j <= n; ++j) val[r, k, cols[j]] = ((cols[j] in c) && $c[cols[j]] != "") ? $c[cols[j]] + 0 : "na"
      }
      END {
        print ""
        print "### Runs"
        print ""
        printf "Peak error: %s.\n", (peakcol == "peak_pressure_error") ? "against Hertz'"'"'s p0" : "against the reference run'"'"'s peak"
        print "\"ref.\": the reference point (difference 0 by definition)."
        for (r = 1; r <= nrun; ++r) {
          print ""
          printf "#### %s\n\n", name(r)
          print "| cycle | DoFs | pressure error (Hertz) | pressure difference | peak error | " width " error | energy error | time [s] | CG / Newton | memory [MB] | memory / DoF [kB] |"
          print "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
          for (i = 1; i <= nrow[r]; ++i)
            printf "| %d | %d | %s | %s | %s | %s | %s | %.2f | %.1f | %.0f | %.2f |\n",
              val[r, i, "cycle"], val[r, i, "dofs"], err(val[r, i, "pressure_error"]),
              err(val[r, i, "pressure_difference"]), err(val[r, i, peakcol]), serr(val[r, i, "half_width_error"]),
              err(val[r, i, "energy_error"]),
              val[r, i, "time_total"],
              (val[r, i, "newton_steps"] > 0) ? val[r, i, "linear_iterations"] / val[r, i, "newton_steps"] : 0,
              val[r, i, "memory_mb"], (val[r, i, "dofs"] > 0) ? 1024 * val[r, i, "memory_mb"] / val[r, i, "dofs"] : 0
          if (val[r, nrow[r], "dofs"] > max_dofs)
            printf "\nThe last mesh has more DoFs than the cap of %d (MAX_DOFS): set fewer cycles for this degree.\n", max_dofs
          fit(r, "dofs", "pressure_error")
          printf "\nRates per DoF (cycles %s to %s, least squares of ln error against ln DoFs): pressure error %s, pressure difference %s, peak error %s, %s error %s, energy error %s.\n",
            fit_first, fit_last, rate(r, "dofs", "pressure_error"), rate(r, "dofs", "pressure_difference"),
            rate(r, "dofs", peakcol), width, rate(r, "dofs", "half_width_error"), rate(r, "dofs", "energy_error")
        }

        print ""
        print "### Rates"
        print ""
        printf "Slopes -d ln(error) / d ln(DoFs) and -d ln(error) / d ln(time), least squares over the\n"
        printf "cycles %d to the last of each run (zero errors left out). In %dD, error ~ h^p is\n", fit_from, dim
        printf "a rate p/%d per DoF on uniform meshes: %.2f for O(h), %.2f for O(h^2). A rate marked *\n", dim, 1 / dim, 2 / dim
        printf "is fitted from cycle 0: the run has fewer than two cycles from cycle %d.\n", fit_from
        print ""
        print "| run | points | pressure error (Hertz) | pressure difference | peak error | " width " error | energy error | pressure (" primary ") per time |"
        print "|---|---:|---:|---:|---:|---:|---:|---:|"
        for (r = 1; r <= nrun; ++r) {
          fit(r, "dofs", "pressure_error"); np_ = fit_n
          printf "| %s | %d | %s | %s | %s | %s | %s | %s |\n", name(r), np_,
            rate(r, "dofs", "pressure_error"), rate(r, "dofs", "pressure_difference"),
            rate(r, "dofs", peakcol), rate(r, "dofs", "half_width_error"), rate(r, "dofs", "energy_error"),
            rate(r, "time_total", primary)
        }
        print ""
        print "What a run cost, summed over its cycles: CG iterations per Newton step, and the wall"
        print "time of the assembly (stiffness, mass, loads), of the contact solve and of all phases."
        print ""
        print "| run | last DoFs | CG / Newton | assembly [s] | solve [s] | total [s] |"
        print "|---|---:|---:|---:|---:|---:|"
        for (r = 1; r <= nrun; ++r) {
          cg = nw = ta = ts = 0
          for (i = 1; i <= nrow[r]; ++i) {
            cg += val[r, i, "linear_iterations"]; nw += val[r, i, "newton_steps"]
            ta += val[r, i, "time_assembly"]; ts += val[r, i, "time_solve"]
          }
          printf "| %s | %d | %.1f | %.1f | %.1f | %.1f |\n", name(r), val[r, nrow[r], "dofs"],
            (nw > 0) ? cg / nw : 0, ta, ts, val[r, nrow[r], "time_total"]
        }

        print ""
        print "### Which degree and refinement reach 1 % and 0.1 % cheapest"
        print ""
        printf "Error measure: the %s. For each run the first cycle at or below\n", (primary == "pressure_error") ? "pressure error against Hertz" : "pressure difference from the reference run"
        printf "the target, with its DoFs and cumulative wall time; where no cycle reaches it, the\n"
        printf "time and DoFs at which the run'"'"'s least-squares lines (ln error against ln time and\n"
        printf "against ln DoFs, cycles %d on) cross the target, marked *extrapolated*: an estimate\n", fit_from
        printf "that assumes the rate holds beyond the measured points (it does not where the error\n"
        printf "levels off at a model error).\n"
        split("1e-2 1e-3", targets, " ")
        for (t = 1; t <= 2; ++t) {
          e = targets[t] + 0
          print ""
          printf "**Target %s (%g %%)**\n\n", (t == 1) ? "1e-2" : "1e-3", 100 * e
          print "| run | cycle | DoFs | " primary " | time [s] | how |"
          print "|---|---:|---:|---:|---:|---|"
          best = -1; best_x = -1
          for (r = 1; r <= nrun; ++r) {
            hit = 0
            for (i = 1; i <= nrow[r]; ++i) {
              v = a(val[r, i, primary])
              if (v > 0 && v <= e * (1 + 1e-9)) { hit = i; break }
            }
            if (hit) {
              printf "| %s | %d | %d | %.2e | %.2f | measured |\n", name(r), val[r, hit, "cycle"], val[r, hit, "dofs"], a(val[r, hit, primary]), val[r, hit, "time_total"]
              if (best < 0 || val[r, hit, "time_total"] < best) { best = val[r, hit, "time_total"]; best_name = name(r); best_dofs = val[r, hit, "dofs"] }
            } else {
              fit(r, "time_total", primary); bt = fit_b; ct = fit_c
              fit(r, "dofs", primary); bd = fit_b; cd = fit_c
              if (bt == "" || bt >= 0 || bd == "" || bd >= 0)
                printf "| %s | not reached | | (last %.2e) | | no decreasing fit |\n", name(r), a(val[r, nrow[r], primary])
              else {
                tt = exp((log(e) - ct) / bt); dd = exp((log(e) - cd) / bd)
                printf "| %s | not reached | %.2g | (last %.2e) | %.3g | extrapolated |\n", name(r), dd, a(val[r, nrow[r], primary]), tt
                if (best_x < 0 || tt < best_x) { best_x = tt; best_x_name = name(r); best_x_dofs = dd }
              }
            }
          }
          print ""
          if (best >= 0) {
            printf "Cheapest measured: **%s**, %.2f s (%d DoFs).", best_name, best, best_dofs
            if (best_x >= 0 && best_x < best) printf " The extrapolation of %s would be cheaper (%.3g s, %.2g DoFs), an estimate beyond its measured points.", best_x_name, best_x, best_x_dofs
            print ""
          } else if (best_x >= 0)
            printf "No run reaches it. Cheapest by extrapolation: **%s**, about %.3g s (%.2g DoFs), an estimate beyond the measured points.\n", best_x_name, best_x, best_x_dofs
          else
            print "No run reaches it, and no run has a decreasing fit."
        }
      }' "${files[@]}"
  done

  echo
  echo "## Discussion"
  echo
  if [ -f "$doc/$discussion" ]; then cat "$doc/$discussion"; else echo "(written by hand after the run)"; fi
} > "$md"
say "wrote $md"
