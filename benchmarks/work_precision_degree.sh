#!/usr/bin/env bash
# Work-precision study by polynomial degree: the error of the contact
# pressure and of the displacement (energy norm) against the degrees of
# freedom and against the wall time, for FE_Q(k), k = 1, 2, 3, each with
# global and with contact refinement and nested iteration, on three scenes:
# the frictionless Hertz cylinder, the same cylinder with Coulomb friction
# (2D), and the rigid sphere pressed into a block (3D Hertz).
# With CELLS="quadrilateral simplex" the same study by element shape: the
# same scenes and error measures with FE_SimplexP(k) on triangles (k = 1, 2)
# and tetrahedra (k = 1) beside FE_Q(k) on quadrilaterals and hexahedra,
# plus the memory that the replicated mesh of simplices costs per rank.
#
#   bash benchmarks/work_precision_degree.sh
#   CELLS="quadrilateral simplex" bash benchmarks/work_precision_degree.sh
#                                 (or bash benchmarks/work_precision_shape.sh)
#
# Runs prm/<scene>.prm once per degree x cell shape x strategy, with these
# entries overridden:
#   Discretization/Polynomial degree = <k>,
#   Refinement/Strategy = <strategy>, Refinement/Number of cycles = <cycles>,
#   Refinement/Nested iteration = true,
#   Output/Directory = a work folder, Output/Write vtu = false,
#   Output/Print timing = true,
#   Geometry/Cell type = simplex on simplices;
# and Refinement/Initial global refinement = 3 for hertz_friction and = 1 for
# indenter_sphere_3d (coarser than the scenes', so that every degree has two
# meshes or more below MAX_DOFS). On tetrahedra the program refuses the
# pre-refinement (no hanging nodes on them in deal.II 9.4): a 3D scene runs
# there with Geometry/Pre-refinement steps = 0, indenter_sphere_3d with
# Initial global refinement = 3 (uniform tetrahedra, h = 0.25 on the first
# mesh against the contact radius 0.1).
# Simplices are run with global refinement only (the program refuses the
# adaptive strategies on them) and at k = 1, 2 in 2D and k = 1 in 3D (the
# degrees it has there with a contact boundary); the page lists what is
# left out.
# The cycle counts are chosen per degree and dimension so that the last mesh
# stays below MAX_DOFS (FE_Q(2) has about 2^d and FE_Q(3) about 3^d times the
# DoFs of FE_Q(1) on one mesh; the built-in discs make 8 triangles of each
# quadrilateral, 3.2 to 3.4 times Q1's DoFs at P1, hence one cycle fewer); a
# run whose last mesh is larger is flagged on the page.
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
# The reference run of a scene is its contact run on quadrilaterals of the
# highest degree (the finest solution of the study, the same for both
# shapes); its last cycle is the reference, so its own errors there are zero
# and are not drawn or fitted.
#
# Memory of the replicated mesh (CELLS with simplex): each scene of
# MEMORY_SCENES as the study's k = 1 global run of each shape less its last
# MEMORY_COARSER cycles, on each rank count of MEMORY_RANKS (--oversubscribe
# beyond the cores): memory_mb of the last cycle (peak resident memory
# summed over the ranks) per rank, per cell and per DoF, what each further
# rank adds, and the run-size estimate of source/run_size.cc beside it.
#
# Writes (CELLS=quadrilateral)
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
# With simplex in CELLS: doc/results_shape.md, doc/figures/shape/ (data/
# with <scene>_<strategy>_k<k>.csv for quadrilaterals and
# <scene>_<strategy>_p<k>.csv for simplices, work_precision_shape.gp, the
# figures) and doc/results_shape_discussion.md as its discussion.
#
# Environment (all optional):
#   DUALCONTACT   the program (default <repository>/build/dualcontact)
#   SCENES        default "hertz_adaptive hertz_friction indenter_sphere_3d"
#   DEGREES       default "1 2 3"
#   STRATEGIES    default "global contact"
#   CELLS         the cell shapes: quadrilateral (default; hexahedra in 3D),
#                 simplex (triangles, tetrahedra), or both
#   CYCLES_<STRATEGY>_<k>  cycles of one strategy and degree in 2D, e.g.
#                 CYCLES_GLOBAL_3=2 (defaults: global 5, 4, 3 and contact 9,
#                 7, 6 for k = 1, 2, 3); CYCLES_3D_<STRATEGY>_<k> in 3D
#                 (defaults: global 4, 3, 2 and contact 6, 5, 4);
#                 on simplices CYCLES_SIMPLEX_GLOBAL_<k> (defaults 4, 3 for
#                 k = 1, 2) and CYCLES_SIMPLEX_3D_GLOBAL_1 (default 3)
#   MAX_DOFS      the cap the cycle counts keep to (default 400000)
#   NP            MPI ranks (default 2); MPIRUN_FLAGS extra mpirun options
#   FIT_FROM      first cycle of the least-squares fits (default 1)
#   EXTRA_PRM     further entries appended to every parameter file
#   MEMORY_RANKS  rank counts of the memory runs (default "1 2 3"; empty:
#                 no memory section); CELLS with simplex only
#   MEMORY_SCENES scenes of the memory runs (default: the first 2D and the
#                 first 3D scene of SCENES)
#   MEMORY_COARSER cycles fewer than the study's k = 1 global run of each
#                 shape that the memory runs make (default 1)
#   WORK=<dir>    keep the runs' outputs (screen logs, cycles.csv,
#                 contact_NN.csv) in <dir> instead of a temporary folder;
#                 with REUSE=1 a run whose output is in <dir> is not run
#                 again (the page is rebuilt from it). The quadrilateral runs
#                 have the same names in both studies, so the shape study
#                 in the degree study's WORK with REUSE=1 runs only the
#                 simplices and the memory runs.
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
cells="${CELLS:-quadrilateral}"
for c in $cells; do case "$c" in quadrilateral|simplex) ;; *) fail "CELLS holds quadrilateral and simplex only, not '$c'" ;; esac; done
# the shape study: simplices in CELLS (its own page, figures and memory runs)
shapes=0
case " $cells " in *" simplex "*) shapes=1 ;; esac

