#!/usr/bin/env bash
# The locking study: the Hertz half disc of prm/hertz.prm at Poisson's
# ratios from 0.3 to 1/2, displacement elements against mixed
# (Taylor-Hood) ones on the same meshes. How far does each discretisation's
# contact pressure stray from Hertz's as nu -> 1/2, and what does each run
# cost?
#
#   bash benchmarks/locking_study.sh [ranks]
#
#   ranks  MPI ranks of every run (default 1)
#
# Runs prm/hertz.prm (its geometry, pre-refinement toward the contact zone
# and load) on one mesh each (Refinement/Number of cycles = 1, no nested
# iteration) at nu = 0.3, 0.45, 0.49, 0.499, 0.4999 and 0.5 (NUS) with
#   displacement Q1   Polynomial degree = 1, Formulation = displacement,
#                     Initial global refinement = R (REFINEMENT, default 4)
#   displacement Q1   the same at refinement R + 1: about the DoFs of the
#                     mixed Q2/Q1 run
#   displacement Q2   degree 2, displacement, refinement R
#   mixed Q2/Q1       degree 2, Formulation = mixed, refinement R
#   mixed P2/P1       degree 2, mixed, Geometry/Cell type = simplex,
#                     refinement R (each quadrilateral of the disc's coarse
#                     mesh becomes 8 triangles: about 4 times the DoFs of
#                     Q2/Q1 at the same refinement)
# each with Output/Write vtu = false, Output/Print timing = true,
# Output/Verbosity = quiet (one row per mesh and the summary) and the
# Exact solution entries (pressure, half-width, peak) of Hertz's closed
# form at that nu (benchmarks/hertz_poisson.sh). The displacement runs at
# nu = 0.5 are run too: the program refuses them (exit status 5), and the
# tables say so. A control tells nu from the size of the contact zone
# (Hertz's a is proportional to sqrt(1 - nu^2), so the zone's edge moves
# among the nodes as nu changes): mixed Q2/Q1 at nu0 = 0.3 under the
# pressure q (1 - nu^2) / (1 - nu0^2) on the flat top, which gives the a of
# each nu of the sweep. One more run counts the vertices of the triangle mesh
# (displacement P1 on it, nu = 0.3): the pressure of a Taylor-Hood pair
# has one DoF per vertex, so its DoFs are half the DoFs of displacement Q1
# (P1) on the same mesh.
# Writes
#   doc/benchmarks/locking_study.log   the screen of every run, each under
#                                      its command
#   doc/benchmarks/locking_study.md    the tables: errors (peak pressure,
#                                      half-width, pressure L2) against nu
#                                      per discretisation, then per run DoFs
#                                      (displacement, pressure), Newton
#                                      steps, CG or MINRES iterations (total,
#                                      per Newton step, fewest and most in a
#                                      step), AMG set-ups, wall time of the
#                                      solve, peak memory and kB per DoF;
#                                      the targets judged from them; the
#                                      control's errors beside mixed Q2/Q1's
#   doc/figures/locking_study.svg      peak-pressure and pressure L2 error
#                                      against nu (log scale in 1/2 - nu),
#                                      one curve per discretisation
#   doc/figures/locking_study.gp, doc/figures/data/locking_study.dat
#                                      its gnuplot script and data
#                                      (cd doc/figures && gnuplot
#                                      locking_study.gp)
# CHECK_NU (default 0.4999) is the ratio at which the mixed runs are judged
# against 1 % and Q1 at about their DoFs against them; TIME_LIMIT (default
# 900) stops a run after that many seconds (exit status 124 in the tables).
# About 5 minutes on 1 rank of a 2-core machine.
# The program is $DUALCONTACT if set, else <repository>/build/dualcontact;
# extra mpirun options in $MPIRUN_FLAGS. Works from any directory; needs
# bash, awk, mpirun, timeout, and gnuplot for the figure (without it the
# tables are still written).
set -euo pipefail
export LC_ALL=C

