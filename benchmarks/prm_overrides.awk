# The 'set' lines of a .prm text as "Subsection/Entry=value", one per line:
# the --set arguments that override a scene's entries with those of the
# text (a second 'set' of an entry in one file is an input error, so the
# benchmark scripts pass their overrides this way).
#   awk -f benchmarks/prm_overrides.awk overrides.prm
{ line = $0; sub(/#.*/, "", line); gsub(/^[ \t]+|[ \t]+$/, "", line) }
line ~ /^subsection[ \t]/ { name = line; sub(/^subsection[ \t]+/, "", name); path[++depth] = name; next }
line == "end" { if (depth > 0) --depth; next }
line ~ /^set[ \t]/ {
  key = line; sub(/^set[ \t]+/, "", key); value = key
  sub(/[ \t]*=.*/, "", key); sub(/^[^=]*=[ \t]*/, "", value)
  full = ""; for (i = 1; i <= depth; ++i) full = full path[i] "/"
  print full key "=" value
}
