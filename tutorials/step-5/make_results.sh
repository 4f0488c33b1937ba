#!/bin/bash
# Regenerate the results of step-5: run it on 2 MPI ranks (screen output in
# output/step-5.out, one folder of cycles.csv and screen.log per run in
# output/), draw work_precision.svg and error_vs_dofs.svg with gnuplot, and
# write the screen output that README.md quotes between its
# <!-- begin output: NAME --> and <!-- end output: NAME --> markers
# (../readme_output.sh says how; the test tutorial_step-5_readme compares
# those blocks with expected.out, wall times masked).
# Run from anywhere; the program is ../../build/tutorials/step-5 unless
# STEP5=<path> says otherwise.
set -euo pipefail
cd "$(dirname "$0")"
program=${STEP5:-../../build/tutorials/step-5}
# Open MPI refuses to run as root unless told
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

rm -rf output
mkdir -p output
start=$(date +%s.%N)
nice mpirun -np 2 "$program" step-5.prm | tee output/step-5.out
end=$(date +%s.%N)
awk -v s="$start" -v e="$end" 'BEGIN { printf "make_results.sh: step-5 took %.1f s on 2 ranks\n", e - s }'
gnuplot plot.gp
bash ../readme_output.sh update README.md output/step-5.out
echo "make_results.sh: wrote work_precision.svg, error_vs_dofs.svg and README.md's quoted output"
