// The kvd command-line tool. Exit status: 0 success, 1 failed check, 2 bad
// input or usage (DESIGN.md section 6).
#include <cstring>
#include <iostream>
#include <string>

#include "kvd/version.hpp"

namespace {

const char* const usage =
    "usage: kvd [--help] [--version] <command> [options]\n"
    "\n"
    "Kinetic Vertical Decomposition trees with exact arithmetic.\n"
    "\n"
    "options:\n"
    "  -h, --help     print this help and exit\n"
    "  --version      print the version and exit\n"
    "\n"
    "No commands are available yet in this version; the scene, tree and\n"
    "simulation commands (info, generate, build, order, render, simulate,\n"
    "diff, bench, certify) come with the library layers that implement them.\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << usage;
    return 2;
  }
  const std::string arg = argv[1];
  if (arg == "-h" || arg == "--help") {
    std::cout << usage;
    return 0;
  }
  if (arg == "--version") {
    std::cout << "kvd " << kvd::version << "\n";
    return 0;
  }
  std::cerr << "kvd: unknown command or option '" << arg << "' (see kvd --help)\n";
  return 2;
}
