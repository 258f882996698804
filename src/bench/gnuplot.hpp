// The plots of `kvd bench`: a gnuplot script written beside its data and run.
#pragma once

#include <string>
#include <vector>

namespace kvd::bench {

// Writes `script` to `script_path` and runs gnuplot on it; whether it wrote
// the plots `outputs`. Without gnuplot on the PATH, or when it fails, says
// so on stderr as `kvd bench SUITE: ...`, leaves no plot behind, and returns
// false: the tables are written all the same.
bool run_gnuplot(const std::string& suite, const std::string& script_path, const std::string& script,
                 const std::vector<std::string>& outputs);

}  // namespace kvd::bench
