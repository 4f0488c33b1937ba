#!/usr/bin/env bash
# The Hertz benchmark: cost of a contact solve against one linear
# elasticity solve on the same mesh, on meshes up to >= 1e6 DoFs.
#
#   bash benchmarks/benchmark_hertz.sh [ranks] [cycles]
#
#   ranks   number of MPI ranks (default 2)
#   cycles  number of refinement cycles (default 5: cycle 0 has ~5e3 DoFs,
#           each cycle multiplies them by ~4, so cycle 4 has ~1.25e6)
#
# SCENE=<name> runs prm/<name>.prm instead of prm/hertz.prm, TAG=<tag>
# names the files doc/benchmarks/benchmark_<tag>.{log,md}, TARGET=<r> is the
# ratio to judge against (default 10), EXTRA_PRM adds entries to the
# parameter file.
# Runs prm/hertz.prm (or the SCENE) with these entries overridden:
#   Refinement/Number of cycles = <cycles>, Output/Write vtu = false,
#   Output/Directory = a temporary folder,
#   Solver/Time a reference linear solve = true.
# Writes doc/benchmarks/benchmark_<tag>.log (the screen output) and
# doc/benchmarks/benchmark_<tag>.md (the table built from cycles.csv). The
# page describes the scene as it was run (friction law, F, threshold
# iteration, nested iteration or cold starts), read from the parameter file
# after the overrides and EXTRA_PRM, with the program's defaults
# (--print-parameters) for the entries it leaves out. Paths written into
# doc/ are relative to the repository root; the temporary folder appears as
# <temporary folder>.
# The program is $DUALCONTACT if set, else <repository>/build/dualcontact.
# KEEP_OUTPUT=1 keeps the temporary output folder (cycles.csv, iterations.csv
# with every Newton step: CG iterations, AMG set-ups, step length, time).
# Extra mpirun options (e.g. --oversubscribe) may be given in $MPIRUN_FLAGS.
# Works from any directory; needs bash, awk and mpirun only.
set -euo pipefail
export LC_ALL=C

np="${1:-2}"
cycles="${2:-5}"
case "$np" in ''|*[!0-9]*|0) echo "benchmark_hertz: ranks must be a positive integer, not '$np'" >&2; exit 2 ;; esac
case "$cycles" in ''|*[!0-9]*|0) echo "benchmark_hertz: cycles must be a positive integer, not '$cycles'" >&2; exit 2 ;; esac

# benchmarks, repo, doc, bin, bin_shown, repo_path
. "$(dirname "${BASH_SOURCE[0]}")/common.sh" benchmark_hertz

scene="${SCENE:-hertz}"              # prm/<scene>.prm
tag="${TAG:-$scene}"                  # names doc/benchmarks/benchmark_<tag>.{log,md}
target="${TARGET:-10}"                # the ratio to judge against
if [ ! -f "$repo/prm/$scene.prm" ]; then
  echo "benchmark_hertz: no parameter file 'prm/$scene.prm' (SCENE=$scene)" >&2
  exit 2
fi
log="$doc/benchmarks/benchmark_${tag}.log"
md="$doc/benchmarks/benchmark_${tag}.md"

tmp="$(mktemp -d "${TMPDIR:-/tmp}/benchmark_hertz.XXXXXX")"
if [ "${KEEP_OUTPUT:-0}" = 1 ]; then
  echo "benchmark_hertz: keeping the output (cycles.csv, iterations.csv) in $tmp/output"
else
  trap 'rm -rf "$tmp"' EXIT
fi
prm="$tmp/hertz_benchmark.prm"
out="$tmp/output"

# The overrides go to the program as --set arguments (the scene may set the
# same entries, and a second 'set' in one file is an input error); the scene
# with the overrides appended is what prm_value below reads (later 'set'
# lines win there).
overrides="$tmp/overrides.prm"
cat > "$overrides" <<EOF

# ---- overrides of benchmarks/benchmark_hertz.sh ----
subsection Refinement
  set Number of cycles = $cycles
end

subsection Output
  set Directory = $out
  set Write vtu = false
end

subsection Solver
  set Time a reference linear solve = true
end
EOF
# further entries from the caller, e.g.
#   EXTRA_PRM=$'subsection Friction\n set Threshold iteration = nested\nend'
if [ -n "${EXTRA_PRM:-}" ]; then
  printf '%s\n' "$EXTRA_PRM" >> "$overrides"
fi
cat "$repo/prm/$scene.prm" "$overrides" > "$prm"
set_args=()
while IFS= read -r entry; do
  set_args+=(--set "$entry")
