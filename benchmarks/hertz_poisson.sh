# shellcheck shell=bash disable=SC2034,SC2154
# What benchmarks/locking_study.sh and benchmarks/mixed_solver_counts.sh
# share: the Hertz half disc of prm/hertz.prm (its geometry, mesh grading
# and load) run at any Poisson's ratio, against the closed-form pressure of
# that ratio. Each sources it after common.sh:
#
#   . "$benchmarks/hertz_poisson.sh"
#
# It needs
#   repo, benchmarks, bin   from common.sh
#   np          MPI ranks of every run
#   work        a folder of the script's own (each run writes work/<name>/)
#   log         the screen log that every run is appended to
#   time_limit  seconds a run may take (then it is stopped: exit status 124)
# It sets
#   scene       prm/hertz.prm
#   youngs, radius, traction, load
#               E, R, the pressure q on the flat top and P = 2 R q, read
#               from the scene
# and defines
#   hertz_exact NU [Q]
#               prints "a p0": Hertz's half-width and peak pressure at
#               Poisson's ratio NU under the pressure Q on the flat top
#               (default: the scene's), plane strain: P = 2 R Q,
#               E* = E / (1 - NU^2), a = sqrt(4 P R / (pi E*)),
#               p0 = 2 P / (pi a); the pressure is p0 sqrt(1 - x^2 / a^2).
#               When this file is sourced, the formula is checked against
#               the scene's own Exact solution at its own ratio (to 1e-9).
#   run_hertz NAME NU DEGREE FORMULATION CELLS REFINEMENT [--set ...]
#               runs the scene with Poisson's ratio NU, Discretization/
#               Polynomial degree = DEGREE, Material/Formulation =
#               FORMULATION, Geometry/Cell type = CELLS, Refinement/Initial
#               global refinement = REFINEMENT (then the scene's
#               pre-refinement), Refinement/Number of cycles = 1 (one
#               mesh), Output/Write vtu = false, Output/Print timing = true,
#               Output/Verbosity = quiet, Output/Directory = work/NAME, the
#               Exact solution entries of NU, and any further --set
#               arguments; appends the screen to the log under a heading
#               with the command; sets run_status (the exit status) and
#               run_wall (its wall time in s, start-up included). With
#               hertz_traction=Q set, under the pressure Q on the flat top
#               instead of the scene's; with hertz_cycles=C set, on C
#               meshes, each refined globally from the coarser one and
#               started from its solution (the program's nested iteration).
#   run_value NAME COLUMN   the value of COLUMN in work/NAME/cycles.csv
#               ('-' if the run wrote none or the column is absent)
#   step_range NAME   "min max" of the linear (CG or MINRES) iterations over
#               the Newton steps of the run that solved a system (rows
#               loop = newton of work/NAME/iterations.csv with
#               cg_iterations > 0), '- -' if there is none

scene="$repo/prm/hertz.prm"
scene_entry() {  # scene_entry 'Subsection/Entry': the scene's value
  awk -f "$benchmarks/prm_overrides.awk" "$scene" |
    awk -v want="$1" 'index($0, want "=") == 1 { v = substr($0, length(want) + 2) } END { print v }'
}
youngs="$(scene_entry "Material/Young's modulus")"
radius="$(scene_entry 'Geometry/Radius')"
# "1: 0; -q": the pressure on the flat top (boundary id 1)
traction="$(scene_entry 'Boundary conditions/Tractions' | awk -F';' '{ v = $NF; gsub(/[ \t]/, "", v); printf "%.17g\n", (v < 0) ? -v : v }')"
load="$(awk -v q="$traction" -v r="$radius" 'BEGIN { printf "%.17g", 2 * r * q }')"

hertz_exact() {
  awk -v nu="$1" -v e="$youngs" -v r="$radius" -v q="${2:-$traction}" 'BEGIN {
    pi = atan2(0, -1); estar = e / (1 - nu * nu); p = 2 * r * q
    a = sqrt(4 * p * r / (pi * estar)); printf "%.17g %.17g\n", a, 2 * p / (pi * a) }'
}

