#!/usr/bin/env bash
# Build, then run a scene on 2 MPI ranks from the repository root:
#   bash contrib/run_default.sh              runs prm/paper_block.prm
#   bash contrib/run_default.sh my.prm       runs another scene
# Output goes to the scene's <Output/Directory> (default ./output/), relative
# to the repository root. Set NP to change the number of ranks.
set -euo pipefail

prm="${1:-prm/paper_block.prm}"
# a relative path given by the caller is relative to the caller's directory
if [ $# -ge 1 ] && [ "${prm:0:1}" != "/" ]; then
  prm="$PWD/$prm"
fi
np="${NP:-2}"

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"

bash contrib/build.sh

# Open MPI refuses to run as root without these.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

echo "run_default: mpirun -np $np build/dualcontact $prm"
exec mpirun -np "$np" build/dualcontact "$prm"
