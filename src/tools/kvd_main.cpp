// The kvd command-line tool. Exit status: 0 success, 1 failed check, 2 bad
// input or usage (DESIGN.md section 6).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/tree/build.hpp"
#include "kvd/version.hpp"

namespace {

std::string usage() {
  std::string out =
      "usage: kvd [--help] [--version] <command> [options]\n"
      "\n"
      "Kinetic Vertical Decomposition trees with exact arithmetic.\n"
      "\n"
      "commands:\n";
  for (const auto& c : kvd::cli::commands) {
    std::string head = std::string("  ") + c.name + " " + c.argument;
    head.resize(std::max<std::size_t>(head.size() + 1, 17), ' ');
    out += head + c.what + "\n";
  }
  return out +
         "\n"
         "options:\n"
         "  -h, --help     print this help and exit\n"
         "  --version      print the version and exit\n"
         "\n"
         "Every command takes --help. Exit status: 0 success, 1 failed check,\n"
         "2 bad input or usage.\n";
}

// The command's status, unless what it wrote to standard output could not
// all be written (a full disk, a closed pipe: /dev/full), which is status 2:
// its output is lost.
int written(const std::string& command, int status) {
  std::cout.flush();
  if (std::fflush(stdout) == 0 && std::cout && !std::ferror(stdout)) return status;
  std::cerr << "kvd " << command << ": cannot write standard output\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << usage();
    return 2;
  }
  const std::string command = argv[1];
  if (command == "-h" || command == "--help") {
    std::cout << usage();
    return written("--help", 0);
  }
  if (command == "--version") {
    std::cout << "kvd " << kvd::version << "\n";
    return written("--version", 0);
  }
  kvd::cli::Args args(command, std::vector<std::string>(argv + 2, argv + argc));
  try {
    for (const auto& c : kvd::cli::commands)
      if (command == c.name) return written(command, c.run(args));
    std::cerr << "kvd: unknown command or option '" << command << "' (see kvd --help)\n";
    return 2;
  } catch (const kvd::cli::Usage_error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const kvd::cli::Kernel_failure& e) {
    std::cerr << e.what() << "\n";
    return 1;
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
