// The command-line contract: --help, --version, and exit status 2 on misuse.
#include <sys/wait.h>

#include <array>
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

#include "kvd/version.hpp"

namespace {

struct Run {
  int status;
  std::string out;
};

Run run(const std::string& args) {
  const std::string cmd = std::string(KVD_EXECUTABLE) + " " + args + " 2>/dev/null";
  FILE* pipe = popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string out;
  std::array<char, 256> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  const int raw = pclose(pipe);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

}  // namespace

TEST_CASE("kvd --help prints usage and succeeds", "[cli]") {
  for (const char* flag : {"--help", "-h"}) {
    const Run r = run(flag);
    CHECK(r.status == 0);
    CHECK(r.out.find("usage: kvd") != std::string::npos);
  }
}

TEST_CASE("kvd --version prints the project version", "[cli]") {
  const Run r = run("--version");
  CHECK(r.status == 0);
  CHECK(r.out == std::string("kvd ") + kvd::version + "\n");
}

TEST_CASE("kvd rejects misuse with exit status 2", "[cli]") {
  CHECK(run("").status == 2);
  CHECK(run("no-such-command").status == 2);
  CHECK(run("--no-such-flag").status == 2);
}
