#!/bin/bash
# Regenerate the results of step-9: run it on 2 MPI ranks, draw
# pressure_error.svg, and write the output README.md quotes
# (../make_results.sh says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 9 "pressure_error.svg"
