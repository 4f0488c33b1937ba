#!/bin/bash
# Regenerate the results of step-4: run it on 2 MPI ranks, draw hertz_friction.svg, hertz_friction_nu2.svg
# and write the output README.md quotes (../make_results.sh says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 4 "hertz_friction.svg, hertz_friction_nu2.svg"
