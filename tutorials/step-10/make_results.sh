#!/bin/bash
# Regenerate the results of step-10: run it on 2 MPI ranks, draw
# pressure.svg, and write the output README.md quotes
# (../make_results.sh says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 10 "pressure.svg"
