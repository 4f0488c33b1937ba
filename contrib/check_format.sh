#!/usr/bin/env bash
# Check (or, with --fix, apply) the formatting of every C++ file against
# .clang-format. Needs clang-format 14 (Debian: apt-get install clang-format).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mapfile -t files < <(git ls-files '*.h' '*.cc')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
else
  clang-format --dry-run -Werror "${files[@]}"
  echo "check_format: ${#files[@]} files formatted as .clang-format says"
fi
