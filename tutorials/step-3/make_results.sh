#!/bin/bash
# Regenerate the results of step-3: run the program on 2 MPI ranks (output
# in ./output, screen output in output/screen.out), draw the figures
# (stick_slip.svg, threshold_history.svg), and write the screen output that
# README.md quotes between its <!-- begin output: NAME --> and
# <!-- end output: NAME --> markers (../readme_output.sh says how; the test
# tutorial_step-3_readme compares those blocks with expected.out).
# Run from anywhere; the build is expected in ../../build (the top-level
# build of the project) unless BUILD names another.
set -eo pipefail
cd "$(dirname "$0")"
BUILD=${BUILD:-../../build}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p output
mpirun -np 2 "$BUILD/tutorials/step-3" step-3.prm | tee output/screen.out
gnuplot plot.gp
bash ../readme_output.sh update README.md output/screen.out
echo "screen output in output/screen.out, figures stick_slip.svg," \
  "threshold_history.svg, quoted in README.md"
