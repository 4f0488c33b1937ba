#!/usr/bin/env bash
# The test random_inputs: dualcontact on generated input, valid and broken.
#   bash check_random_inputs.sh <source dir> <dualcontact> <random_scenes>
#                               <mpiexec> <work dir>
# tests/random_scenes.cc writes the inputs (the same files on every run and
# platform; its head says what they are) and a manifest with the ranks and
# the exit statuses each input allows: 0 for the valid scenes, 2-7 for the
# mutated ones (each mutation kind names the statuses it can cause, 0 too
# for those that may leave the scene valid). Each input runs in its own
# empty working directory, and passes if
#   - the program ended by itself: no signal (exit status >= 128, or an
#     mpirun report of one), no hang (60 s: every input takes 1-4 s), and
#     nothing of deal.II's or the C++ run time's internals on stdout or
#     stderr (an uncaught exception, an assertion, a stack trace, a heap
#     check);
#   - its exit status is one its manifest line allows (exit 1, a solver
#     failure, is allowed for none: a valid scene must solve, and a mutation
#     must be refused before the solve);
#   - on an error exit: its working directory is still empty (no output
#     folder) and stderr holds one error line starting with "dualcontact: "
#     (besides warning lines, "dualcontact: warning: ...");
#   - on exit 0: the working directory holds the output folder only; no NaN
#     or infinity in cycles.csv or any contact_XX.csv nor on the screen;
#     equilibrium_imbalance <= 1e-6 in every cycle; at every node of the last
#     cycle's contact_XX.csv l1 >= 0 and |l2| <= g (1 + 1e-6) + 1e-12 max l1,
#     g the threshold (to 1e-9) for given friction; for Coulomb friction
#     with a constant F, |g - F l1| <= tol |F l1| in the Euclidean norm over
#     the nodes, tol = <Friction/Threshold tolerance>: where the threshold
#     iteration stops (node by node, g and F l1 may differ by more than tol
#     max g: 1.3e-6 was seen); the law, F, g and tol as output/parameters.prm
#     records them. A valid scene sets no entry without effect: its stderr
#     is empty (no warning).
# One line per input (name, ranks, exit status, PASS/FAIL and why, seconds),
# then 'N passed, M failed' alone on the last line; the exit status is 1 if
# any input failed. A failing input's files stay in <work dir>: inputs/ (the
# scene, with the mutation in its first line), run/<name>/ and log/<name>.*;
# rerun one by hand there with
#   cd <work dir>/run/<name> && [mpirun -np 2] <dualcontact> ../../inputs/<name>.prm
# DUALCONTACT_RANDOM_SEED=<n> makes other inputs than the test's, to explore.
#
# Run time: 69 inputs, each mostly the program's start (some 0.4 s of
# loading deal.II's libraries and starting MPI; mpirun adds 0.5 s, and 2 s
# more on an error exit); the scenes solve in a small fraction of a second.
set -uo pipefail

