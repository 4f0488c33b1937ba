#!/bin/bash
# What every tutorial's make_results.sh does, with the step's number and the
# figures its plot.gp draws:
#
#   bash ../make_results.sh N "figure.svg, other.svg"
#
# runs build/tutorials/step-N on its step-N.prm on 2 MPI ranks from the
# step's folder (a fresh ./output: the library's files, and the screen
# output in output/screen.out), prints the wall time, draws the figures with
# plot.gp, and writes the screen output that README.md quotes between its
# <!-- begin output: NAME --> and <!-- end output: NAME --> markers anew
# (readme_output.sh says how; the test tutorial_step-N_readme compares those
# blocks with expected.out). The build is ../../build, the top-level build
# of the project, unless BUILD names another.
set -euo pipefail
step=step-$1
figures=$2
build=${BUILD:-../../build}
# Open MPI refuses to run as root unless told
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

rm -rf output
mkdir -p output
start=$(date +%s.%N)
nice mpirun -np 2 "$build/tutorials/$step" "$step.prm" | tee output/screen.out
end=$(date +%s.%N)
awk -v s="$start" -v e="$end" -v n="$step" \
  'BEGIN { printf "make_results.sh: %s took %.1f s on 2 ranks\n", n, e - s }'
gnuplot plot.gp
bash ../readme_output.sh update README.md output/screen.out
echo "make_results.sh: wrote $figures and README.md's quoted output"