# the space dimension of a scene (Geometry/Dimension, 2 unless set)
dim_of() {
  awk '/^[ \t]*subsection[ \t]+Geometry/ { g = 1 } g && /^[ \t]*end/ { g = 0 }
       g && /^[ \t]*set[ \t]+Dimension[ \t]*=/ { sub(/^[^=]*=[ \t]*/, ""); d = $1 }
       END { print (d == "") ? 2 : d }' "$repo/prm/$1.prm"
}
# cycles of one strategy, degree, dimension and cell shape (quadrilateral
# unless $4 is simplex): CYCLES_[SIMPLEX_][3D_]<STRATEGY>_<k>, or the default
cycles_of() {
  local var n prefix=CYCLES_
  if [ "${4:-quadrilateral}" = simplex ]; then prefix=CYCLES_SIMPLEX_; fi
  if [ "$3" = 3 ]; then var="${prefix}3D_${1^^}_$2"; else var="${prefix}${1^^}_$2"; fi
  if [ -n "${!var:-}" ]; then n="${!var}"
  # simplices: global refinement only; the discs' 8 triangles per
  # quadrilateral give P1 3.2 to 3.4 times Q1's DoFs, one cycle fewer in 2D;
  # the uniform tetrahedra of a 3D scene, 3 cycles from their own start
  elif [ "${4:-quadrilateral}" = simplex ] && [ "$3" = 3 ]; then n=3
  elif [ "${4:-quadrilateral}" = simplex ]; then n=$((5 - $2))
  elif [ "$3" = 3 ] && [ "$1" = global ]; then n=$((5 - $2))
  elif [ "$3" = 3 ]; then n=$((7 - $2))
  elif [ "$1" = global ]; then n=$((6 - $2))
  else case "$2" in 1) n=9 ;; 2) n=7 ;; *) n=6 ;; esac
  fi
  case "$n" in ''|*[!0-9]*|0) fail "$var must be a positive integer, not '$n'" ;; esac
  echo "$n"
}
# the value of Subsection/Entry ($2/$3) in the scene's file $1 ('' if unset)
scene_value() {
  awk -v sub_="$2" -v key="$3" '
    $1 == "subsection" { line = $0; sub(/^[ \t]*subsection[ \t]+/, "", line); sub(/[ \t]+$/, "", line); inside = (line == sub_); next }
    /^[ \t]*end[ \t]*$/ { inside = 0; next }
    inside && $0 ~ "^[ \t]*set[ \t]+" key "[ \t]*=" { sub(/^[^=]*=[ \t]*/, ""); sub(/[ \t]+$/, ""); v = $0 }
    END { print v }' "$repo/prm/$1.prm"
}
# entries a scene gets beyond the common ones (listed on the page), on the
# cell shape $2 (quadrilateral unless simplex)
scene_entries() {
  local igr="" pre=0
  case "$1:${2:-quadrilateral}" in
    hertz_friction:*) igr=3 ;;
    indenter_sphere_3d:quadrilateral) igr=1 ;;
    # no band of finer cells toward the sphere: start at h = 0.25
    indenter_sphere_3d:simplex) igr=3 ;;
  esac
  # tetrahedra have no hanging nodes in deal.II 9.4: the program refuses the
  # pre-refinement on them
  if [ "${2:-quadrilateral}" = simplex ] && [ "$(dim_of "$1")" = 3 ] &&
     [ "$(scene_value "$1" Geometry 'Pre-refinement steps')" -gt 0 ] 2>/dev/null; then pre=1; fi
  if [ "$pre" = 1 ]; then printf 'subsection Geometry\n  set Pre-refinement steps = 0\nend\n'; fi
  if [ -n "$igr" ]; then printf 'subsection Refinement\n  set Initial global refinement = %s\nend\n' "$igr"; fi
}
# the highest degree of FE_SimplexP with a contact boundary in dimension $1
simplex_max_degree() { if [ "$1" = 3 ]; then echo 1; else echo 2; fi; }
# the run's name: <scene>_<strategy>_k<k> on quadrilaterals,
# <scene>_<strategy>_p<k> on simplices
run_name() {  # $1 scene, $2 cell shape, $3 strategy, $4 degree
  if [ "$2" = simplex ]; then echo "${1}_${3}_p$4"; else echo "${1}_${3}_k$4"; fi
}

have_gnuplot=1
command -v gnuplot > /dev/null 2>&1 || { have_gnuplot=0; say "gnuplot not found; the figures are skipped (apt-get install gnuplot-nox), the tables are still written" >&2; }

if [ "$shapes" = 1 ]; then
  figures_rel="figures/shape" page=results_shape gp_name=work_precision_shape.gp meta_name=meta_shape
else
  figures_rel="figures/degree" page=results_degree gp_name=work_precision_degree.gp meta_name=meta
