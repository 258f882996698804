#include "gnuplot.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "cli.hpp"

namespace kvd::bench {

bool run_gnuplot(const std::string& suite, const std::string& script_path, const std::string& script,
                 const std::vector<std::string>& outputs) {
  const std::string who = "kvd bench " + suite;
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
    std::cerr << who << ": gnuplot not found (apt-get install gnuplot-nox): no plot\n";
    return false;
  }
  if (script_path.find('\'') != std::string::npos) throw cli::Usage_error(who + ": --out must not contain a quote");
  cli::write_atomically("bench " + suite, script_path, script);
  const std::string command = "gnuplot '" + script_path + "'";
  if (std::system(command.c_str()) != 0) {
    for (const std::string& o : outputs) std::filesystem::remove(o);
    std::cerr << who << ": gnuplot failed; the CSV and the tables are written\n";
    return false;
  }
  return true;
}

}  // namespace kvd::bench