np="${1:-1}"
case "$np" in ''|*[!0-9]*|0) echo "locking_study: ranks must be a positive integer, not '$np'" >&2; exit 2 ;; esac
if [ $# -gt 1 ]; then
  echo "locking_study: usage: bash benchmarks/locking_study.sh [ranks]" >&2
  exit 2
fi

# benchmarks, repo, doc, bin, bin_shown, repo_path, last_value
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" locking_study

nus="${NUS:-0.3 0.45 0.49 0.499 0.4999 0.5}"
refinement="${REFINEMENT:-4}"
check_nu="${CHECK_NU:-0.4999}"
time_limit="${TIME_LIMIT:-900}"
for v in "$refinement" "$time_limit"; do
  case "$v" in ''|*[!0-9]*) echo "locking_study: REFINEMENT and TIME_LIMIT must be integers, not '$v'" >&2; exit 2 ;; esac
done
for nu in $nus $check_nu; do
  if ! awk -v nu="$nu" 'BEGIN { exit !(nu ~ /^[0-9.]+$/ && nu >= 0 && nu <= 0.5) }'; then
    echo "locking_study: Poisson's ratios (NUS, CHECK_NU) must lie in [0, 0.5], not '$nu'" >&2
    exit 2
  fi
done
fine=$((refinement + 1))

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# ranks waiting for a rank that is not scheduled must not hold a core
export OMPI_MCA_hwloc_base_binding_policy="${OMPI_MCA_hwloc_base_binding_policy:-none}"
export OMPI_MCA_mpi_yield_when_idle="${OMPI_MCA_mpi_yield_when_idle:-1}"

work="$(mktemp -d "${TMPDIR:-/tmp}/locking_study.XXXXXX")"
trap 'rm -rf -- "$work"' EXIT
log="$doc/benchmarks/locking_study.log"
md="$doc/benchmarks/locking_study.md"
figures="$doc/figures"
mkdir -p "$doc/benchmarks" "$figures/data"

# scene, youngs, radius, traction, load, hertz_exact, run_hertz, run_value,
# step_range
. "$benchmarks/hertz_poisson.sh"

# The discretisations: key, then degree, formulation, cell type, refinement
# and the name the tables give it.
discs="q1 q1fine q2 q2q1 p2p1"
disc_spec() {
  case "$1" in
    q1) echo "1 displacement quadrilateral $refinement" ;;
    q1fine) echo "1 displacement quadrilateral $fine" ;;
    q2) echo "2 displacement quadrilateral $refinement" ;;
    q2q1) echo "2 mixed quadrilateral $refinement" ;;
    p2p1) echo "2 mixed simplex $refinement" ;;
  esac
}
disc_name() {
  case "$1" in
    q1) echo "displacement Q1" ;;
    q1fine) echo "displacement Q1, refinement $fine" ;;
    q2) echo "displacement Q2" ;;
    q2q1) echo "mixed Q2/Q1" ;;
    p2p1) echo "mixed P2/P1" ;;
  esac
}

invocation=""
for v in NUS REFINEMENT CHECK_NU TIME_LIMIT MPIRUN_FLAGS; do
  if [ -n "${!v:-}" ]; then
    case "${!v}" in *[[:space:]]*) invocation="$invocation$v=\"${!v}\" " ;; *) invocation="$invocation$v=${!v} " ;; esac
  fi
done
if [ -n "${DUALCONTACT:-}" ]; then invocation="${invocation}DUALCONTACT=$bin_shown "; fi
invocation="${invocation}bash benchmarks/locking_study.sh $np"
date_run="$(date -u '+%Y-%m-%d %H:%M UTC')"
cores="$(nproc 2>/dev/null || echo '?')"
cpu="$(awk -F': *' '/^model name/ {print $2; exit}' /proc/cpuinfo 2>/dev/null || true)"
mem_gb="$(awk '/^MemTotal/ {printf "%.0f", $2 / 1048576}' /proc/meminfo 2>/dev/null || true)"
load_before="$(cut -d" " -f1-3 /proc/loadavg 2>/dev/null || echo "?")"
bin_date="$(date -u -r "$bin" '+%Y-%m-%d %H:%M UTC' 2>/dev/null || echo "?")"
commit="$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git -C "$repo" status --porcelain --untracked-files=no -- source include CMakeLists.txt 2>/dev/null)" ]; then
  commit="$commit (with local changes to the code)"
fi

{
  echo "# The screen of every run of $invocation"
  echo "# on $date_run, source tree at commit $commit, program $bin_shown built $bin_date."
  echo "# <temporary folder> stands for the script's work folder."
} > "$log"
echo "locking_study: $np rank(s), nu = $nus; log in $(repo_path "$log")" >&2
start_all=$(date +%s)

