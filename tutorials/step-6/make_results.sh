#!/bin/bash
# Regenerate the results of step-6: run it on 2 MPI ranks (screen output in
# output/step-6.out, the library's in output/screen.log), then draw
# pressure.svg and stress_axis.svg with gnuplot, and write the quoted output
# of README.md anew (../readme_output.sh).
# Run from anywhere; the program is ../../build/tutorials/step-6 unless
# STEP6=<path> says otherwise.
set -euo pipefail
cd "$(dirname "$0")"
program=${STEP6:-../../build/tutorials/step-6}
# Open MPI refuses to run as root unless told
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

rm -rf output
start=$(date +%s.%N)
nice mpirun -np 2 "$program" step-6.prm | tee step-6.out
end=$(date +%s.%N)
mv step-6.out output/
awk -v s="$start" -v e="$end" 'BEGIN { printf "make_results.sh: step-6 took %.1f s on 2 ranks\n", e - s }'
gnuplot plot.gp
bash ../readme_output.sh update README.md output/step-6.out
echo "make_results.sh: wrote pressure.svg, stress_axis.svg and README.md's quoted output"
