#!/usr/bin/env bash
# Work-precision study by element shape: FE_SimplexP on triangles and
# tetrahedra beside FE_Q on quadrilaterals and hexahedra, on the scenes and
# with the error measures of the degree study, and what the replicated mesh
# of simplices costs per rank. It is benchmarks/work_precision_degree.sh
# with CELLS="quadrilateral simplex": that script's header says what is run
# and written (doc/results_shape.md, doc/figures/shape/) and lists the
# environment variables.
#
#   bash benchmarks/work_precision_shape.sh
#
# With the degree study's WORK and REUSE=1 only the simplices and the
# memory runs are made (the quadrilateral runs have the same names):
#   WORK=/tmp/wp bash benchmarks/work_precision_degree.sh
#   WORK=/tmp/wp REUSE=1 bash benchmarks/work_precision_shape.sh
set -euo pipefail
export CELLS="${CELLS:-quadrilateral simplex}"
exec bash "$(dirname "${BASH_SOURCE[0]}")/work_precision_degree.sh" "$@"
