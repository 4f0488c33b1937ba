#!/bin/bash
# Regenerate the results of step-11: run it on 2 MPI ranks, draw patch.svg,
# pressure.svg and traction.svg, and write the output README.md quotes
# (../make_results.sh says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 11 "patch.svg, pressure.svg, traction.svg"
