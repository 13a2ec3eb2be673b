// Wall-clock timing of the phases of an algorithm, for the result structs and reports.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace hexadapt {

class Timer {
 public:
  Timer() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  void restart() { start_ = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point start_;
};

/// Ordered (phase name, seconds) pairs: the order is the order the phases ran.
using PhaseTimes = std::vector<std::pair<std::string, double>>;

}  // namespace hexadapt
