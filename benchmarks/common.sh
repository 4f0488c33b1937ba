# shellcheck shell=bash disable=SC2034
# What the benchmark scripts share; each sources it after `set -euo
# pipefail`, with the name it gives its messages:
#
#   . "$(dirname "${BASH_SOURCE[0]}")/common.sh" <script name>
#
# It sets
#   benchmarks   this folder, repo the repository root, doc its doc/ folder
#   bin          the program: $DUALCONTACT if set, else build/dualcontact
#                (the script stops with status 2 if it is not executable)
#   bin_shown    the program as the pages in doc/ show it (repo_path)
# and defines
#   last_value F C  the value of column C in the last row of the CSV file F
#                ('' if the column is absent)
#   repo_path P  P as seen from the repository root: '.', a path below it,
#                or '<name outside the repository>' for anything else, so
#                that no page shows an absolute path of the machine that
#                ran it.

benchmark_name="${1:?common.sh needs the name of the script that sources it}"
benchmarks="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)"
repo="$(cd "$benchmarks/.." && pwd -P)"
doc="$repo/doc"
bin="${DUALCONTACT:-$repo/build/dualcontact}"
if [ ! -x "$bin" ]; then
  echo "$benchmark_name: no program at '$bin'; build it (bash contrib/build.sh) or set DUALCONTACT=<path to dualcontact>" >&2
  exit 2
fi

repo_path() {
  local p
  p="$(realpath -m -- "$1" 2>/dev/null || printf '%s' "$1")"
  case "$p" in
    "$repo") printf '.' ;;
    "$repo"/*) printf '%s' "${p#"$repo"/}" ;;
    *) printf '<%s outside the repository>' "$(basename -- "$p")" ;;
  esac
}
bin_shown="$(repo_path "$bin")"

# The value of column $2 in the last row of the CSV file $1 ('' if absent).
last_value() {
  awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
    { v = (c ? $c : "") } END { print v }' "$1"
}
