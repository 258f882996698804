#!/usr/bin/env bash
# CTest consumer_project: installs this build into a scratch prefix, then
# configures, builds and runs examples/consumer against it with
# find_package(KVD CONFIG REQUIRED), as a user's project would.
# Usage: run_consumer.sh BUILD_DIR SOURCE_DIR SCRATCH_DIR
set -euo pipefail
build="$1" src="$2" scratch="$3"
rm -rf "$scratch"
cmake --install "$build" --prefix "$scratch/prefix" > /dev/null
cmake -S "$src/examples/consumer" -B "$scratch/build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$scratch/prefix" > /dev/null
cmake --build "$scratch/build" > /dev/null
out="$("$scratch/build/kvd_consumer")"
echo "$out"
# The three events of the slide out, mirrored after the turn at t = 5 (the
# triangle is where it was at 4, 3 and 2 at 6, 7 and 8), and a validated run.
[ "$(grep "^t = " <<< "$out" | cut -d: -f1 | tr '\n' ' ')" = "t = 2 t = 3 t = 4 t = 6 t = 7 t = 8 " ]
grep -q '^validated against fresh builds: yes$' <<< "$out"
grep -q "^back to front from (0, 0, 50): T(0) T(0) T(1) T(1)$" <<< "$out"
