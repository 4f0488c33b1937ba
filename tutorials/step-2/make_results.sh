#!/bin/bash
# Regenerate the results of step-2: run the program on 2 MPI ranks (screen
# output in output/screen.out, the Newton iterates in output/newton.csv),
# draw the figure (newton.svg), and write the screen output that README.md
# quotes between its <!-- begin output: NAME --> and <!-- end output: NAME -->
# markers (../readme_output.sh says how; the test tutorial_step-2_readme
# compares those blocks with expected.out).
# Run from anywhere; the build is expected in ../../build (the top-level
# build of the project).
set -eo pipefail
cd "$(dirname "$0")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p output
mpirun -np 2 ../../build/tutorials/step-2 step-2.prm | tee output/screen.out
gnuplot plot.gp
bash ../readme_output.sh update README.md output/screen.out
echo "screen output in output/screen.out, figure newton.svg, quoted in" \
  "README.md"
