#!/usr/bin/env bash
# A parameter sweep: run one scene once per value of one entry (dualcontact's
# --set), take one figure from the last row of each run's cycles.csv, and
# write them as a table (CSV) and a figure (SVG, with gnuplot).
#
#   bash contrib/sweep.sh [--set "Subsection/Entry=value" ...]
#
# Settings, as environment variables [default]:
#   SCENE    the scene                                [prm/hertz_friction.prm]
#   ENTRY    the entry that varies                    [Friction/Coefficient]
#   VALUES   its values                               [0.1 0.2 0.3 0.4 0.5]
#   COLUMN   the column of cycles.csv to collect      [stick_nodes]
#   OUT      folder for the runs, table and figure    [sweep]
#   NP       MPI ranks per run                        [2]
#   PROGRAM  the dualcontact program                  [build/dualcontact]
# The arguments go to every run: more overrides, e.g.
#   bash contrib/sweep.sh --set "Refinement/Number of cycles=1"
# Each run also gets --set "Output/Directory=OUT/run_<k>" and --set
# "Output/Write vtu=false".
#
# Writes, in OUT:
#   run_<k>/       the output of run k (cycles.csv, parameters.prm with its
#                  value, ...), run_<k>.out its screen output
#   sweep.csv      one row per value: the value, COLUMN, and the cells and
#                  DoFs of the last mesh
#   sweep.svg      COLUMN against the value (if gnuplot is installed)
# Relative paths are taken from the directory the script is called from.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scene="${SCENE:-$repo/prm/hertz_friction.prm}"
entry="${ENTRY:-Friction/Coefficient}"
values="${VALUES:-0.1 0.2 0.3 0.4 0.5}"
column="${COLUMN:-stick_nodes}"
out="${OUT:-sweep}"
np="${NP:-2}"
program="${PROGRAM:-$repo/build/dualcontact}"

if [ ! -x "$program" ]; then
  echo "sweep: no program $program (build first: bash contrib/build.sh)" >&2
  exit 1
fi
# Open MPI refuses to run as root without these.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

mkdir -p "$out"
table="$out/sweep.csv"
echo "$entry,$column,cells,dofs" > "$table"
k=0
for value in $values; do
  run="$out/run_$k"
  rm -rf "$run"
  echo "sweep: $entry = $value -> $run/"
  mpirun -np "$np" "$program" "$scene" --set "$entry=$value" \
    --set "Output/Directory=$run" --set "Output/Write vtu=false" \
    "$@" > "$run.out"
  # the named column of the last row of cycles.csv
  awk -F, -v column="$column" -v value="$value" '
    NR == 1 { for (i = 1; i <= NF; ++i) index_of[$i] = i; next }
    { last = $0 }
    END {
      if (!(column in index_of)) {
        print "sweep: cycles.csv has no column " column > "/dev/stderr"
        exit 1
      }
      n = split(last, field, ",")
      print value "," field[index_of[column]] "," field[index_of["cells"]] \
            "," field[index_of["dofs"]]
    }' "$run/cycles.csv" >> "$table"
  k=$((k + 1))
done
echo "sweep: table $table"
cat "$table"

if command -v gnuplot > /dev/null; then
  gnuplot <<EOF
set terminal svg size 640,420 dynamic font "sans,12"
set output '$out/sweep.svg'
set datafile separator ','
set key off
set grid
set xlabel '$entry' noenhanced
set ylabel '$column (last mesh)' noenhanced
set title 'dualcontact: $(basename "$scene") for several $entry' noenhanced
plot '$table' using 1:2 skip 1 with linespoints pointtype 7
EOF
  echo "sweep: figure $out/sweep.svg"
else
  echo "sweep: gnuplot not found, no figure (apt-get install gnuplot-nox)"
fi
