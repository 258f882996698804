#!/usr/bin/env bash
# Remakes every committed table and plot under data/bench/, then the copies
# of its tables in README.md and data/stiff/README.md (splice.py). Timings
# are this machine's; everything else must come out the same anywhere, and
# CTest bench_reproduces checks that it does.
# Usage: data/bench/regenerate.sh [path/to/kvd] (default: build/kvd of this checkout);
# kvd_bench_next_root is taken from the same folder.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
kvd="$(realpath "${1:-$root/build/kvd}")"
cd "$root"
"$kvd" bench accuracy --out data/bench
"$kvd" bench thesis --sizes 25,50,100,200,400,800 --events 1000 --out data/bench
"$kvd" bench update --out data/bench
"$kvd" bench cost --out data/bench
"$kvd" bench aeg --out data/bench
"$kvd" bench aeg-cost --out data/bench
# Beside kvd in a build with CGAL (the default): our isolator against CGAL's.
"$(dirname "$kvd")/kvd_bench_next_root" --degrees 1,2,4,6,8 --bits 64,200 --count 1000 --out data/bench
python3 data/bench/splice.py
