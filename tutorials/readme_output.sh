#!/bin/bash
# The screen output a tutorial's README.md quotes, kept equal to what the
# program prints. A quoted block is
#
#   <!-- begin output: NAME -->
#   ```
#   (lines of the screen output)
#   ```
#   <!-- end output: NAME -->
#
# and holds the paragraph of the screen output (its lines up to the next
# blank line) whose first line begins with NAME.
#
#   readme_output.sh update README.md screen.out
#       writes every quoted block anew from screen.out (make_results.sh);
#   readme_output.sh check README.md expected.out
#       exits 1 if a quoted block differs from its paragraph of expected.out,
#       if a NAME begins no paragraph or more than one, if a marker has no
#       partner or its block no fence, or if README.md quotes nothing
#       (ctest: tutorial_step-N_readme, tutorials/CMakeLists.txt).
#
# Wall times are masked in both texts before they are compared: README.md
# quotes a run with <Output/Print timing> = true, expected.out comes from one
# with false (tests/run_regression.cmake), and times change from run to run.
# The masks, for the times the tutorial programs print in wall seconds:
#   - " (0.127 s)": a number of seconds in parentheses, with the blanks
#     before it (step-1: each Uzawa line, the "contact solved" line);
#   - a header line ending in a column "<title> [s]": that title, and the
#     last field of each line below it up to the end of the paragraph
#     (step-1: "solve [s]" of the r study).
# Everything else must match character by character. A step that prints
# times in another form adds its mask to mask() below.
set -eo pipefail

usage() {
  echo "usage: $0 update|check README.md screen.out|expected.out" >&2
  exit 2
}
[ $# -eq 3 ] || usage
mode=$1
readme=$2
output=$3
case "$mode" in update | check) ;; *) usage ;; esac
for file in "$readme" "$output"; do
  [ -s "$file" ] || { echo "$0: no file $file, or it is empty" >&2; exit 2; }
done

# The awk program: the output file first (its paragraphs), then README.md.
# shellcheck disable=SC2016
program='
function mask(line) {
  gsub(/ +\([0-9]+\.[0-9]+ s\)/, "", line)
  if (line ~ / +[^ ]+ \[s\]$/) {
    sub(/ +[^ ]+ \[s\]$/, "", line)
    in_table = 1
  } else if (in_table)
    sub(/ +[^ ]+$/, "", line)
  return line
}
function fail(message) {
  print FILENAME ":" FNR ": " message > "/dev/stderr"
  failed = 1
}
# ---- the output: paragraph p has lines text[p, 1 .. size[p]]
FNR == NR {
  if ($0 == "") { open = 0; next }
  if (!open) { open = 1; ++n_paragraphs }
  text[n_paragraphs, ++size[n_paragraphs]] = $0
  next
}
# ---- README.md
/^<!-- begin output: .* -->$/ {
  if (name != "") fail("begin marker inside the block \"" name "\"")
  name = substr($0, 20, length($0) - 23)
  begin_line = FNR
  n_block = 0
  ++n_blocks
  if (mode == "update") print
  next
}
/^<!-- end output: .* -->$/ {
  end_name = substr($0, 18, length($0) - 21)
  if (name == "") { fail("end marker without a begin marker"); next }
  if (end_name != name)
    fail("end marker \"" end_name "\" closes the block \"" name "\"")
  finish_block()
  name = ""
  if (mode == "update") print
  next
}
name != "" { block[++n_block] = $0; next }
mode == "update" { print }
function finish_block(   p, found, i, lines) {
  found = 0
  for (p = 1; p <= n_paragraphs; ++p)
    if (index(text[p, 1], name) == 1) { ++found; lines = p }
  if (found != 1) {
    fail("\"" name "\" begins " (found ? found " paragraphs" : "no paragraph") \
         " of " output_file)
    if (mode == "update")  # keep the old block
      for (i = 1; i <= n_block; ++i) print block[i]
    return
  }
  if (mode == "update") {
    print "```"
    for (i = 1; i <= size[lines]; ++i) print text[lines, i]
    print "```"
    return
  }
  if (n_block < 2 || block[1] != "```" || block[n_block] != "```") {
    fail("the block \"" name "\" (line " begin_line ") is not one fenced block")
    return
  }
  if (n_block - 2 != size[lines])
    fail("the block \"" name "\" (line " begin_line ") has " n_block - 2 \
         " lines, " output_file " " size[lines])
  # the masks see each text whole, so that a table column spans its rows
  in_table = 0
  for (i = 1; i <= n_block - 2; ++i) quoted[i] = mask(block[i + 1])
  in_table = 0
  for (i = 1; i <= size[lines]; ++i) expected[i] = mask(text[lines, i])
  for (i = 1; i <= n_block - 2 && i <= size[lines]; ++i)
    if (quoted[i] != expected[i]) {
      fail("the block \"" name "\" differs from " output_file \
           " (timings masked) in its line " i ":\n  README:   " quoted[i] \
           "\n  expected: " expected[i])
      break
    }
}
END {
  if (name != "") fail("the block \"" name "\" has no end marker")
  if (n_blocks == 0) fail("no <!-- begin output: NAME --> marker")
  exit failed
}
'

if [ "$mode" = check ]; then
  awk -v mode=check -v output_file="$output" "$program" "$output" "$readme" ||
    { echo "$0: $readme quotes output that $output does not hold; run the" \
        "step's make_results.sh (and review its diff)" >&2; exit 1; }
  echo "$readme: every quoted block matches $output (timings masked)"
else
  temporary=$(mktemp "$readme.XXXXXX")
  trap 'rm -f "$temporary"' EXIT
  awk -v mode=update -v output_file="$output" "$program" "$output" "$readme" \
    > "$temporary"
  cat "$temporary" > "$readme"
  echo "$readme: quoted blocks written from $output"
fi