fi
figures="$doc/$figures_rel"
data="$figures/data"
md="$doc/$page.md"
discussion="${page}_discussion.md"
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
meta="$work/$meta_name"
if [ "${REUSE:-0}" != 1 ] || [ ! -f "$meta" ]; then
  {
    echo "date_run=\"$(date -u '+%Y-%m-%d %H:%M UTC')\""
    echo "load_before=\"$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')\""
    echo "bin_date=\"$(date -u -r "$bin" '+%Y-%m-%d %H:%M UTC' 2>/dev/null || echo '?')\""
    echo "commit=\"$commit\""
  } > "$meta"
  start_all=$(date +%s)
fi
# Runs scene $2 with the overrides $work/$1.prm as run $1 on $3 ranks, its
# output in $work/$1; stops the script if the run fails. With $5 = 1, more
# ranks than cores are allowed (--oversubscribe).
run_scene() {  # $1 run, $2 scene, $3 ranks, $4 cycles (for the message), $5
  local set_args=() entry t0 status=0 flags="${MPIRUN_FLAGS:-}"
  while IFS= read -r entry; do set_args+=(--set "$entry"); done < <(awk -f "$benchmarks/prm_overrides.awk" "$work/$1.prm")
  if [ "${5:-0}" = 1 ] && [ "$3" -gt "$(nproc 2>/dev/null || echo 1)" ]; then
    case "$flags" in *oversubscribe*) ;; *) flags="$flags --oversubscribe" ;; esac
  fi
  printf 'work_precision_degree: %-34s %2d cycles ... ' "$1" "$4"
  t0=$(date +%s)
  # shellcheck disable=SC2086
  mpirun $flags -np "$3" "$bin" "$repo/prm/$2.prm" "${set_args[@]}" > "$work/$1.log" 2>&1 || status=$?
  if [ "$status" -ne 0 ] || [ ! -s "$work/$1/cycles.csv" ]; then
    echo "FAILED (exit status $status)"
    tail -n 30 "$work/$1.log" >&2
    exit 1
  fi
  echo "$(( $(date +%s) - t0 )) s, $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { d = $c["dofs"]; e = $c["pressure_error"] } END { printf "last cycle %d DoFs, pressure error %.2e", d, e }' "$work/$1/cycles.csv")"
}
runs="" skipped="" n_ran=0
for scene in $scenes; do
  dim="$(dim_of "$scene")"
  for k in $degrees; do
    for cell in $cells; do
      for strategy in $strategies; do
        if [ "$cell" = simplex ]; then
          # what the program refuses on simplices, left out with a note
          if [ "$k" -gt "$(simplex_max_degree "$dim")" ]; then
            skipped="$skipped $scene:$strategy:$k:degree"; continue
          elif [ "$strategy" != global ]; then
            skipped="$skipped $scene:$strategy:$k:strategy"; continue
          fi
        fi
        run="$(run_name "$scene" "$cell" "$strategy" "$k")"
        runs="$runs $run"
        out="$work/$run"
        if [ "${REUSE:-0}" = 1 ] && [ -s "$out/cycles.csv" ]; then continue; fi
        cycles="$(cycles_of "$strategy" "$k" "$dim" "$cell")"
        prm="$work/$run.prm"
        {
          if [ "$cell" = simplex ]; then
            echo "subsection Geometry"
            echo "  set Cell type = simplex"
            echo "end"
          fi
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
          scene_entries "$scene" "$cell"
          if [ -n "${EXTRA_PRM:-}" ]; then printf '%s\n' "$EXTRA_PRM"; fi
        } > "$prm"
        run_scene "$run" "$scene" "$np" "$cycles"
        n_ran=$((n_ran + 1))
      done
    done
  done
done
runs="${runs# }"

# ---- the memory runs: the replicated mesh of simplices per rank ----
memory_ranks=""
if [ "$shapes" = 1 ]; then
  memory_ranks="${MEMORY_RANKS-1 2 3}"
  memory_coarser="${MEMORY_COARSER:-1}"
  for v in $memory_ranks; do
    case "$v" in ''|*[!0-9]*|0) fail "MEMORY_RANKS must hold positive integers, not '$v'" ;; esac
  done
  case "$memory_coarser" in ''|*[!0-9]*) fail "MEMORY_COARSER must be a non-negative integer, not '$memory_coarser'" ;; esac
  if [ -n "${MEMORY_SCENES:-}" ]; then
    memory_scenes="$MEMORY_SCENES"
    for s in $memory_scenes; do [ -f "$repo/prm/$s.prm" ] || fail "no parameter file 'prm/$s.prm' (MEMORY_SCENES)"; done
  else
    # the first 2D and the first 3D scene of the study
    memory_scenes="$(for s in $scenes; do echo "$(dim_of "$s") $s"; done | awk '!seen[$1]++ { print $2 }' | tr '\n' ' ')"
  fi
