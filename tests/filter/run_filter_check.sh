#!/bin/bash
# The exact kernel's interval filter changes no answer: on one scene, kvd
# simulate with and without --no-filter writes the same trace and ends at the
# same structure hash. Usage: run_filter_check.sh KVD SCENE EVENTS WORKDIR
set -euo pipefail
kvd=$1 scene=$2 events=$3 dir=$4
mkdir -p "$dir"
name=$(basename "$scene" .json)
hash_of() { sed -n 's/.*"structure_hash": "\([0-9a-f]*\)".*/\1/p' "$1"; }
"$kvd" simulate "$scene" --events "$events" --validate every --trace "$dir/$name.filtered" --json > "$dir/$name.filtered.json"
"$kvd" simulate "$scene" --events "$events" --validate every --no-filter --trace "$dir/$name.exact" --json \
  > "$dir/$name.exact.json"
cmp "$dir/$name.filtered" "$dir/$name.exact"
a=$(hash_of "$dir/$name.filtered.json") b=$(hash_of "$dir/$name.exact.json")
test -n "$a" && test "$a" = "$b"
echo "$name: same trace ($(wc -l < "$dir/$name.exact") lines) and structure hash $a"
