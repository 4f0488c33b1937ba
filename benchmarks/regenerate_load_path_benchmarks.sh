#!/usr/bin/env bash
# Regenerate the load-path pages doc/benchmarks/benchmark_load_path_*.md and
# doc/benchmarks/benchmark_long_path.md (and their logs) with the current
# program, one run after the other:
#   bash benchmarks/regenerate_load_path_benchmarks.sh
# About 3 minutes on 2 cores. Quote their times only from a quiet machine.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
# the cycle of prm/cattaneo_mindlin.prm: pressed in four steps, sheared to
# Q*, -Q* and Q* in twelve (the predictor on, the default)
bash benchmarks/benchmark_load_path.sh 2
# ... and without the predictor (every later step from the last state)
SCENE=cattaneo_mindlin TAG=cattaneo_mindlin_warm EXTRA_PRM='subsection Load path
  set Predictor = false
end' bash benchmarks/benchmark_load_path.sh 2
# the same cylinder loaded in proportion from t = 0.001 in steps of 0.1,
# with the predictor and without it
proportional='subsection Boundary conditions
  set Displacements = 1: 0.001 * t; -0.01 * t
end
subsection Load path
  set Times = 0.001, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1
end'
SCENE=cattaneo_mindlin TAG=proportional EXTRA_PRM="$proportional" \
  bash benchmarks/benchmark_load_path.sh 2
SCENE=cattaneo_mindlin TAG=proportional_warm EXTRA_PRM="$proportional
subsection Load path
  set Predictor = false
end" bash benchmarks/benchmark_load_path.sh 2
# a step's cost against the number of steps before it
bash benchmarks/benchmark_long_path.sh 10000
