#!/usr/bin/env bash
# Regenerate the benchmark pages doc/benchmarks/benchmark_hertz*.md (and
# their logs) with the current program, one run after the other on 2 MPI
# ranks:
#   bash benchmarks/regenerate_benchmarks.sh
# About 6 minutes on 2 cores. The stress run
# (doc/benchmarks/benchmark_stress_*: 4.8e6 DoFs, 10 GB) is not repeated
# here; run it by hand:
#   SCENE=hertz_friction TAG=stress_hertz_friction TARGET=20 \
#     bash benchmarks/benchmark_hertz.sh 2 6
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cold='subsection Refinement
  set Nested iteration = false
end'
nested_strategy='subsection Friction
  set Threshold iteration = nested
end'

# frictionless Hertz, every mesh from a cold start
EXTRA_PRM="$cold" bash benchmarks/benchmark_hertz.sh 2 5
# Coulomb friction, merged and nested threshold iteration, cold starts
SCENE=hertz_friction TAG=hertz_friction_merged TARGET=20 \
  EXTRA_PRM="$cold" bash benchmarks/benchmark_hertz.sh 2 5
SCENE=hertz_friction TAG=hertz_friction_nested TARGET=20 \
  EXTRA_PRM="$cold
$nested_strategy" bash benchmarks/benchmark_hertz.sh 2 4
# the defaults (nested iteration: each mesh starts from the previous one),
# against the targets of doc/performance.md: 1.5 linear solves frictionless,
# 2 with Coulomb friction
TAG=hertz_nested TARGET=1.5 bash benchmarks/benchmark_hertz.sh 2 5
SCENE=hertz_friction TAG=hertz_friction_merged_nested_iteration TARGET=2 \
  bash benchmarks/benchmark_hertz.sh 2 5
SCENE=hertz_friction TAG=hertz_friction_nested_nested_iteration TARGET=2 \
  EXTRA_PRM="$nested_strategy" bash benchmarks/benchmark_hertz.sh 2 5
# two elastic cylinders (a contact pair, dual mortar), frictionless: the
# defaults against 2.5 linear solves at >= 2e5 DoFs, and cold starts
SCENE=two_cylinders TAG=two_cylinders TARGET=2.5 \
  bash benchmarks/benchmark_hertz.sh 2 4
SCENE=two_cylinders TAG=two_cylinders_cold TARGET=2.5 \
  EXTRA_PRM="$cold" bash benchmarks/benchmark_hertz.sh 2 4
