#!/usr/bin/env bash
# The test scripts_parse: every shell script of the repository (benchmarks/,
# contrib/, tests/, tutorials/) parses (bash -n), and every benchmark script
# that runs the program stops with exit status 2 and its own message when
# the program is missing (DUALCONTACT set to a path that does not exist):
# the part they share, benchmarks/common.sh, loads. Benchmarks are not run
# by the test suite (they take minutes and write doc/); this catches a
# script broken by an edit.
#   bash check_scripts.sh <source dir>
set -uo pipefail
source_dir="$1"
failed=0
fail() {
  echo "check_scripts: $*" >&2
  failed=1
}
shopt -s nullglob
for script in "$source_dir"/benchmarks/*.sh "$source_dir"/contrib/*.sh \
  "$source_dir"/tests/*.sh "$source_dir"/tutorials/*.sh; do
  bash -n "$script" 2> /dev/null || fail "${script#"$source_dir"/} does not parse: $(bash -n "$script" 2>&1 | head -1)"
done
missing="$(mktemp -u)"
for name in benchmark_hertz benchmark_load_path degree_sweep locking_study mixed_solver_counts solver_limits_sweep \
  work_precision work_precision_degree; do
  message="$(DUALCONTACT="$missing" bash "$source_dir/benchmarks/$name.sh" 2>&1 > /dev/null)"
  status=$?
  [ "$status" -eq 2 ] || fail "benchmarks/$name.sh without a program: exit status $status, not 2"
  case "$message" in
    "$name: no program at '$missing'"*) ;;
    *) fail "benchmarks/$name.sh without a program: message '$message'" ;;
  esac
done
[ "$failed" -eq 0 ] && echo "check_scripts: every script parses; the benchmark scripts load benchmarks/common.sh"
exit "$failed"
