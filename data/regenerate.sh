#!/usr/bin/env bash
# Regenerates the thesis's data sets (chapter 8.2) byte for byte:
# uniform-scale and uniform-density at 25 ... 800 triangles, all moving
# linearly, seed 1. Usage: data/regenerate.sh [path/to/kvd] (default: build/kvd of this checkout).
set -euo pipefail
kvd="$(realpath "${1:-$(dirname "$0")/../build/kvd}")"
cd "$(dirname "$0")"
for family in uniform-scale uniform-density; do
  for n in 25 50 100 200 400 800; do
    "$kvd" generate "$family" --triangles "$n" --moving 1 --degree 1 --seed 1 -o "$family-$n.json"
  done
done