done < <(awk -f "$benchmarks/prm_overrides.awk" "$overrides")

# Open MPI refuses to run as root without these.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

cmd="mpirun ${MPIRUN_FLAGS:+$MPIRUN_FLAGS }-np $np $bin_shown <prm/$scene.prm + the overrides above>"
# the command line, with the settings that were given
invocation=""
for v in SCENE TAG TARGET MPIRUN_FLAGS; do
  if [ -n "${!v:-}" ]; then
    case "${!v}" in *[[:space:]]*) invocation="$invocation$v=\"${!v}\" " ;; *) invocation="$invocation$v=${!v} " ;; esac
  fi
done
if [ -n "${DUALCONTACT:-}" ]; then invocation="${invocation}DUALCONTACT=$bin_shown "; fi
if [ -n "${EXTRA_PRM:-}" ]; then invocation="${invocation}EXTRA_PRM=... "; fi
invocation="${invocation}bash benchmarks/benchmark_hertz.sh $np $cycles"
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

# The scene as it will run: the program's defaults, then the file with the
# overrides (later 'set' lines win, as in deal.II's ParameterHandler).
defaults="$tmp/defaults.prm"
if ! "$bin" --print-parameters > "$defaults" 2> /dev/null; then
  : > "$defaults"  # the fallbacks given to prm_value stand in
fi
prm_value() {  # prm_value 'Subsection/Entry' fallback
  local value
  value="$({ awk -f "$benchmarks/prm_overrides.awk" "$defaults"
              awk -f "$benchmarks/prm_overrides.awk" "$prm"; } |
            awk -v want="$1" 'index($0, want "=") == 1 { found = substr($0, length(want) + 2) } END { print found }')"
  printf '%s' "${value:-$2}"
}
is_zero() {  # every component of "a; b" is the number 0
  awk -v e="$1" 'BEGIN { n = split(e, c, ";"); for (i = 1; i <= n; ++i) { gsub(/[ \t]/, "", c[i]); if (c[i] !~ /^[-+]?[0-9.]+([eE][-+]?[0-9]+)?$/ || c[i] + 0 != 0) exit 1 } exit 0 }'
}
dimension="$(prm_value 'Geometry/Dimension' 2)"
geometry="$(prm_value 'Geometry/Type' rectangle)"
youngs="$(prm_value "Material/Young's modulus" 1)"
poisson="$(prm_value "Material/Poisson's ratio" 0.3)"
law="$(prm_value 'Friction/Law' none)"
coefficient="$(prm_value 'Friction/Coefficient' 0)"
threshold="$(prm_value 'Friction/Threshold' 0)"
strategy="$(prm_value 'Friction/Threshold iteration' merged)"
initial="$(prm_value 'Friction/Initial threshold' zero)"
refinement="$(prm_value 'Refinement/Strategy' global)"
nested="$(prm_value 'Refinement/Nested iteration' true)"
r_rel="$(prm_value 'Solver/Augmentation parameter' 10)"
chi_rel="$(prm_value 'Solver/Proximal parameter' 1e-3)"
rt_rel="$(prm_value 'Solver/Tangential augmentation parameter' auto)"
# what the file says it shows: its first comment line
title="$(awk '/^[ \t]*#/ { sub(/^[ \t]*#[ \t]*/, ""); if ($0 != "") { print; exit } }' "$repo/prm/$scene.prm")"
title="${title%.}"

friction=0  # 1: friction acts, so the frictionless exact pressure is not exact
friction_text="frictionless contact"
case "$law" in
  given)
    if is_zero "$threshold"; then friction_text="given friction threshold g = 0 (the frictionless path runs)"
    else friction=1; friction_text="given friction threshold (Tresca) g = \`$threshold\`, no threshold iteration"; fi ;;
  coulomb)
    if is_zero "$coefficient"; then friction_text="Coulomb friction with F = 0 (the frictionless path runs)"
    else
      friction=1
      case "$strategy" in
        nested) how="nested (successive approximations: g = F l1 after each converged Uzawa solve)" ;;
        *) how="merged (g = F l1 after every Uzawa step)" ;;
      esac
      case "$initial" in
        frictionless) first="g^0 = F times the frictionless pressure" ;;
        *) first="g^0 = 0" ;;
      esac
      friction_text="Coulomb friction, F = \`$coefficient\`, threshold iteration $how, $first on the first mesh"
    fi ;;
esac
if [ "$nested" = true ]; then
  start_text="nested iteration: each mesh after the first starts from the previous mesh's v, l1, l2 and g (\`Refinement/Nested iteration = true\`)"
