#!/bin/sh
# The core's files call one another in one direction: each file calls
# functions only of the files listed after it in the map at the top of
# src/core/internal.h, so no two files call each other, directly or
# round a loop. From the sources with their comments removed, a file's
# functions are the non-static ones it defines (a definition starts in
# the first column) and its calls are the names of those followed by "(".
# Ends with a Unity-style summary for tests/run.sh.
cd "$(dirname "$0")/../.." || exit 1
dir=src/core
map=$(sed -n '1,/\*\//s/^ \*   \([a-z_0-9]*\.c\) .*/\1/p' $dir/internal.h)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for f in $dir/*.c; do
    # comments and string literals out, so that names in them are not calls
    awk '
    { line = $0; out = ""
      while (line != "") {
          if (incomment) {
              i = index(line, "*/")
              if (i == 0) { line = ""; break }
              line = substr(line, i + 2); incomment = 0; continue
          }
          c = index(line, "/*"); d = index(line, "//"); q = index(line, "\"")
          first = 0
          if (c && (!first || c < first)) first = c
          if (d && (!first || d < first)) first = d
          if (q && (!first || q < first)) first = q
          if (!first) { out = out line; break }
          out = out substr(line, 1, first - 1)
          if (first == c) { incomment = 1; line = substr(line, c + 2) }
          else if (first == d) { line = "" }
          else { rest = substr(line, q + 1); e = match(rest, /^([^"\\]|\\.)*"/)
                 line = e ? substr(rest, RLENGTH + 1) : "" }
      }
      print out }' "$f" > "$tmp/$(basename "$f").src"
done
failures=0; tests=0
report() { tests=$((tests + 1)); if [ -n "$2" ]; then echo "$1: FAIL: $2"; failures=$((failures + 1)); else echo "$1: PASS"; fi; }
# every file of the core is on the map
missing=""
for f in $dir/*.c; do
    b=$(basename "$f")
    echo "$map" | grep -qx "$b" || missing="$missing $b"
done
report "every_core_file_should_be_on_the_map_in_internal_h" "${missing:+not on the map:$missing}"
# definitions: name -> file
for s in "$tmp"/*.src; do
    b=$(basename "$s" .src)
    grep -E '^[A-Za-z_][A-Za-z0-9_ *]*[ *]mote_[A-Za-z0-9_]*\(' "$s" | grep -vE '^(static|MOTE__|typedef|extern)' \
        | grep -v ';[[:space:]]*$' | sed -E 's/^.*[ *](mote_[A-Za-z0-9_]*)\(.*$/\1/' | sed "s/\$/ $b/"
done | sort -u > "$tmp/defs"
# calls: file -> defining file
for s in "$tmp"/*.src; do
    b=$(basename "$s" .src)
    grep -oE 'mote_[A-Za-z0-9_]*[[:space:]]*\(' "$s" | sed -E 's/[[:space:]]*\($//' | sort -u \
        | while read -r fn; do
            to=$(awk -v fn="$fn" '$1 == fn { print $2; exit }' "$tmp/defs")
            [ -n "$to" ] && [ "$to" != "$b" ] && echo "$b $to $fn"
        done
done > "$tmp/calls"
# each call goes down the map
up=$(awk -v map="$map" '
    BEGIN { n = split(map, m, "\n"); for (i = 1; i <= n; i++) pos[m[i]] = i }
    { if (!($1 in pos) || !($2 in pos) || pos[$1] >= pos[$2]) printf "%s calls %s (%s); ", $1, $2, $3 }' "$tmp/calls")
report "core_files_should_call_only_files_below_them_on_the_map" "$up"
# and so no two files call each other
pairs=$(awk '{ e[$1 " " $2] = 1 } END { for (k in e) { split(k, p, " "); if ((p[2] " " p[1]) in e && p[1] < p[2]) printf "%s <-> %s; ", p[1], p[2] } }' "$tmp/calls")
report "no_two_core_files_should_call_each_other" "$pairs"
echo "$(wc -l < "$tmp/calls") calls between core files, $(wc -l < "$tmp/defs") functions"
echo "-----------------------"
echo "$tests Tests $failures Failures 0 Ignored"
[ "$failures" -eq 0 ]
