#!/bin/bash
# Regenerate the results of step-7: run it on 2 MPI ranks, draw profile.svg, zones.svg
# and write the output README.md quotes (../make_results.sh says how).
set -euo pipefail
cd "$(dirname "$0")"
bash ../make_results.sh 7 "profile.svg, zones.svg"
