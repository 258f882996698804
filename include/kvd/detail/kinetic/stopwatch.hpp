// Wall-clock seconds since construction: the timings a run reports
// (Batch::*_seconds, construction_seconds, a differential run's seconds).
#pragma once

#include <chrono>

namespace kvd::kinetic {

class Stopwatch {
public:
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace kvd::kinetic