rows="$work/rows"
: > "$rows"
for key in $discs; do
  read -r degree formulation cells mesh <<< "$(disc_spec "$key")"
  for nu in $nus; do
    name="${key}_nu$nu"
    run_hertz "$name" "$nu" "$degree" "$formulation" "$cells" "$mesh"
    read -r lo hi <<< "$(step_range "$name")"
    echo "$key $nu $run_status $(run_value "$name" dofs) $(run_value "$name" cells)" \
      "$(run_value "$name" newton_steps) $(run_value "$name" linear_iterations)" \
      "$(run_value "$name" amg_setups) $lo $hi $(run_value "$name" peak_pressure_error)" \
      "$(run_value "$name" half_width_error) $(run_value "$name" pressure_error)" \
      "$(run_value "$name" time_solve) $run_wall $(run_value "$name" memory_mb)" >> "$rows"
  done
done
# The control: is it nu that moves the mixed errors, or the size of the
# contact zone (its edge against the nodes: a changes by 9 % from nu = 0.3
# to 1/2)? Mixed Q2/Q1 at nu0 = 0.3 under the pressure q (1 - nu^2) /
# (1 - nu0^2), which gives Hertz's a of nu at nu0.
control="$work/control"
: > "$control"
control_nu=0.3
for nu in $nus; do
  [ "$nu" = "$control_nu" ] && continue
  read -r degree formulation cells mesh <<< "$(disc_spec q2q1)"
  hertz_traction="$(awk -v q="$traction" -v nu="$nu" -v n0="$control_nu" 'BEGIN { printf "%.17g", q * (1 - nu * nu) / (1 - n0 * n0) }')"
  run_hertz "control_a_nu$nu" "$control_nu" "$degree" "$formulation" "$cells" "$mesh"
  read -r a _ <<< "$(hertz_exact "$control_nu" "$hertz_traction")"
  echo "$nu $hertz_traction $a $run_status $(run_value "control_a_nu$nu" peak_pressure_error)" \
    "$(run_value "control_a_nu$nu" half_width_error) $(run_value "control_a_nu$nu" pressure_error)" >> "$control"
  unset hertz_traction
done

# The vertices of the meshes, for the pressure DoFs: displacement Q1 (P1)
# has two DoFs per vertex, the Taylor-Hood pressure one.
pressure_quads=-
for nu in $nus; do
  d="$(run_value "q1_nu$nu" dofs)"
  if [ "$d" != - ]; then pressure_quads=$((d / 2)); break; fi
done
run_hertz count_p1 0.3 1 displacement simplex "$refinement"
pressure_triangles=-
d="$(run_value count_p1 dofs)"
[ "$d" = - ] || pressure_triangles=$((d / 2))
elapsed=$(( $(date +%s) - start_all ))
load_after="$(cut -d" " -f1-3 /proc/loadavg 2>/dev/null || echo "?")"

