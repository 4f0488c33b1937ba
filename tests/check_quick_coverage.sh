#!/usr/bin/env bash
# Does the quick tier (ctest -L quick) execute every source file?
#
#   bash tests/check_quick_coverage.sh [<build directory>]
#   bash tests/check_quick_coverage.sh --report <build directory>
#
# The first form configures a build directory of its own (default:
# build-coverage in the repository, which git ignores) with coverage
# counters, builds there only what the quick tier runs (dualcontact and
# unit_tests; JOBS compile jobs, default 1), runs `ctest -L quick -j2` there
# and reports. --report only reports on the counters such a directory holds.
#
# The report has one row per source file (source/**/*.cc, main.cc included):
# the lines the tier executed, of the lines gcov counts. A file that only
# registers a plugin has no line gcov counts: its row says 'register', and it
# counts as run when its counters were written (the program loaded it, which
# runs the registration). The script fails if a file has no executed line
# or a test of the tier fails.
#
# The build is deal.II's Release configuration (no assertions: the tier runs
# at about the speed of a Release build) compiled unoptimised, -O0
# --coverage: a compiler launcher appends both to every compile command, so
# that they come after deal.II's -O2. Only gcov (GCC's) is needed.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

report_only=false
if [ "${1:-}" = "--report" ]; then
  report_only=true
  shift
  [ $# -eq 1 ] || { echo "usage: $0 --report <build directory>" >&2; exit 2; }
fi
dir="${1:-$repo/build-coverage}"
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"

status=0
if ! $report_only; then
  launcher="$dir/coverage-cxx.sh"
  printf '%s\n' '#!/bin/sh' 'exec "$@" -O0 --coverage' > "$launcher"
  chmod +x "$launcher"
  cmake -S "$repo" -B "$dir" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" \
    -DCMAKE_EXE_LINKER_FLAGS=--coverage \
    -DCMAKE_SHARED_LINKER_FLAGS=--coverage > "$dir/coverage-configure.log"
  cmake --build "$dir" --target dualcontact unit_tests -j"${JOBS:-1}"
  find "$dir" -name '*.gcda' -delete
  (cd "$dir" && ctest -L quick -j2 --output-on-failure) || status=1
fi

# the counters of source/<file>.cc are in <dir>/CMakeFiles/<target>.dir/source/<file>.cc.gcno
# (and .gcda once it ran); gcov -n prints a summary per file and writes nothing
printf '%-45s %8s %8s\n' "source file" executed lines
missing=0
cd "$dir"
while IFS= read -r source; do
  notes="$(find "$dir/CMakeFiles" -path "*.dir/$source.gcno" | head -n 1)"
  if [ -z "$notes" ]; then
    printf '%-45s %8s %8s\n' "$source" "-" "not built"
    missing=$((missing + 1))
    continue
  fi
  summary="$(gcov -n -o "$notes" "$repo/$source" 2>/dev/null \
    | grep -A1 -F "File '$repo/$source'" | sed -n 's/^Lines executed:\([0-9.]*\)% of \([0-9]*\)$/\1 \2/p')"
  read -r percent lines <<< "${summary:-0 0}"
  executed="$(awk -v p="$percent" -v n="$lines" 'BEGIN { printf "%d", p * n / 100 + 0.5 }')"
  if [ "$lines" -eq 0 ] && [ -f "${notes%.gcno}.gcda" ]; then
    # a file that only registers a plugin: gcov counts no line of it, and
    # its registration runs when the program loads (the .gcda is written)
    printf '%-45s %8s %8s\n' "$source" "-" "register"
    continue
  fi
  printf '%-45s %8d %8d\n' "$source" "$executed" "$lines"
  if [ "$executed" -eq 0 ]; then
    missing=$((missing + 1))
  fi
done < <(cd "$repo" && find source -name '*.cc' | LC_ALL=C sort)

if [ "$missing" -gt 0 ]; then
  echo "$missing source file(s) without an executed line" >&2
  status=1
else
  echo "every source file has executed lines"
fi
exit $status