else
  start_text="cold starts: every mesh starts from v = 0, l1 = l2 = 0 (\`Refinement/Nested iteration = false\`)"
fi

echo "benchmark_hertz: mpirun -np $np $bin, $cycles cycles; log in $log"
start=$(date +%s)
status=0
# The log goes into doc/: the temporary folder (output directory, parameter
# file in messages) is named, not printed as a path of this machine.
# shellcheck disable=SC2086
mpirun ${MPIRUN_FLAGS:-} -np "$np" "$bin" "$repo/prm/$scene.prm" "${set_args[@]}" 2>&1 |
  awk -v t="$tmp" '{ while (t != "" && (i = index($0, t)) > 0) $0 = substr($0, 1, i - 1) "<temporary folder>" substr($0, i + length(t)); print; fflush() }' |
  tee "$log" || status=$?
elapsed=$(( $(date +%s) - start ))
echo "benchmark_hertz: run took ${elapsed} s (exit status $status)"

csv="$out/cycles.csv"
if [ "$status" -ne 0 ] || [ ! -s "$csv" ]; then
  echo "benchmark_hertz: the run failed (exit status $status); see $log. No table written." >&2
  exit 1
fi

# the program's own account of the scene, from the log
if [ "$friction" = 1 ] && grep -qF 'only friction holds the body tangentially' "$log"; then
  friction_text="${friction_text/g^0 = 0/g^0 = F N / |Gamma_C| (only friction holds the body sideways; doc/theory.md §8)}"
fi
effects="$(awk '/^Effects composed/ { on = 1; next } on && /^[^ ]/ { exit } on { print "    " $0 }' "$log")"
first_r="$(awk '/ contact: .* r = / { sub(/.* r = /, "r = "); print; exit }' "$log")"
if [ "$dimension" = 2 ]; then plane=", plane strain"; else plane=""; fi