if [ $# -ne 5 ]; then
  echo "usage: check_random_inputs.sh <source dir> <dualcontact> <random_scenes> <mpiexec> <work dir>" >&2
  exit 2
fi
source_dir="$1"
program="$2"
generator="$3"
mpiexec="$4"
work="$5"

rm -rf "$work"
mkdir -p "$work/run" "$work/log"
inputs="$work/inputs"

# microseconds now (bash 5: no process)
now() {
  if [ -n "${EPOCHREALTIME:-}" ]; then
    clock=${EPOCHREALTIME//[^0-9]/}
  else
    clock=$(($(date +%s%N) / 1000))
  fi
}
now
start=$clock

seed=(${DUALCONTACT_RANDOM_SEED:-})
"$generator" "$source_dir" "$inputs" ${seed[@]+"${seed[@]}"} || {
  echo "check_random_inputs: the generator $generator failed"
  echo "0 passed, 1 failed"
  exit 1
}
# the same files a second time: the generator depends on nothing but its seed
"$generator" "$source_dir" "$work/inputs_again" ${seed[@]+"${seed[@]}"} &&
  diff -r "$inputs" "$work/inputs_again" > /dev/null || {
  echo "check_random_inputs: the generator wrote different inputs the second time"
  echo "0 passed, 1 failed"
  exit 1
}
rm -rf "$work/inputs_again"

# Open MPI's start probes every point-to-point layer it has (UCX, OFI, ...)
# and loads their libraries; ob1, the one a single machine uses, is a third
# of a second cheaper per run. A 1-rank run needs no orted daemon either
# (ess_singleton_isolated). A rank that waits for the other one polls
# without yielding its core: with the other core busy (ctest -j2), a 2-rank
# run that takes 1 s alone took 12 to 65 s, 3 to 4 s with yield_when_idle.
# Other MPI implementations ignore all three.
export OMPI_MCA_pml="${OMPI_MCA_pml:-ob1}"
export OMPI_MCA_ess_singleton_isolated="${OMPI_MCA_ess_singleton_isolated:-1}"
export OMPI_MCA_mpi_yield_when_idle="${OMPI_MCA_mpi_yield_when_idle:-1}"

# a run that hangs fails (timeout: exit 124) instead of using up ctest's time
run_limit=()
if command -v timeout > /dev/null; then
  run_limit=(timeout -k 5 60)
fi

# deal.II's and the C++ run time's texts, and the kernel's for signals
internal='terminate called|Stacktrace|An error occurred in line|Additional information|Aborted|Segmentation|segfault|double free|corrupted|what\(\):|Assertion|assertion|std::|ExcMessage|Exc[A-Z][A-Za-z]*\(|MPI_ABORT|core dumped|free\(\)|malloc|munmap_chunk|stack smashing|Floating point exception|Bus error|Illegal instruction|signal [0-9]'

# stdout and stderr without mpirun's framed reports (on a non-zero exit of
# a rank), which are checked on their own for a signal
strip_mpirun_reports() {
  awk '/^----------+$/ { framed = !framed; next } !framed'
}

# the checks of a run that ended with exit 0, in its working directory;
# prints the reasons for failing, nothing if it passed
check_success() {
  local dir="$1" log="$2"
  local entries
  entries=$(ls -A "$dir")
  if [ "$entries" != "output" ]; then
    echo "the working directory holds '$(echo $entries)', not the output folder only;"
    return
  fi
  local out="$dir/output"
  if [ ! -s "$out/cycles.csv" ]; then
    echo "no output/cycles.csv;"
    return
  fi
  if grep -Eiq '(^|[^a-z])[-+]?(nan|inf)([^a-z]|$)' "$log.out"; then
    echo "NaN or infinity on the screen;"
  fi
  local csv
  for csv in "$out"/cycles.csv "$out"/contact_*.csv; do
    [ -e "$csv" ] || continue
    awk -F, -v file="${csv##*/}" '
      NR > 1 {
        for (i = 1; i <= NF; ++i)
          if (tolower($i) ~ /^[-+]?(nan|inf)/) {
            printf "%s line %d has %s;\n", file, NR, $i
            exit
          }
      }' "$csv"
  done
  awk -F, '
    NR == 1 {
      for (i = 1; i <= NF; ++i)
        if ($i == "equilibrium_imbalance") column = i
      if (!column) { print "cycles.csv has no column equilibrium_imbalance;"; exit }
      next
    }
    !($column + 0 <= 1e-6) {
      printf "cycle %s: equilibrium_imbalance %s > 1e-6;\n", $1, $column
    }' "$out/cycles.csv"

  # the friction law at the last cycle's contact nodes
  local last
  last=$(ls "$out" | grep -E '^contact_[0-9]+\.csv$' | sort | tail -n 1)
  [ -n "$last" ] || return
  local law coefficient threshold tolerance
  entry() {
    sed -n "s/^ *set $1 *= *\([^#]*\).*/\1/p" "$out/parameters.prm" | head -n 1
  }
  law=$(entry Law)
  coefficient=$(entry Coefficient)
  threshold=$(entry Threshold)
  tolerance=$(entry 'Threshold tolerance')
  awk -F, -v file="$last" -v law="$law" -v F="$coefficient" -v G="$threshold" \
    -v tolerance="$tolerance" '
    function number(s) { return s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
    function abs(x) { return x < 0 ? -x : x }
    function trim(s) { gsub(/^[ \t]+|[ \t]+$/, "", s); return s }
    BEGIN { law = trim(law); F = trim(F); G = trim(G); tolerance = trim(tolerance) }
    NR == 1 {
      for (i = 1; i <= NF; ++i) column[$i] = i
      n = 0
      if ("l2" in column) l2[n++] = column["l2"]
      else for (d = 1; d <= 3; ++d) {
        name = "l2_" substr("xyz", d, 1)
        if (name in column) l2[n++] = column[name]
      }
      if (!("l1" in column) || !("g" in column) || n == 0) {
        printf "%s lacks the columns l1, l2 or g;\n", file
        bad = 1
        exit
      }
      next
    }
    {
      rows++
      p[rows] = $(column["l1"]) + 0
      g[rows] = $(column["g"]) + 0
      t = 0
      for (k = 0; k < n; ++k) t += $(l2[k]) * $(l2[k])
      t2[rows] = sqrt(t)
      if (p[rows] > max_l1) max_l1 = p[rows]
      if (g[rows] > max_g) max_g = g[rows]
    }
    END {
      if (bad) exit
      coulomb = law == "coulomb" && number(F)
      given   = law == "given" && number(G)
      for (r = 1; r <= rows; ++r) {
        if (!(p[r] >= 0)) { printf "%s node %d: l1 = %.17g < 0;\n", file, r, p[r]; failed++ }
        if (!(t2[r] <= g[r] * (1 + 1e-6) + 1e-12 * max_l1)) {
          printf "%s node %d: |l2| = %.17g > g = %.17g;\n", file, r, t2[r], g[r]; failed++
        }
        if (coulomb) {
          difference += (g[r] - F * p[r]) ^ 2
          norm       += (F * p[r]) ^ 2
        }
        if (given && !(abs(g[r] - G) <= 1e-9 * abs(G))) {
          printf "%s node %d: g = %.17g, not the threshold %s;\n", file, r, g[r], G; failed++
        }
        if (failed >= 3) exit
      }
      # the threshold iteration stops at |g_new - g| <= tol |g_new|, g_new =
      # F l1, in the Euclidean norm over the nodes
      if (coulomb && !(sqrt(difference) <= tolerance * sqrt(norm) * (1 + 1e-9))) {
        printf "%s: |g - F l1| = %.17g > %s |F l1| = %.17g;\n", file, sqrt(difference),
          tolerance, tolerance * sqrt(norm)
      }
    }' "$out/$last"
}

# stdout and stderr in one pass (a process per check would cost 1-2 s of
# the test): a signal in mpirun's framed reports, the first line of
# internal text outside them, and the lines of stderr outside them: error
# lines, and lines that are not the program's ("dualcontact: ...")
scan_output() {
  internal_re="$internal" awk '
    FNR == 1 { framed = 0; on_stderr = FILENAME ~ /\.err$/ }
    /^----------+$/ { framed = !framed; next }
    framed { if (tolower($0) ~ /signal/) signal = 1; next }
    found == "" && $0 ~ ENVIRON["internal_re"] { found = substr($0, 1, 100) }
    on_stderr && $0 != "" {
      if ($0 !~ /^dualcontact: /) foreign++
      else if ($0 !~ /^dualcontact: warning: /) errors++
    }
    END {
      if (signal) print "mpirun reports a signal;"
      if (found != "") printf "internal text: '\''%s'\'';\n", found
      printf "STDERR %d %d\n", errors, foreign
    }' "$1.out" "$1.err"
}

shopt -s nullglob dotglob
passed=0
failed=0
while IFS=$'\t' read -r name ranks exits description; do
  dir="$work/run/$name"
  log="$work/log/$name"
  mkdir -p "$dir"
  now
  t0=$clock
  if [ "$ranks" = 1 ]; then
    (cd "$dir" && "${run_limit[@]}" "$program" "$inputs/$name.prm") \
      < /dev/null > "$log.out" 2> "$log.err"
  else
    (cd "$dir" && "${run_limit[@]}" "$mpiexec" -np "$ranks" \
      "$program" "$inputs/$name.prm") < /dev/null > "$log.out" 2> "$log.err"
  fi
  status=$?
  now
  elapsed=$((clock - t0))

  why=""
  if [ "$status" -ge 124 ]; then
    why+="killed or timed out (exit status $status);"
  fi
  scan=$(scan_output "$log")
  why+=${scan%%STDERR *}
  read -r errors foreign <<< "${scan##*STDERR }"
  if [[ ",$exits," != *",$status,"* ]]; then
    why+="exit status $status, expected one of $exits;"
  fi
  entries=("$dir"/*)
  if [ "$status" = 0 ]; then
    why+=$(check_success "$dir" "$log")
    # a valid scene sets no entry without effect: no warning either
    if [ "${name#valid_}" != "$name" ] && [ -s "$log.err" ]; then
      why+="stderr is not empty;"
    fi
  elif [ "$status" -lt 124 ]; then
    if [ ${#entries[@]} -gt 0 ]; then
      why+="an error exit left '${entries[*]##*/}' in the working directory;"
    fi
    if [ "$foreign" != 0 ]; then
      why+="stderr has $foreign lines that do not start with 'dualcontact: ';"
    fi
    if [ "$errors" != 1 ]; then
      why+="stderr has $errors error lines, not 1;"
    fi
  fi

  seconds="$((elapsed / 1000000)).$((elapsed / 100000 % 10))"
  if [ -z "$why" ]; then
    passed=$((passed + 1))
    printf '%-11s np %s  exit %s  PASS  %5s s  %s\n' "$name" "$ranks" "$status" "$seconds" "$description"
    rm -rf "$dir" "$log.out" "$log.err"
  else
    failed=$((failed + 1))
    printf '%-11s np %s  exit %s  FAIL  %5s s  %s\n' "$name" "$ranks" "$status" "$seconds" "$description"
    printf '    why: %s\n' "${why//$'\n'/ }"
    printf '    stderr: %s\n' "$(strip_mpirun_reports < "$log.err" | head -c 600 | cat -v | tr '\n' '|')"
  fi
done < "$inputs/manifest.txt"

now
echo "check_random_inputs: $((passed + failed)) inputs in $(((clock - start) / 1000000)) s (work dir $work)"
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