fi
memory_runs=""
declare -A memory_of=()  # run: "scene cell ranks"
if [ -n "$memory_ranks" ]; then
  for scene in $memory_scenes; do
    dim="$(dim_of "$scene")"
    for cell in $cells; do
      # the study's k = 1 global run of this shape, less its last
      # MEMORY_COARSER cycles (a higher Initial global refinement would not
      # give its meshes where the scene has a pre-refinement band: the band
      # is refined after the global refinement)
      cycles=$(( $(cycles_of global 1 "$dim" "$cell") - memory_coarser ))
      [ "$cycles" -ge 1 ] || cycles=1
      for n in $memory_ranks; do
        run="memory_$(run_name "$scene" "$cell" global 1)_np$n"
        memory_runs="$memory_runs $run"
        memory_of[$run]="$scene $cell $n"
        out="$work/$run"
        if [ "${REUSE:-0}" = 1 ] && [ -s "$out/cycles.csv" ]; then continue; fi
        {
          if [ "$cell" = simplex ]; then printf 'subsection Geometry\n  set Cell type = simplex\nend\n'; fi
          printf 'subsection Discretization\n  set Polynomial degree = 1\nend\n'
          printf 'subsection Refinement\n  set Number of cycles = %s\n  set Strategy         = global\n  set Nested iteration = true\nend\n' "$cycles"
          printf 'subsection Output\n  set Directory    = %s\n  set Write vtu    = false\n  set Print timing = true\nend\n' "$out"
          scene_entries "$scene" "$cell"
          if [ -n "${EXTRA_PRM:-}" ]; then printf '%s\n' "$EXTRA_PRM"; fi
        } > "$work/$run.prm"
        run_scene "$run" "$scene" "$n" "$cycles" 1
        n_ran=$((n_ran + 1))
      done
    done
  done
fi
memory_runs="${memory_runs# }"

if [ -n "${start_all:-}" ]; then
  {
    echo "elapsed=$(( $(date +%s) - start_all ))"
    echo "load_after=\"$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')\""
    echo "n_ran=$n_ran"
  } >> "$meta"
fi
# what the runs found out about the machine (the file written above)
date_run='?' load_before='?' bin_date='?' load_after='' elapsed='' n_ran=''
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
  # the contact run on quadrilaterals of the highest degree, else the
  # quadrilateral run with the most DoFs, else the run with the most DoFs
  ref=""; best=0
  for run in $runs; do
    case "$run" in "${scene}"_*) ;; *) continue ;; esac
    d="$(last_value "$work/$run/cycles.csv" dofs)"
    case "$run" in
      "${scene}_contact_k"*) d=$((d + 1000000000 * (1 + ${run##*_k}))) ;;
      *_k[0-9]*) d=$((d + 500000000)) ;;
    esac
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
gp="$figures/$gp_name"
rm -f "$figures"/*.svg
# the curves of a figure, in the order of the legend: degree, cell shape,
# strategy, as run in 2D (in 3D some are not run; their styles stay unused)
combos=()
for k in $degrees; do
  for cell in $cells; do
    for strategy in $strategies; do
      if [ "$cell" = simplex ] && { [ "$strategy" != global ] || [ "$k" -gt "$(simplex_max_degree 2)" ]; }; then continue; fi
      combos+=("$cell $k $strategy")
    done
  done
done
# a run's label: "k = 1, global" on the degree page, "Q1, global" and
# "P1, global" on the shape page
run_label() {  # $1 cell shape, $2 degree, $3 strategy
  if [ "$shapes" = 0 ]; then echo "k = $2, $3"
  elif [ "$1" = simplex ]; then echo "P$2, $3"
  else echo "Q$2, $3"; fi
}
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
  local i=0 sep="plot" combo cell k strategy run
  for combo in "${combos[@]}"; do
    read -r cell k strategy <<< "$combo"
    i=$((i + 1))
    run="$(run_name "$1" "$cell" "$strategy" "$k")"
    case " $runs " in *" $run "*) ;; *) continue ;; esac
    printf '%s %s using "%s":(abs(column("%s")) > 0 ? abs(column("%s")) : NaN) with linespoints ls %d title "%s"' \
      "$sep" "'data/$run.csv'" "$2" "$3" "$3" "$i" "$(run_label "$cell" "$k" "$strategy")"
    sep=", \\"$'\n    '
  done
  printf '\n'
}
{
  echo "# Generated by benchmarks/work_precision_degree.sh on $date_run; run it in"
  echo "# doc/$figures_rel:  gnuplot $gp_name"
  if [ "$shapes" = 1 ]; then
    echo "# It reads data/<scene>_<strategy>_k<degree>.csv (quadrilaterals) and"
    echo "# data/<scene>_<strategy>_p<degree>.csv (simplices), cycles.csv of each run with"
  else
    echo "# It reads data/<scene>_<strategy>_k<degree>.csv (cycles.csv of each run with"
  fi
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
  # dashed with open points; simplices dash-dotted with open triangles
  i=0
  for combo in "${combos[@]}"; do
    read -r cell k strategy <<< "$combo"
    i=$((i + 1))
    case "$k" in 1) colour='#1f5fbf' ;; 2) colour='#2a9d3a' ;; *) colour='#c8302c' ;; esac
    case "$cell:$strategy" in simplex:*) dt=4; pt=8 ;; *:global) dt=2; pt=6 ;; *:kelly) dt=3; pt=8 ;; *) dt=1; pt=7 ;; esac
    echo "set style line $i lc rgb '$colour' lw 2 dt $dt pt $pt ps 1.2"
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
  if (cd "$figures" && gnuplot "$gp_name") > "$work/gnuplot.log" 2>&1; then
    say "wrote the figures in $figures"
  else
    echo "work_precision_degree: gnuplot failed; the tables are written without figures:" >&2
    cat "$work/gnuplot.log" >&2
    have_gnuplot=0
    figure_note="(gnuplot failed on this run; no figures.)"
  fi
else
  figure_note="(gnuplot was not installed when this page was generated; run \`cd doc/$figures_rel && gnuplot $gp_name\`.)"
fi

# ---- the page ----
invocation=""
for v in CELLS SCENES DEGREES STRATEGIES MAX_DOFS NP FIT_FROM MEMORY_RANKS MEMORY_SCENES MEMORY_COARSER MPIRUN_FLAGS; do
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
# the same for simplices: global refinement, at the degrees they are run at
simplex_cycles_text() {
  local k run_degrees=""
  for k in $degrees; do
    if [ "$k" -le "$(simplex_max_degree "$1")" ]; then run_degrees="$run_degrees $k"; fi
  done
  if [ -z "$run_degrees" ]; then printf 'none'; return; fi
  printf 'global %s (k = %s)' "$(for k in $run_degrees; do printf '%s, ' "$(cycles_of global "$k" "$1" simplex)"; done | sed 's/, $//')" "$(commas "$run_degrees")"
}
# a list "1 2 3" as "1, 2, 3"
commas() { echo "$*" | sed 's/^ *//; s/ *$//; s/  */, /g'; }
cores="$(nproc 2>/dev/null || echo '?')"
cpu="$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)"
n_runs=$(wc -w <<< "$runs")
n_memory=$(wc -w <<< "$memory_runs")

# the texts in which the shape page differs from the degree page
if [ "$shapes" = 1 ]; then
  case " $cells " in
    *" quadrilateral "*)
      title="Work and precision by element shape: simplices beside quadrilaterals"
      ref_text="the contact-refinement run on
  quadrilaterals of the highest degree (its last cycle; the same reference
  for both shapes)" ;;
    *)
      title="Work and precision by element shape: simplices"
      ref_text="the run with the most DoFs (no
  quadrilateral runs on this page; its last cycle)" ;;
  esac
  if [ -n "$n_ran" ] && [ "$n_ran" != "$((n_runs + n_memory))" ]; then
    run_time="Total run time of the $n_ran runs made (the others of the $n_runs runs and $n_memory memory runs reused from WORK): ${elapsed:-?} s."
  else
    run_time="Total run time of the $n_runs runs and the $n_memory memory runs: ${elapsed:-?} s."
  fi
  memory_text="
  On simplices every rank holds the whole mesh: see the section on the
  replicated mesh's memory at the end."
  data_text="Data: \`doc/$figures_rel/data/<scene>_<strategy>_k<degree>.csv\` (quadrilaterals) and
