#!/bin/bash
# Options that must change no answer: on one scene, kvd simulate under each
# set of flags writes the same trace, byte for byte, and ends at the same
# structure hash as under the first. Every run validates the tree in force
# after every batch unless its flags say otherwise.
# Usage: same_run.sh KVD SCENE EVENTS WORKDIR LABEL "FLAGS" [LABEL "FLAGS" ...]
set -euo pipefail
kvd=$1 scene=$2 events=$3 dir=$4
shift 4
mkdir -p "$dir"
name=$(basename "$scene" .json)
hash_of() { sed -n 's/.*"structure_hash": "\([0-9a-f]*\)".*/\1/p' "$1"; }
first="" first_hash=""
while [ $# -ge 2 ]; do
  label=$1 flags=$2
  shift 2
  out="$dir/$name.$label"
  # shellcheck disable=SC2086  # the flags are words
  "$kvd" simulate "$scene" --events "$events" --validate every $flags --trace "$out" --json > "$out.json"
  h=$(hash_of "$out.json")
  test -n "$h"
  if [ -z "$first" ]; then
    first=$out first_hash=$h
  else
    cmp "$first" "$out"
    test "$h" = "$first_hash"
  fi
  echo "$name, $label: $(wc -l < "$out") trace lines, structure hash $h"
done
