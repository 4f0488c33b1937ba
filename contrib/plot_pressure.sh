#!/usr/bin/env bash
# The contact pressure along Gamma_C from a run's contact_NN.csv, against
# the exact pressure where the scene gives one (<Exact solution/Contact
# pressure>: the column exact_pressure), drawn with gnuplot.
#
#   bash contrib/plot_pressure.sh [folder] [cycle] [figure]
#
# folder  the run's output folder (default: output)
# cycle   the cycle to draw (default: the last one in the folder)
# figure  the file to write, .svg or .png (default: <folder>/pressure_NN.svg)
#
# The abscissa is s = x . t, the position along the mean tangent t of
# Gamma_C (2D: the rows are in this order). Nodes are marked by their
# status: in contact (stick, or contact without friction), slip, separated.
# Needs gnuplot (Debian: apt-get install gnuplot-nox).
set -euo pipefail

folder="${1:-output}"
cycle="${2:-}"
if [[ -z "$cycle" ]]; then
  last="$(ls "$folder"/contact_[0-9]*.csv 2>/dev/null | sort | tail -n 1 || true)"
  if [[ -z "$last" ]]; then
    echo "plot_pressure: no contact_NN.csv in '$folder' (a scene with contact writes one per cycle)" >&2
    exit 1
  fi
  cycle="$(basename "$last" .csv)"
  cycle="${cycle#contact_}"
fi
csv="$folder/contact_$(printf '%02d' "$((10#$cycle))").csv"
if [[ ! -f "$csv" ]]; then
  echo "plot_pressure: no file $csv" >&2
  exit 1
fi
figure="${3:-$folder/pressure_$(printf '%02d' "$((10#$cycle))").svg}"
if ! command -v gnuplot > /dev/null; then
  echo "plot_pressure: gnuplot is missing (Debian: apt-get install gnuplot-nox)" >&2
  exit 1
fi

case "$figure" in
  *.png) terminal="pngcairo size 900,600"
         gnuplot -e "set terminal pngcairo" > /dev/null 2>&1 || terminal="png size 900,600" ;;
  *)     terminal="svg size 900,600 dynamic" ;;
esac
exact=0
head -n 1 "$csv" | grep -q 'exact_pressure' && exact=1

# one series of points per status the file has (the status is the 11th
# column in 2D, the 15th in 3D: the one named 'status')
column="$(head -n 1 "$csv" | tr ',' '\n' | grep -n '^status$' | cut -d: -f1)"
series=""
for status in stick contact slip separated; do
  if cut -d, -f"$column" "$csv" | grep -qx "$status"; then
    case "$status" in
      stick)     style="pt 7 ps 0.5 lc rgb '#1f77b4'"; title="stick" ;;
      contact)   style="pt 7 ps 0.5 lc rgb '#1f77b4'"; title="in contact" ;;
      slip)      style="pt 7 ps 0.6 lc rgb '#d62728'"; title="slip" ;;
      separated) style="pt 6 ps 0.5 lc rgb '#7f7f7f'"; title="separated" ;;
    esac
    series="$series, '' using 's':(on('$status')) with points $style title '$title'"
  fi
done
if [[ $exact == 1 ]]; then
  series="$series, '' using 's':'exact_pressure' with lines lw 1.5 dt 2 lc rgb '#000000' title 'exact'"
fi

gnuplot <<GNUPLOT
set terminal $terminal
set output '$figure'
set datafile separator ','
set key top right
set grid
set xlabel 's = x . t along {/Symbol G}_C'
set ylabel 'contact pressure l1'
set title 'Contact pressure, cycle $((10#$cycle)) ($csv)' noenhanced
# the abscissa: the zone in contact (l1 > 0) and half its width on each
# side, within the contact boundary
stats '$csv' using 's' nooutput
s_min = STATS_min; s_max = STATS_max
stats '$csv' using (column('l1') > 0 ? column('s') : NaN) nooutput
if (STATS_records > 0) { w = STATS_max - STATS_min; if (w <= 0) { w = s_max - s_min }; \
  lo = STATS_min - 0.5 * w; hi = STATS_max + 0.5 * w; \
  set xrange [(lo < s_min ? s_min : lo):(hi > s_max ? s_max : hi)] }
set yrange [0:*]
# a status's rows: their l1, 1/0 (no point) elsewhere
on(status) = (strcol('status') eq status) ? column('l1') : 1/0
plot '$csv' using 's':'l1' with lines lw 2 lc rgb '#1f77b4' title 'l1 (computed)'$series
GNUPLOT
echo "plot_pressure: $figure"