\`<scene>_<strategy>_p<degree>.csv\` (simplices), cycles.csv of each"
  cheapest_title="Which element, degree and refinement reach 1 % and 0.1 % cheapest"
  legend_text="Colour: degree (blue 1, green 2, red 3); quadrilaterals (Qk): solid lines and
filled points contact refinement, dashed lines and open points global
refinement; simplices (Pk): dash-dotted lines and open triangles, global
refinement."
else
  title="Work and precision by polynomial degree"
  run_time="Total run time of the $n_runs runs: ${elapsed:-?} s."
  ref_text="the contact-refinement run of the
  highest degree (its last cycle)"
  memory_text=""
  data_text="Data: \`doc/$figures_rel/data/<scene>_<strategy>_k<degree>.csv\` (cycles.csv of each"
  cheapest_title="Which degree and refinement reach 1 % and 0.1 % cheapest"
  legend_text="Colour: degree (blue k = 1, green k = 2, red k = 3); solid lines and filled
points: contact refinement; dashed lines and open points: global refinement."
fi
# the paragraph on what is run
study_text() {
  if [ "$shapes" = 0 ]; then
    cat <<EOF
Each scene is run with FE_Q(k) and a mapping of degree k, k = $(commas "$degrees"), each with the
refinement strategies $(commas "$strategies"), all with nested iteration (each mesh starts
from the solution of the one before) and \`Write vtu = false\`. The cycle counts
per degree keep the last mesh below MAX_DOFS = $max_dofs DoFs (FE_Q(2) has about 2^d and
FE_Q(3) about 3^d times the DoFs of FE_Q(1) on one mesh in d dimensions); cycles for
k = $(commas "$degrees"): $(cycles_text 2) in 2D; $(cycles_text 3) in 3D.
EOF
    return
  fi
  local with_quads=0 strategy_left="" degree_left_3="" p3_left="" item scene strategy k why
  case " $cells " in *" quadrilateral "*) with_quads=1 ;; esac
  echo "The element shapes side by side, on the scenes and with the error measures of"
  if [ "$with_quads" = 1 ]; then
    echo "[results_degree.md](results_degree.md): quadrilaterals (hexahedra in 3D) with"
    echo "FE_Q(k) and a mapping of degree k (*Qk*), and triangles (tetrahedra in 3D) with"
  else
    echo "[results_degree.md](results_degree.md): triangles (tetrahedra in 3D) with"
  fi
  echo "FE_SimplexP(k) mapped at degree k (*Pk*, [simplices.md](simplices.md)): each"
  echo "scene's built-in geometry made of simplices by \`Geometry/Cell type = simplex\`"
  echo "(the rectangle: each box into 2 triangles or 5 tetrahedra; the discs: each"
  echo "quadrilateral into 8 triangles, 3.2 to 3.4 times the DoFs of Q1 at P1 on the"
  echo "same refinement level), on a \`parallel::shared\` mesh that every rank holds whole."
  if [ "$with_quads" = 1 ]; then
    echo "Degrees k = $(commas "$degrees"); the refinement strategies $(commas "$strategies") on"
    echo "quadrilaterals, global refinement on simplices; all with nested iteration"
  else
    echo "Degrees k = $(commas "$degrees"), global refinement, nested iteration"
  fi
  echo "(each mesh starts from the previous mesh's solution) and \`Write vtu = false\`."
  echo "The cycle counts keep the last mesh below MAX_DOFS = $max_dofs DoFs; cycles:"
  if [ "$with_quads" = 1 ]; then
    echo "quadrilaterals $(cycles_text 2) (k = $(commas "$degrees")) in 2D, $(cycles_text 3) in 3D;"
  fi
  echo "simplices $(simplex_cycles_text 2) in 2D, $(simplex_cycles_text 3) in 3D."
  # what the program refuses on simplices, left out
  for item in $skipped; do
    IFS=: read -r scene strategy k why <<< "$item"
    if [ "$why" = strategy ]; then
      case " $strategy_left " in *" $strategy "*) ;; *) strategy_left="$strategy_left $strategy" ;; esac
    elif [ "$k" -ge 3 ]; then
      p3_left=1
    else
      degree_left_3=2
    fi
  done
  if [ -n "$skipped" ]; then
    echo
    echo "Not run on simplices (the program refuses them, doc/simplices.md):"
    echo
    if [ -n "$strategy_left" ]; then
      echo "- refinement $(commas "$strategy_left"): deal.II 9.4 has neither error estimators"
      echo "  nor coarsening on simplices, so global refinement is the only strategy there."
    fi
    if [ -n "$p3_left" ]; then
      echo "- k = 3: FE_SimplexP has degrees 1 and 2 only."
    fi
    if [ -n "$degree_left_3" ]; then
      echo "- k = 2 on tetrahedra: P2's vertex functions integrate to zero on a triangle"
      echo "  face, so the contact nodes at the vertices would get no weight m_s (with a"
      echo "  contact boundary, tetrahedra have degree 1 only)."
    fi
  fi
  return 0
}

# a constant of source/run_size.cc in bytes, "constexpr double <name> =
# <a> * <b> ...;" ('' if it is not there)
run_size_constant() {
  awk -v name="$1" '$0 ~ "constexpr double[ \t]+" name "[ \t]*=" {
      sub(/^[^=]*=/, ""); sub(/;.*/, ""); n = split($0, f, "*"); v = 1
      for (i = 1; i <= n; ++i) v *= f[i] + 0
      print v; exit }' "$repo/source/run_size.cc" 2>/dev/null || true
}
# The section on the memory of the replicated mesh: the memory runs' rows,
# what each further rank adds, and the run-size estimate beside them.
memory_section() {
  local run scene cell n dim table="$work/memory.table"
  echo
  echo "## Memory of the replicated mesh"
  echo
  if [ -z "$memory_runs" ]; then
    echo "Not measured on this page (MEMORY_RANKS is empty)."
    return 0
  fi
  cat <<EOF
Quadrilaterals and hexahedra are on a \`parallel::distributed\` mesh (p4est):
each rank holds its own cells and a layer of ghost cells. Simplices are on a
\`parallel::shared\` mesh: every rank holds the whole triangulation and the DoF
indices of every cell, so that part of the memory is paid once per rank. Each
scene below is run as the study's k = 1 global run of each shape less its last
$memory_coarser cycle(s) (MEMORY_COARSER; the cycles listed), so that its last mesh, the
largest, is one of the study's, on $(commas "$memory_ranks") MPI ranks (\`--oversubscribe\` beyond
the $cores cores). The figures are those of the last cycle. *memory*: \`memory_mb\`,
the peak resident memory (VmHWM) of each rank over the run, summed over the
ranks, 1 MB = 2^20 bytes; *per rank* that over the ranks, *per cell* and *per
DoF* that over the last mesh's cells and DoFs; *time*: \`time_total\`, all cycles. *estimate*: the run-size
check's formula of \`source/run_size.cc\` with the run's own cells and DoFs:
ranks x $(awk -v b="$(run_size_constant bytes_per_rank)" 'BEGIN { printf "%g", b / 1048576 }') MB + $(run_size_constant bytes_per_dof_2d) B (2D) or $(run_size_constant bytes_per_dof_3d) B (3D) per DoF, and on
simplices + ranks x cells x $(run_size_constant bytes_per_replicated_cell_2d) B per triangle or $(run_size_constant bytes_per_replicated_cell_3d) B per tetrahedron.
*added per rank*: the slope of a least-squares line of the memory against the
rank count: what each further rank costs (the program's fixed cost per rank,
and on simplices the replicated mesh). The replicated mesh per cell and rank is
the simplices' slope less that of the quadrilaterals of the same scene (their
fixed cost per rank and their ghost layers), over the simplices' cells (less
the estimate's fixed cost per rank where no quadrilateral runs were made).
EOF
  : > "$table"
  for run in $memory_runs; do
    read -r scene cell n <<< "${memory_of[$run]}"
    dim="$(dim_of "$scene")"
    # the last cycle's figures, and the number of cycles the run made
    echo "$scene $dim $cell $n $(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
      { v = $c["cells"] " " $c["dofs"] " " $c["memory_mb"] " " $c["time_total"] } END { print NR - 1, v }' "$work/$run/cycles.csv")" >> "$table"
  done
  awk -v per_rank="$(run_size_constant bytes_per_rank)" \
      -v dof2="$(run_size_constant bytes_per_dof_2d)" -v dof3="$(run_size_constant bytes_per_dof_3d)" \
      -v cell2="$(run_size_constant bytes_per_replicated_cell_2d)" -v cell3="$(run_size_constant bytes_per_replicated_cell_3d)" '
    function shape(cell, dim) { return (cell == "simplex") ? (dim == 3 ? "tetrahedra" : "triangles") : (dim == 3 ? "hexahedra" : "quadrilaterals") }
    function estimate(cell, dim, n, cells, dofs,    b) {
      if (per_rank == "" || dof2 == "" || dof3 == "" || cell2 == "" || cell3 == "") return ""
      b = n * per_rank + (dim == 3 ? dof3 : dof2) * dofs
      if (cell == "simplex") b += n * cells * (dim == 3 ? cell3 : cell2)
      return b / 1048576
    }
    {
      sc = $1; key = $1 SUBSEP $3
      if (!(sc in seen)) { seen[sc] = 1; scenes[++ns] = sc; dim[sc] = $2 }
      if (!(key in nrow)) { kinds[sc, ++nk[sc]] = $3 }
      r = ++nrow[key]
      np[key, r] = $4; ncycles[key] = $5; cells[key, r] = $6; dofs[key, r] = $7; mem[key, r] = $8; t[key, r] = $9
    }
    # least squares memory = a + b ranks: the slope b [MB]
    function slope(key,    i, n, sx, sy, sxx, sxy, d) {
      n = sx = sy = sxx = sxy = 0
      for (i = 1; i <= nrow[key]; ++i) { ++n; sx += np[key, i]; sy += mem[key, i]; sxx += np[key, i] ^ 2; sxy += np[key, i] * mem[key, i] }
      d = n * sxx - sx * sx
      return (n < 2 || d <= 0) ? "" : (n * sxy - sx * sy) / d
    }
    END {
      for (s = 1; s <= ns; ++s) {
        sc = scenes[s]; d = dim[sc]
        print ""
        printf "### %s\n\n", sc
        print "| shape | cycles | ranks | cells | DoFs | memory [MB] | per rank [MB] | per cell [kB] | per DoF [kB] | estimate [MB] | time [s] |"
        print "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        for (j = 1; j <= nk[sc]; ++j) {
          key = sc SUBSEP kinds[sc, j]
          for (i = 1; i <= nrow[key]; ++i) {
            e = estimate(kinds[sc, j], d, np[key, i], cells[key, i], dofs[key, i])
            printf "| %s | %d | %d | %d | %d | %.0f | %.0f | %.2f | %.2f | %s | %.1f |\n", shape(kinds[sc, j], d), ncycles[key],
              np[key, i], cells[key, i], dofs[key, i], mem[key, i], mem[key, i] / np[key, i],
              1024 * mem[key, i] / cells[key, i], 1024 * mem[key, i] / dofs[key, i],
              (e == "") ? "n/a" : sprintf("%.0f", e), t[key, i]
          }
        }
        # the slopes; the quadrilaterals of the scene, if any, as the base
        bq = ""
        for (j = 1; j <= nk[sc]; ++j) if (kinds[sc, j] == "quadrilateral") bq = slope(sc SUBSEP "quadrilateral")
        print ""
        print "| shape | cells | per rank on " nlist(sc) " ranks [MB] | added per rank [MB] | replicated mesh per cell and rank [B] | source/run_size.cc assumes |"
        print "|---|---:|---|---:|---:|---:|"
        for (j = 1; j <= nk[sc]; ++j) {
          kind = kinds[sc, j]; key = sc SUBSEP kind; b = slope(key); n = nrow[key]
          pr = ""
          for (i = 1; i <= n; ++i) pr = pr (i > 1 ? ", " : "") sprintf("%.0f", mem[key, i] / np[key, i])
          repl = "n/a"; assumed = "n/a"; rb[kind] = ""
          if (kind == "simplex") {
            assumed = ((d == 3) ? cell3 : cell2) " B"
            base = (bq != "") ? bq : ((per_rank != "") ? per_rank / 1048576 : "")
            if (b != "" && base != "") { rb[kind] = (b - base) * 1048576 / cells[key, n]; repl = sprintf("%.0f", rb[kind]) }
          } else if (per_rank != "") assumed = sprintf("%.0f MB per rank", per_rank / 1048576)
          printf "| %s | %d | %s | %s | %s | %s |\n", shape(kind, d), cells[key, n], pr,
            (b == "") ? "n/a" : sprintf("%.1f", b), repl, assumed
          first[kind] = mem[key, 1] / np[key, 1]; last[kind] = mem[key, n] / np[key, n]
          fn[kind] = np[key, 1]; ln[kind] = np[key, n]; slope_of[kind] = b; nc[kind] = cells[key, n]
        }
        print ""
        for (j = 1; j <= nk[sc]; ++j) {
          kind = kinds[sc, j]
          if (fn[kind] == ln[kind]) continue
          change = 100 * (last[kind] / first[kind] - 1)
          printf "%s: per rank %.0f MB on %d rank%s, %.0f MB on %d (%s %.0f %%)", toupper(substr(shape(kind, d), 1, 1)) substr(shape(kind, d), 2),
            first[kind], fn[kind], (fn[kind] == 1) ? "" : "s", last[kind], ln[kind], (change < 0) ? "falls by" : "grows by", (change < 0) ? -change : change
          if (slope_of[kind] != "")
            printf "; each further rank adds %.0f MB", slope_of[kind]
          if (kind == "simplex" && rb[kind] != "") {
            a = (d == 3) ? cell3 : cell2; cname = (d == 3) ? "tetrahedron" : "triangle"
            if (rb[kind] <= 0)
              printf ", no more than the fixed cost per rank: at %d cells the replicated mesh is not measurable (source/run_size.cc assumes %s B per %s)",
                nc[kind], a, cname
            else {
              printf ", of which the replicated mesh is about %.0f B per %s and rank (%.0f MB for the %d cells), against the %s B per %s that source/run_size.cc assumes: ",
                rb[kind], cname, rb[kind] * nc[kind] / 1048576, nc[kind], a, cname
              if (a >= rb[kind]) printf "the constant is %.1f times the measurement, an upper bound", a / rb[kind]
              else printf "the measurement is %.1f times the constant, which underestimates it", rb[kind] / a
            }
          } else if (kind != "simplex" && slope_of[kind] != "" && per_rank != "")
            printf " (the estimate assumes %.0f MB per rank)", per_rank / 1048576
          print "."
          print ""
        }
        above = total = 0
        for (j = 1; j <= nk[sc]; ++j) {
          key = sc SUBSEP kinds[sc, j]
          for (i = 1; i <= nrow[key]; ++i) {
            e = estimate(kinds[sc, j], d, np[key, i], cells[key, i], dofs[key, i])
            if (e == "") continue
            ++total; if (e >= mem[key, i]) ++above
          }
        }
        if (total > 0)
          printf "The run-size estimate is at or above the measured memory in %d of the %d runs (it is meant to bound the peak, so that the check refuses only what cannot fit).\n", above, total
      }
    }
    function nlist(sc,    j, key, i, out) {
      key = sc SUBSEP kinds[sc, 1]; out = ""
      for (i = 1; i <= nrow[key]; ++i) out = out (i > 1 ? ", " : "") np[key, i]
      return out
    }' "$table"
}

{
  cat <<EOF
# $title

Generated by \`$invocation\` on $date_run
(source tree at commit $commit; program \`$bin_shown\` built $bin_date).
Do not edit: re-run the script. The discussion at the end is kept in
\`doc/$discussion\`.

Machine: $cores cores${cpu:+ ($cpu)}; $np MPI ranks; the runs one after the other.
Load average (1, 5, 15 min) just before the runs: $load_before; just after: ${load_after:-?}
(other work on the machine inflates the wall times). $run_time

$(study_text)

What is measured, per cycle:

- *pressure error*: the relative L2 error of the contact pressure on Gamma_C
  against Hertz's (column \`pressure_error\` of cycles.csv);
- *pressure difference*: the relative L2 difference of the pressure from
  that of the scene's *reference run*, $ref_text: the nodal pressures l1 of both
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
  fixed cost of the program and its libraries, so it falls with the size).$memory_text

$data_text
run, with the columns \`pressure_difference\`, \`peak_difference\` and
\`energy_error\` added); figures: \`cd doc/$figures_rel && gnuplot $gp_name\`.
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
    if [ "$shapes" = 1 ]; then
      # the simplices' entries beyond the common ones
      extra="$( { printf 'subsection Geometry\n  set Cell type = simplex\nend\n'; scene_entries "$scene" simplex; } | awk '/^subsection/ { s = $2 } /set/ { sub(/^[ \t]*set[ \t]+/, ""); printf "%s<%s/%s>", sep, s, $0; sep = ", " }' | sed 's/ *= */ = /')"
      echo "On simplices: $extra."
      if scene_entries "$scene" simplex | grep -q 'Pre-refinement steps = 0'; then
        echo "The program refuses the scene's pre-refinement on tetrahedra (deal.II 9.4 has"
        echo "no hanging nodes on them; with it the run stops with exit status 6: \"The mesh"
        echo "is made of tetrahedra ..., and deal.II 9.4 has no hanging nodes on tetrahedra,"
        echo "which <Geometry/Pre-refinement steps> would make\"), so the tetrahedra are"
        echo "uniform where the hexahedra have a graded band toward the contact zone: the"
        echo "comparison of the shapes here includes that grading."
      fi
    fi
    echo "Reference run: \`${ref_run[$scene]}\`, last cycle, J_ref = $j_ref."
    echo
    echo "### Figures"
    echo
    if [ "$have_gnuplot" = 1 ]; then
      cat <<EOF
$legend_text

![$scene pressure vs DoFs]($figures_rel/${scene}_pressure_vs_dofs.svg)

![$scene pressure vs time]($figures_rel/${scene}_pressure_vs_time.svg)

![$scene energy vs DoFs]($figures_rel/${scene}_energy_vs_dofs.svg)

![$scene energy vs time]($figures_rel/${scene}_energy_vs_time.svg)

![$scene peak vs DoFs]($figures_rel/${scene}_peak_vs_dofs.svg)
EOF
    else
      echo "$figure_note"
    fi
    awk -F, -v fit_from="$fit_from" -v primary="$m" -v peakcol="$pk" -v max_dofs="$max_dofs" -v dim="$(dim_of "$scene")" \
        -v shapes="$shapes" -v cheapest_title="$cheapest_title" '
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
      function name(r) { return shapes ? (simplex[r] ? "P" : "Q") deg[r] ", " strat[r] : "k = " deg[r] ", " strat[r] }
      BEGIN { width = (dim == 3) ? "radius" : "half-width" }
      FNR == 1 {
        f = FILENAME; sub(/.*\//, "", f); sub(/\.csv$/, "", f)
        r = ++nrun
        # <scene>_<strategy>_k<k> (quadrilaterals), _p<k> (simplices)
        simplex[r] = (f ~ /_p[0-9]+$/)
        deg[r] = f; sub(/.*_[kp]/, "", deg[r])
        strat[r] = f; sub(/_[kp][0-9]+$/, "", strat[r]); sub(/.*_/, "", strat[r])
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
        print "### " cheapest_title
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

  if [ "$shapes" = 1 ]; then memory_section; fi

  echo
  echo "## Discussion"
  echo
  if [ -f "$doc/$discussion" ]; then cat "$doc/$discussion"; else echo "(written by hand after the run)"; fi
} > "$md"
say "wrote $md"
