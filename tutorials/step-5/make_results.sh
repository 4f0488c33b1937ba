#!/bin/bash
# Regenerate the results of step-5: run it on 2 MPI ranks, draw work_precision.svg, error_vs_dofs.svg
# and write the output README.md quotes (../make_results.sh says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 5 "work_precision.svg, error_vs_dofs.svg"