# ---------------------------------------------------------------- figure
data="$figures/data/locking_study.dat"
gp="$figures/locking_study.gp"
{
  echo "# Generated by $invocation on $date_run."
  echo "# One block per discretisation (gnuplot's index 0, 1, ...), one line per run that"
  echo "# converged: nu, x = 1/2 - nu (1e-5 stands for nu = 1/2), |peak pressure error|,"
  echo "# pressure L2 error, |half-width error|, displacement DoFs (relative errors)."
  for key in $discs; do
    echo "# $(disc_name "$key")"
    awk -v key="$key" '$1 == key && $3 == 0 && $11 != "-" {
      x = 0.5 - $2; if (x < 1e-12) x = 1e-5
      printf "%s %.6g %.6e %.6e %.6e %s\n", $2, x, ($11 < 0) ? -$11 : $11, $13, ($12 < 0) ? -$12 : $12, $4 }' "$rows"
    printf '\n\n'
  done
} > "$data"
{
  cat <<EOF
# Generated by benchmarks/locking_study.sh on $date_run; run it in doc/figures:
#   cd doc/figures && gnuplot locking_study.gp
# It reads data/locking_study.dat (one block per discretisation).
set terminal svg size 1100,600 dynamic noenhanced font 'Helvetica,13' background rgb 'white'
set output 'locking_study.svg'
set logscale xy
# nu grows to the right; nu = 1/2 is drawn one decade beyond 1/2 - nu = 1e-4
set xrange [0.35:5e-6]
set xtics ("0.3" 0.2, "0.45" 0.05, "0.49" 0.01, "0.499" 1e-3, "0.4999" 1e-4, "0.5" 1e-5)
set format y '%g'
set grid xtics ytics mytics lc rgb '#dddddd'
set xlabel "Poisson's ratio nu (log scale in 1/2 - nu)"
set style line 1 lc rgb '#c8302c' lw 2 dt 1 pt 7 ps 1.0
set style line 2 lc rgb '#c8302c' lw 2 dt 2 pt 6 ps 1.3
set style line 3 lc rgb '#e08a1e' lw 2 dt 1 pt 5 ps 1.0
set style line 4 lc rgb '#1f5fbf' lw 2 dt 1 pt 9 ps 1.2
set style line 5 lc rgb '#2a9d3a' lw 2 dt 1 pt 13 ps 1.2
set multiplot layout 1,2 margins 0.08,0.98,0.27,0.88 spacing 0.09 title "Hertz half disc (prm/hertz.prm), one mesh per discretisation: error against Hertz as nu -> 1/2"
# one key for both panels, below them
set key at screen 0.53,0.085 center center vertical maxrows 3 box opaque samplen 3
EOF
  for panel in peak l2; do
    if [ "$panel" = peak ]; then
      echo "set title 'peak pressure: |max l1 / p0 - 1|'"
      echo "set ylabel 'relative error of the peak pressure [-]'"
      column=3
    else
      echo "unset key"
      echo "set title 'contact pressure: relative L2 error on Gamma_C'"
      echo "set ylabel 'relative L2 error of the pressure [-]'"
      column=4
    fi
    printf 'plot '
    i=0
    for key in $discs; do
      [ "$i" -gt 0 ] && printf ', \\\n     '
      label="$(disc_name "$key")"
      d="$(awk -v k="$key" '$1 == k && $3 == 0 && $4 != "-" { print $4; exit }' "$rows")"
      case "$key" in q2q1) d="$d + $pressure_quads" ;; p2p1) d="$d + $pressure_triangles" ;; esac
      printf "'data/locking_study.dat' index %d using 2:%d with linespoints ls %d title \"%s (%s DoFs)\"" \
        "$i" "$column" "$((i + 1))" "$label" "${d:--}"
      i=$((i + 1))
    done
    printf '\n'
  done
  echo "unset multiplot"
} > "$gp"
figure_note=""
if command -v gnuplot > /dev/null 2>&1; then
  if ! (cd "$figures" && gnuplot locking_study.gp) > "$work/gnuplot.log" 2>&1; then
    cat "$work/gnuplot.log" >&2
    figure_note=" (gnuplot failed on this run: no figure)"
  fi
else
  figure_note=" (gnuplot was not installed: run \`cd doc/figures && gnuplot locking_study.gp\`)"
fi

