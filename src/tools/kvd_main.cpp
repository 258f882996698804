// The kvd command-line tool. Exit status: 0 success, 1 failed check, 2 bad
// input or usage (DESIGN.md section 6).
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/version.hpp"

namespace {

const char* const usage =
    "usage: kvd [--help] [--version] <command> [options]\n"
    "\n"
    "Kinetic Vertical Decomposition trees with exact arithmetic.\n"
    "\n"
    "commands:\n"
    "  info SCENE     validate a scene file and print its counts\n"
    "  generate FAM   write a generated scene (the thesis's data sets and more)\n"
    "  build SCENE    build the KVD at an instant and print its statistics\n"
    "  order SCENE    list triangle fragments back to front from a viewpoint\n"
    "  render SCENE   paint the decomposition from a viewpoint (SVG or PNG)\n"
    "  simulate SCENE run the kinetic KVD (exact events, symbolic batches)\n"
    "  certify SCENE  write an event-order certificate of the exact simulation\n"
    "  diff SCENE     compare a floating-point simulation with the exact one\n"
    "  bench SUITE    benchmarks: accuracy (error against run time), thesis\n"
    "                 (the thesis's Figures 8.4-8.9 and the cost of exactness)\n"
    "\n"
    "options:\n"
    "  -h, --help     print this help and exit\n"
    "  --version      print the version and exit\n"
    "\n"
    "Every command takes --help. Exit status: 0 success, 1 failed check,\n"
    "2 bad input or usage.\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << usage;
    return 2;
  }
  const std::string command = argv[1];
  if (command == "-h" || command == "--help") {
    std::cout << usage;
    return 0;
  }
  if (command == "--version") {
    std::cout << "kvd " << kvd::version << "\n";
    return 0;
  }
  kvd::cli::Args args(command, std::vector<std::string>(argv + 2, argv + argc));
  try {
    if (command == "info") return kvd::cli::info(args);
    if (command == "generate") return kvd::cli::generate(args);
    if (command == "build") return kvd::cli::build(args);
    if (command == "order") return kvd::cli::order(args);
    if (command == "render") return kvd::cli::render(args);
    if (command == "simulate") return kvd::cli::simulate(args);
    if (command == "certify") return kvd::cli::certify(args);
    if (command == "diff") return kvd::cli::diff(args);
    if (command == "bench") return kvd::cli::bench(args);
    std::cerr << "kvd: unknown command or option '" << command << "' (see kvd --help)\n";
    return 2;
  } catch (const kvd::cli::Usage_error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const kvd::scene::Scene_error& e) {
    std::cerr << "kvd " << command << ": " << e.what() << "\n";
    return 2;
  } catch (const kvd::tree::Build_error& e) {
    // Triangles that cross where a command needs them disjoint: bad input.
    std::cerr << "kvd " << command << ": " << e.what() << "\n";
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "kvd " << command << ": out of memory\n";
    return 2;
  } catch (const std::exception& e) {
    // A failure of kvd itself, never std::terminate: reported as a failed check.
    std::cerr << "kvd " << command << ": internal error: " << e.what() << "\n";
    return 1;
  }
}
