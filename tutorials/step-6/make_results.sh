#!/bin/bash
# Regenerate the results of step-6: run it on 2 MPI ranks, draw pressure.svg, stress_axis.svg
# and write the output README.md quotes (../make_results.sh says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 6 "pressure.svg, stress_axis.svg"