# ---------------------------------------------------------------- page
exact_rows="$(for nu in $nus; do read -r a p0 <<< "$(hertz_exact "$nu")"; printf '| %s | %.6f | %.4f |\n' "$nu" "$a" "$p0"; done)"
cells_quads="$(awk -v k=q1 '$1 == k && $5 != "-" { print $5; exit }' "$rows")"
cells_fine="$(awk -v k=q1fine '$1 == k && $5 != "-" { print $5; exit }' "$rows")"
cells_triangles="$(awk -v k=p2p1 '$1 == k && $5 != "-" { print $5; exit }' "$rows")"
[ -n "$cells_triangles" ] || cells_triangles="$(run_value count_p1 cells)"
{
  cat <<EOF
# Locking study: the Hertz half disc from nu = 0.3 to 1/2

Generated by \`$invocation\` on $date_run; source tree at commit $commit,
program \`$bin_shown\` built $bin_date. What the figures show:
[locking.md](../locking.md).

**Scene.** \`prm/hertz.prm\`'s half disc (R = $radius, E = $youngs, plane strain),
pressed on the rigid plane by q = $(printf '%.6g' "$traction") on its flat top (P = 2 R q =
$(printf '%.6g' "$load") per unit thickness), frictionless, at each Poisson's ratio nu with
Hertz's closed form of that nu as \`Exact solution\`: E* = E / (1 - nu^2),
a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), p(x) = p0 sqrt(1 - x^2 / a^2)
(\`benchmarks/hertz_poisson.sh\`):

| nu | a | p0 |
|---:|---:|---:|
$exact_rows

**Meshes.** One mesh per run (\`Refinement/Number of cycles = 1\`: no
nested iteration), the scene's pre-refinement toward the contact zone
(4 steps within 0.05, grading 0.6) after \`Initial global refinement\` =
$refinement: $cells_quads quadrilaterals for Q1, Q2 and Q2/Q1, $cells_triangles triangles
for P2/P1 (each cell of the disc's coarse mesh made 8 triangles), and
$cells_fine quadrilaterals at refinement $fine for the second Q1 run, which has
about the DoFs of Q2/Q1. DoFs are the displacement's (the program's
\`dofs\`); the pressure of a Taylor-Hood pair has one DoF per vertex,
$pressure_quads on the quadrilaterals and $pressure_triangles on the triangles (half the DoFs of
displacement Q1 and P1 on the same mesh; the P1 run only counts them).

Machine: $cores cores${cpu:+ ($cpu)}${mem_gb:+, $mem_gb GB}, shared with
other work while this ran: load average (1, 5, 15 min) $load_before at the start and
$load_after at the end. The times are therefore not quiet-machine figures; the
errors and the counts are the results. $np MPI rank(s) per run. Total run
time of the script: $elapsed s. Screen log: \`doc/benchmarks/locking_study.log\`.

Errors are relative, signed (computed minus Hertz, over Hertz): peak =
max l1 / p0 - 1, half-width = the zone's edges extrapolated from the
square-root pressure against a, L2 = the relative L2 error of the pressure
on Gamma_C. "refused": the program stops with exit status 5 at nu = 1/2 with
displacement elements (lambda is infinite).

![peak-pressure and L2 error against nu](../figures/locking_study.svg)

\`doc/figures/locking_study.svg\`${figure_note}; data \`doc/figures/data/locking_study.dat\`.
EOF
  awk -v discs="$discs" -v nus="$nus" -v pq="$pressure_quads" -v pt="$pressure_triangles" \
    -v check="$check_nu" -v fine="$fine" -v names="$(for k in $discs; do printf '%s|' "$(disc_name "$k")"; done)" '
    # signed errors with their sign, the L2 norm without
    function pct(v) { return (v == "-") ? "-" : sprintf("%+.3g %%", 100 * v) }
    function pct_abs(v) { return (v == "-") ? "-" : sprintf("%.3g %%", 100 * v) }
    function cell(k, nu, col) {
      if (!((k, nu) in st)) return "-"
      if (st[k, nu] == 5 && dof[k, nu] == "-") return "refused"
      if (st[k, nu] != 0) return "failed (exit " st[k, nu] ")"
      return (col == "l2") ? pct_abs(val[k, nu, col]) : pct(val[k, nu, col])
    }
    function abs(v) { return (v < 0) ? -v : v }
    function pdofs(k) { return (k == "q2q1") ? pq : (k == "p2p1") ? pt : "" }
    {
      k = $1; nu = $2; st[k, nu] = $3; dof[k, nu] = $4; nw[k, nu] = $6; lin[k, nu] = $7
      amg[k, nu] = $8; lo[k, nu] = $9; hi[k, nu] = $10
      val[k, nu, "peak"] = $11; val[k, nu, "hw"] = $12; val[k, nu, "l2"] = $13
      ts[k, nu] = $14; wall[k, nu] = $15; mem[k, nu] = $16
    }
    END {
      nk = split(discs, K, " "); nn = split(nus, N, " "); split(names, NAME, "|")
      for (i = 1; i <= nk; ++i) {
        label[K[i]] = NAME[i]
        for (j = 1; j <= nn; ++j) if (st[K[i], N[j]] == 0 && dof[K[i], N[j]] != "-") { d[K[i]] = dof[K[i], N[j]]; break }
      }
      head = "| nu |"; rule = "|---:|"
      for (i = 1; i <= nk; ++i) {
        head = head " " label[K[i]] " (" d[K[i]] (pdofs(K[i]) != "" ? " + " pdofs(K[i]) : "") ") |"; rule = rule "---:|"
      }
      split("peak hw l2", C, " ")
      title["peak"] = "Peak pressure error"; title["hw"] = "Half-width error"; title["l2"] = "Pressure L2 error"
      for (c = 1; c <= 3; ++c) {
        printf "\n## %s\n\nColumns: the discretisation (displacement DoFs, + pressure DoFs).\n\n%s\n%s\n", title[C[c]], head, rule
        for (j = 1; j <= nn; ++j) {
          line = "| " N[j] " |"
          for (i = 1; i <= nk; ++i) line = line " " cell(K[i], N[j], C[c]) " |"
          print line
        }
      }

      print "\n## Each run\n"
      print "DoFs u, p: displacement and pressure DoFs; Newton: Newton steps (each one linear solve); linear: CG"
      print "iterations (displacement) or MINRES iterations (mixed) summed over the solve, per Newton step,"
      print "and the fewest and most of one Newton step; AMG: set-ups; solve: wall time of the contact solve"
      print "[s] (`time_solve`), run: of the whole run with start-up; memory: peak resident memory of all"
      print "ranks [MB] (`memory_mb`, the start-up cost included), per displacement DoF and per DoF of"
      print "both fields [kB]."
      print ""
      print "| discretisation | nu | exit | DoFs u | DoFs p | peak | half-width | L2 | Newton | linear | per Newton | fewest, most | AMG | solve [s] | run [s] | memory [MB] | kB/DoF u | kB/DoF u+p |"
      print "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
      for (i = 1; i <= nk; ++i) for (j = 1; j <= nn; ++j) {
        k = K[i]; nu = N[j]
        if (!((k, nu) in st)) continue
        if (dof[k, nu] == "-") {
          printf "| %s | %s | %s | %s |%s\n", label[k], nu, st[k, nu], (st[k, nu] == 5) ? "refused" : "failed", " - | - | - | - | - | - | - | - | - | - | - | - | - | - |"
          continue
        }
        p = pdofs(k); tot = dof[k, nu] + ((p != "" && p != "-") ? p : 0)
        printf "| %s | %s | %s | %d | %s | %s | %s | %s | %d | %d | %.1f | %s, %s | %d | %.2f | %.1f | %.0f | %.2f | %s |\n", \
          label[k], nu, st[k, nu], dof[k, nu], (p == "") ? "-" : p, pct(val[k, nu, "peak"]), pct(val[k, nu, "hw"]), pct_abs(val[k, nu, "l2"]), \
          nw[k, nu], lin[k, nu], (nw[k, nu] > 0) ? lin[k, nu] / nw[k, nu] : 0, lo[k, nu], hi[k, nu], amg[k, nu], ts[k, nu], wall[k, nu], \
          mem[k, nu], 1024 * mem[k, nu] / dof[k, nu], (p == "") ? "-" : sprintf("%.2f", 1024 * mem[k, nu] / tot)
      }

      print "\n## The targets\n"
      # the mixed error independent of nu: max / min over the sweep
      for (i = 1; i <= nk; ++i) {
        k = K[i]; if (pdofs(k) == "") continue
        split("peak l2", E, " ")
        for (e = 1; e <= 2; ++e) {
          n = 0; lo_v = 0; hi_v = 0
          for (j = 1; j <= nn; ++j) if (st[k, N[j]] == 0 && val[k, N[j], E[e]] != "-") {
            v = abs(val[k, N[j], E[e]])
            if (!n++ || v < lo_v) { lo_v = v; lo_nu = N[j] }; if (v > hi_v) { hi_v = v; hi_nu = N[j] }
          }
          if (n < 2 || lo_v <= 0) { printf "- %s, %s error: not judged (%d runs converged).\n", label[k], E[e] == "peak" ? "peak-pressure" : "L2", n; continue }
          f = hi_v / lo_v
          printf "- **\"The mixed error is independent of nu within a factor 1.5\", %s, %s error: %s**: max / min = %.3g %% (nu = %s) / %.3g %% (nu = %s) = **%.2f** over %d ratios.\n", \
            label[k], (E[e] == "peak") ? "peak-pressure" : "L2", (f <= 1.5) ? "met" : "not met", 100 * hi_v, hi_nu, 100 * lo_v, lo_nu, f, n
        }
      }
      # at the check ratio: mixed within 1 % at <= 1e5 DoFs, Q1 at about the same DoFs off by more
      if (!(("q2q1", check) in st)) { print "- At nu = " check ": not judged (not in the sweep)."; exit }
      for (i = 1; i <= nk; ++i) {
        k = K[i]; p = pdofs(k); if (p == "") continue
        if (st[k, check] != 0) { printf "- **%s at nu = %s: not met**: the run failed (exit status %s).\n", label[k], check, st[k, check]; continue }
        tot = dof[k, check] + p; worst = abs(val[k, check, "peak"]); if (abs(val[k, check, "hw"]) > worst) worst = abs(val[k, check, "hw"])
        if (val[k, check, "l2"] > worst) worst = val[k, check, "l2"]
        printf "- **\"%s within 1 %% at <= 1e5 DoFs at nu = %s\": %s**: %d DoFs (%d + %d), peak %s, half-width %s, L2 %s.\n", \
          label[k], check, (worst <= 0.01 && tot <= 1e5) ? "met" : "not met", tot, dof[k, check], p, pct(val[k, check, "peak"]), pct(val[k, check, "hw"]), pct_abs(val[k, check, "l2"])
      }
      k = "q1fine"
      if (st[k, check] == 0 && st["q2q1", check] == 0) {
        q = abs(val[k, check, "peak"]); m = abs(val["q2q1", check, "peak"])
        printf "- **\"Q1 at the same DoFs is off by more\" (nu = %s): %s**: displacement Q1 at refinement %d, %d DoFs against mixed Q2/Q1 with %d + %d: peak %s against %s, half-width %s against %s, L2 %s against %s.\n", \
          check, (q > 0.01 && q > m) ? "met" : "not met", fine, dof[k, check], dof["q2q1", check], pq, \
          pct(val[k, check, "peak"]), pct(val["q2q1", check, "peak"]), pct(val[k, check, "hw"]), pct(val["q2q1", check, "hw"]), \
          pct_abs(val[k, check, "l2"]), pct_abs(val["q2q1", check, "l2"])
      } else print "- Q1 at the same DoFs at nu = " check ": not judged (a run failed)."
    }' "$rows"
  cat <<EOF

## Mixed Q2/Q1: nu, or the size of the contact zone?

Hertz's half-width a shrinks by 9 % from nu = 0.3 to 1/2 (a is
proportional to sqrt(1 - nu^2)), so the zone's edge, where the pressure's
derivative is singular, sits at a different place among the nodes at each
nu. The control runs mixed Q2/Q1 at
nu0 = $control_nu on the same mesh under the pressure q (1 - nu^2) / (1 - nu0^2),
which gives the a of each nu: an error that follows the control is set by
a, not by nu.

| nu | a | q of the control | at nu: peak | half-width | L2 | at nu0 = $control_nu, same a: peak | half-width | L2 | L2 at nu / L2 of the control |
|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
EOF
  awk -v nus="$nus" -v n0="$control_nu" -v traction="$traction" -v e="$youngs" -v rr="$radius" '
    FNR == 1 { ++file }
    file == 1 && $1 == "q2q1" { st[$2] = $3; pk[$2] = $11; hw[$2] = $12; l2[$2] = $13; next }
    file == 2 { cq[$1] = $2; ca[$1] = $3; cst[$1] = $4; cpk[$1] = $5; chw[$1] = $6; cl2[$1] = $7 }
    END {
      nn = split(nus, N, " ")
      # nu0 is its own control
      if (n0 in st) { cq[n0] = traction; cst[n0] = st[n0]; cpk[n0] = pk[n0]; chw[n0] = hw[n0]; cl2[n0] = l2[n0] }
      for (j = 1; j <= nn; ++j) {
        nu = N[j]
        if (st[nu] != 0 || cst[nu] != 0 || l2[nu] == "-" || cl2[nu] == "-") { printf "| %s | - | - | failed | | | | | | |\n", nu; continue }
        r = l2[nu] / cl2[nu]
        if (!n++ || r < lo) lo = r; if (r > hi) hi = r
        printf "| %s | %.6f | %.6g | %+.3g %% | %+.3g %% | %.3g %% | %+.3g %% | %+.3g %% | %.3g %% | %.2f |\n", nu, \
          sqrt(8 * traction * rr * rr * (1 - nu * nu) / (atan2(0, -1) * e)), \
          cq[nu], 100 * pk[nu], 100 * hw[nu], 100 * l2[nu], 100 * cpk[nu], 100 * chw[nu], 100 * cl2[nu], r
      }
      if (n >= 2) printf "\nThe L2 error at each nu over the control'"'"'s with the same a: from %.2f to %.2f, a factor %.2f.\n", lo, hi, hi / lo
    }' "$rows" "$control"
} > "$md"

echo "locking_study: wrote $(repo_path "$md"), $(repo_path "$log") and $(repo_path "$figures/locking_study.svg") in $elapsed s" >&2
