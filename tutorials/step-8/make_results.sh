#!/bin/bash
# Regenerate the results of step-8: run it on 2 MPI ranks, draw loop.svg and
# traction.svg, and write the output README.md quotes (../make_results.sh
# says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 8 "loop.svg, traction.svg"