# The formula must give the scene's own exact values at the scene's ratio:
# else the scene is not the Hertz half disc this study assumes.
read -r _a _p0 <<< "$(hertz_exact "$(scene_entry "Material/Poisson's ratio")")"
if ! awk -v a="$_a" -v p0="$_p0" -v sa="$(scene_entry 'Exact solution/Contact half-width')" \
  -v sp="$(scene_entry 'Exact solution/Peak pressure')" \
  'BEGIN { d1 = (a - sa) / sa; d2 = (p0 - sp) / sp; exit !(d1 * d1 < 1e-18 && d2 * d2 < 1e-18) }'; then
  echo "$benchmark_name: prm/hertz.prm's Exact solution is not Hertz's a = $_a, p0 = $_p0 for its E, R and load" >&2
  exit 2
fi

run_hertz() {
  local name="$1" nu="$2" degree="$3" formulation="$4" cells="$5" refinement="$6"
  shift 6
  local a p0 a2 start arg
  local q="${hertz_traction:-$traction}"
  read -r a p0 <<< "$(hertz_exact "$nu" "$q")"
  a2="$(awk -v a="$a" 'BEGIN { printf "%.17g", a * a }')"
  local args=(--set "Boundary conditions/Tractions=1: 0; -$q"
    --set "Material/Poisson's ratio=$nu" --set "Material/Formulation=$formulation"
    --set "Geometry/Cell type=$cells" --set "Discretization/Polynomial degree=$degree"
    --set "Refinement/Initial global refinement=$refinement" --set "Refinement/Number of cycles=${hertz_cycles:-1}"
    --set "Output/Write vtu=false" --set "Output/Print timing=true" --set "Output/Verbosity=quiet"
    --set "Exact solution/Contact pressure=$p0 * sqrt(max(0, 1 - x^2 / $a2))"
    --set "Exact solution/Contact half-width=$a" --set "Exact solution/Peak pressure=$p0" "$@")
  {
    echo
    echo "==== $name: nu = $nu, degree $degree, $formulation, $cells, refinement $refinement, q = $q ===="
    printf 'mpirun -np %s %s prm/hertz.prm' "$np" "$bin_shown"
    for arg in "${args[@]}"; do [ "$arg" = --set ] || printf ' --set "%s"' "$arg"; done
    printf ' --set "Output/Directory=<temporary folder>/%s"\n' "$name"
  } >> "$log"
  start=$(date +%s.%N)
  run_status=0
  # shellcheck disable=SC2086
  timeout "$time_limit" mpirun ${MPIRUN_FLAGS:-} -np "$np" "$bin" "$scene" "${args[@]}" \
    --set "Output/Directory=$work/$name" > "$work/screen" 2>&1 || run_status=$?
  run_wall=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", e - s }')
  # the log goes into doc/: the work folder is named, not shown as a path
  awk -v t="$work" '{ while (t != "" && (i = index($0, t)) > 0) $0 = substr($0, 1, i - 1) "<temporary folder>" substr($0, i + length(t)); print }' \
    "$work/screen" >> "$log"
  echo "(exit status $run_status, $run_wall s)" >> "$log"
  echo "$benchmark_name: $name (nu = $nu): exit status $run_status, $run_wall s" >&2
}

run_value() {
  local csv="$work/$1/cycles.csv" v=""
  [ -s "$csv" ] && v="$(last_value "$csv" "$2")"
  printf '%s' "${v:--}"
}

step_range() {
  local csv="$work/$1/iterations.csv"
  if [ -s "$csv" ]; then
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
      $c["loop"] == "newton" && $c["cg_iterations"] > 0 {
        n = $c["cg_iterations"]; if (!k++ || n < lo) lo = n; if (n > hi) hi = n }
      END { if (k) print lo, hi; else print "- -" }' "$csv"
  else
    echo "- -"
  fi
}
