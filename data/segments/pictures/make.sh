#!/usr/bin/env bash
# Makes the pictures of the cylindrical BSP of segments in this folder again,
# byte for byte: data/segments/pictures/make.sh [KVD [OUT]] (KVD: the kvd
# binary, default build/kvd of this repository; OUT: the folder to write,
# default this one; CTest writes elsewhere and compares).
set -euo pipefail
src=$(cd "$(dirname "$0")" && pwd)
scenes=$src/..
kvd=${1:-$src/../../../build/kvd}
here=${2:-$src}
mkdir -p "$here"

"$kvd" render "$scenes/two-crossing.json" -o "$here/two-crossing.svg"
"$kvd" render "$scenes/concurrent-three.json" --time 0 -o "$here/concurrent-three.svg"
# The sinker passes over the floor's right endpoint at t = 3 (an edge event).
"$kvd" render "$scenes/over-endpoint.json" --time 2 -o "$here/over-endpoint-before.svg"
"$kvd" render "$scenes/over-endpoint.json" --time 13/4 -o "$here/over-endpoint-after.svg"
# The needle is vertical at t = 1 (a flip).
"$kvd" render "$scenes/turning-vertical.json" --time 1/2 -o "$here/turning-vertical-before.svg"
"$kvd" render "$scenes/turning-vertical.json" --time 3/2 -o "$here/turning-vertical-after.svg"
"$kvd" render "$scenes/random-100.json" -o "$here/random-100.svg"
# A film of six moving segments: vertex, edge and intersection events.
"$kvd" generate segments-random --n 6 --length 0.4 --moving 1 --seed 3 -o "$here/random-6-moving.json" 2>/dev/null
"$kvd" animate "$here/random-6-moving.json" --frames 20 -o "$here/random-6-moving.svg" >/dev/null
