#!/bin/bash
# Regenerate the results of step-3: run it on 2 MPI ranks, draw stick_slip.svg, threshold_history.svg
# and write the output README.md quotes (../make_results.sh says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 3 "stick_slip.svg, threshold_history.svg"
