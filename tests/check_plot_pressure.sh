#!/usr/bin/env bash
# The test plot_pressure: prm/hertz.prm (one cycle), then
# contrib/plot_pressure.sh on its output folder. Passes if contact_00.csv has
# the exact_pressure column (the scene gives <Exact solution/Contact
# pressure>) and the script draws output/pressure_00.svg with the computed
# and the exact pressure. Skipped (exit 77) without gnuplot.
#   bash check_plot_pressure.sh <source dir> <dualcontact> <work dir>
set -euo pipefail
source_dir="$1"
program="$2"
work="$3"
rm -rf "$work"
mkdir -p "$work"
cd "$work"

fail() {
  echo "check_plot_pressure: $*" >&2
  exit 1
}
"$program" "$source_dir/prm/hertz.prm" --set "Refinement/Number of cycles=1" \
  --set "Output/Write vtu=false" --set "Output/Print timing=false" > screen.out
head -1 output/contact_00.csv | grep -q ',exact_pressure$' ||
  fail "output/contact_00.csv has no column exact_pressure: $(head -1 output/contact_00.csv)"
if ! command -v gnuplot > /dev/null; then
  echo "check_plot_pressure: gnuplot is not installed: skipped"
  exit 77
fi
bash "$source_dir/contrib/plot_pressure.sh" output
grep -q "<svg" output/pressure_00.svg || fail "no figure output/pressure_00.svg"
for title in "l1 (computed)" "exact" "in contact" "separated"; do
  grep -q "$title" output/pressure_00.svg || fail "the figure has no curve '$title'"
done
echo "check_plot_pressure: output/pressure_00.svg"
