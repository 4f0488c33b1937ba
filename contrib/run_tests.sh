#!/usr/bin/env bash
# Build, then run the whole test suite with ctest. Extra arguments go to
# ctest (e.g. -R unit). The exit status is ctest's.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

bash contrib/build.sh

# Open MPI refuses to run as root without these.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

cd build
echo "run_tests: ctest --output-on-failure -j2 $*"
status=0
ctest --output-on-failure -j2 "$@" || status=$?
exit "$status"
