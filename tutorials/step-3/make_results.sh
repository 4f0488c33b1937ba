#!/bin/bash
# The results of README.md: run step-3 on 2 MPI ranks (screen output also in
# output/screen.out), then draw the figures (gnuplot plot.gp). Works from any
# directory; BUILD names another build directory (default ../../build).
set -e
cd "$(dirname "$0")"
BUILD=${BUILD:-../../build}
if [ "$(id -u)" = 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
mkdir -p output
mpirun -np 2 "$BUILD/tutorials/step-3" step-3.prm | tee output/screen.out
gnuplot plot.gp