{
  cat <<EOF
# Hertz benchmark: contact solve vs. one linear solve

Generated by \`$invocation\` on $date_run; source tree at commit $commit,
program \`$bin_shown\` built $bin_date.

**Scene** \`prm/$scene.prm\`${title:+: $title.} As run (the file, the
overrides below${EXTRA_PRM:+, EXTRA_PRM} and the program's defaults):
- ${dimension}D $geometry, E = $youngs, nu = $poisson$plane, Q1 elements;
- $friction_text;
- $cycles cycle(s), refinement strategy \`$refinement\`; $start_text;
- r_rel = $r_rel, r_t,rel = $rt_rel (friction terms; auto: r_rel in 2D, r_rel / 4 in 3D), chi_rel = $chi_rel${first_r:+ (on the first mesh $first_r)};
- \`Output/Write vtu = false\`, \`Solver/Time a reference linear solve = true\`.

    $invocation
    # i.e. $cmd
EOF
  if [ -n "$effects" ]; then
    printf '\nThe program'"'"'s account of the scene (from the log):\n\n%s\n' "$effects"
  fi
  cat <<EOF

Machine: $cores cores${cpu:+ ($cpu)}${mem_gb:+, $mem_gb GB}; $np MPI rank(s).
Load average (1, 5, 15 min) just before the run: $load_before
(other work on the machine inflates the wall times).
Total run time (including mesh set-up, output and the reference solves):
$elapsed s. Screen log: \`doc/benchmarks/benchmark_${tag}.log\`.${EXTRA_PRM:+ Extra entries: \`$(echo "$EXTRA_PRM" | tr "\n" " ")\`.}

Columns: contact nodes = nodes on the contact boundary, active = nodes in
contact at the end; Uzawa / Newton / CG = steps of the Uzawa and Newton iterations and CG
iterations, summed over the contact solve; AMG = AMG set-ups in the contact
solve; memory = peak resident memory summed over ranks (KB per DoF: the
same over the DoFs; it includes the program's fixed start-up cost, which
dominates on small meshes); contact = wall time of
the assembly and the contact solve; linear = wall time of the assembly and of
one linear solve on the same mesh (AMG set-up + CG); ratio = contact / linear;
start = nested (from the previous mesh's solution and multipliers,
Refinement/Nested iteration) or cold; ratio, all meshes = the contact solves
and transfers of this mesh and of all coarser ones, over the linear solve on
this mesh; exponent = log(contact_k / contact_{k-1}) / log(N_k / N_{k-1}),
the growth of the contact time with the DoFs N since the previous mesh
(1 is linear cost); pressure error = relative L2 error of the contact pressure on
Gamma_C against the scene's \`Exact solution/Contact pressure\`. The target
is judged on "ratio".
EOF
  if [ "$friction" = 1 ]; then
    cat <<'EOF'
With friction that exact solution is the frictionless (Hertz) pressure,
which friction changes (doc/theory.md §9), so this error levels off instead
of going to zero.
EOF
  fi
  echo
  awk -F, -v target="$target" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    {
      ta = $c["time_assembly"]; ts = $c["time_solve"]; tr = $c["time_reference"]
      contact = ta + ts; linear = ta + tr
      ratio = (linear > 0) ? contact / linear : -1
      # the whole sequence up to this mesh: with nested iteration each mesh
      # starts from the previous one, so their cost belongs to this one
      sequence += contact + $c["time_refine"]
      whole = (linear > 0) ? sequence / linear : -1
      # memory per DoF, and the growth exponent of the contact time with
      # the DoFs since the previous mesh (t ~ N^exponent)
      kb = 1024 * $c["memory_mb"] / $c["dofs"]
      exponent = (n > 0 && previous_contact > 0 && contact > 0 && $c["dofs"] > previous_dofs) ? \
        sprintf("%.2f", log(contact / previous_contact) / log($c["dofs"] / previous_dofs)) : "-"
      previous_contact = contact; previous_dofs = $c["dofs"]
      # first and last mesh (memory added per DoF), and the first mesh from
      # 2.5e5 DoFs on (growth exponent over the large meshes)
      if (n == 0) { first_dofs = $c["dofs"]; first_mb = $c["memory_mb"] }
      last_dofs = $c["dofs"]; last_mb = $c["memory_mb"]; last_contact = contact
      if ($c["dofs"] >= 2.5e5 && big_dofs == 0) { big_dofs = $c["dofs"]; big_contact = contact }
      rows[++n] = sprintf("| %d | %s | %d | %d | %d | %d | %d | %d | %d | %.0f | %.0f | %.3f | %.3f | %s | %s | %s | %s |",
        $c["dofs"], ($c["warm_start"] == 1) ? "nested" : "cold", $c["contact_nodes"], $c["active_nodes"], $c["threshold_steps"], $c["uzawa_steps"],
        $c["newton_steps"], $c["linear_iterations"], $c["amg_setups"],
        $c["memory_mb"], kb, contact, linear,
        (ratio >= 0) ? sprintf("%.2f", ratio) : "n/a",
        (whole >= 0) ? sprintf("%.2f", whole) : "n/a", exponent,
        ($c["pressure_error"] > 0) ? sprintf("%.2e", $c["pressure_error"]) : "-")
      if ($c["dofs"] >= 2.5e5) {
        ++big
        if (ratio < 0 || ratio > target) { ++miss; worst = worst sprintf(" %d DoFs: %s;", $c["dofs"], (ratio >= 0) ? sprintf("%.2f", ratio) : "not timed") }
        else ok = ok sprintf(" %d DoFs: %.2f;", $c["dofs"], ratio)
      }
    }
    END {
      print "| DoFs | start | contact nodes | active | threshold steps | Uzawa | Newton | CG | AMG set-ups | memory [MB] | KB per DoF | contact [s] | linear [s] | ratio | ratio, all meshes | exponent | pressure error |"
      print "|---:|:---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
      for (i = 1; i <= n; ++i) print rows[i]
      print ""
      if (last_dofs > first_dofs)
        printf "Memory per DoF added from the first to the last mesh: **%.2f KB** ((%.0f - %.0f) MB over %d DoFs).\n", \
          1024 * (last_mb - first_mb) / (last_dofs - first_dofs), last_mb, first_mb, last_dofs - first_dofs
      if (big_dofs > 0 && last_dofs > big_dofs && big_contact > 0)
        printf "Growth of the contact time from %d to %d DoFs: **N^%.2f**.\n", big_dofs, last_dofs, \
          log(last_contact / big_contact) / log(last_dofs / big_dofs)
      print ""
      if (big == 0)
        print "**Target \"ratio <= " target " at >= 2.5e5 DoFs\": not judged**: no cycle reached 2.5e5 DoFs."
      else if (miss == 0) {
        sub(/;$/, "", ok)
        print "**Target \"ratio <= " target " at >= 2.5e5 DoFs\": met** (" substr(ok, 2) ")."
      } else {
        sub(/;$/, "", worst)
        print "**Target \"ratio <= " target " at >= 2.5e5 DoFs\": not met** (" substr(worst, 2) ")."
      }
    }' "$csv"
} > "$md"

echo "benchmark_hertz: wrote $md"
cat "$md"
