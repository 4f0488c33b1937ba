#!/bin/bash
# Regenerate the results of step-5: run it on 2 MPI ranks (screen output in
# output/step-5.out, one folder of cycles.csv per run in output/), then draw
# work_precision.svg and error_vs_dofs.svg with gnuplot.
# Run from anywhere; the program is ../../build/tutorials/step-5 unless
# STEP3=<path> says otherwise.
set -euo pipefail
cd "$(dirname "$0")"
program=${STEP3:-../../build/tutorials/step-5}
# Open MPI refuses to run as root unless told
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

rm -rf output
mkdir -p output
start=$(date +%s.%N)
nice mpirun -np 2 "$program" step-5.prm | tee output/step-5.out
end=$(date +%s.%N)
awk -v s="$start" -v e="$end" 'BEGIN { printf "make_results.sh: step-5 took %.1f s on 2 ranks\n", e - s }'
gnuplot plot.gp
echo "make_results.sh: wrote work_precision.svg and error_vs_dofs.svg"
