// The table of kvd's commands: one line each. A command is a function
// `int NAME(Args&)` in src/tools/cmd_NAME.cpp (found by CMake) and a line
// here; kvd_main.cpp dispatches on the table and prints it as the usage.
#pragma once

#include "cli.hpp"

// X(NAME, ARGUMENT, WHAT): the command, its main argument, one line of help.
#define KVD_COMMANDS(X)                                                                   \
  X(info, "SCENE", "validate a scene file and print its counts")                           \
  X(generate, "FAM", "write a generated scene (the thesis's data sets and more)")          \
  X(build, "SCENE", "build the KVD at an instant and print its statistics")                \
  X(order, "SCENE", "list triangle fragments back to front from a viewpoint")              \
  X(render, "SCENE", "paint the decomposition from a viewpoint (SVG or PNG)")              \
  X(animate, "SCENE", "film a run from a viewpoint (SVG, MP4 or GIF), events held")        \
  X(simulate, "SCENE", "run the kinetic KVD (exact events, symbolic batches)")             \
  X(certify, "SCENE", "write an event-order certificate of the exact simulation")          \
  X(diff, "SCENE", "compare a floating-point simulation with the exact one")               \
  X(bench, "SUITE", "benchmarks: accuracy, thesis, update, cost, aeg, aeg-cost")       \
  X(import, "MESH", "an OBJ, OFF or PLY mesh as a scene, read exactly")                  \
  X(view, "SCENE", "an interactive HTML page of a run (3D, timeline, tree, diff)")

namespace kvd::cli {

#define KVD_DECLARE_COMMAND(name, argument, what) int name(Args& args);
KVD_COMMANDS(KVD_DECLARE_COMMAND)
#undef KVD_DECLARE_COMMAND

struct Command {
  const char* name;
  const char* argument;
  const char* what;
  int (*run)(Args&);
};

#define KVD_COMMAND_ENTRY(name, argument, what) Command{#name, argument, what, &name},
inline constexpr Command commands[] = {KVD_COMMANDS(KVD_COMMAND_ENTRY)};
#undef KVD_COMMAND_ENTRY

}  // namespace kvd::cli
