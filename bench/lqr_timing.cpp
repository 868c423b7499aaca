// Timing helper for bench/compare_scipy (not a Google Benchmark: it answers requests on stdin so
// that the script can interleave library solves with SciPy calls in one process pair).
//
//   solve I   -> "<microseconds> <status>"     one timed solveLqr of fixture state I (dt 0.01)
//   warm I N  -> "<median us> <failures>"      N back-to-back timed solves of state I
//   gain I    -> "<status> k00 k01 ... k39"    the 40 entries of K, row-major, 17 digits
//   count     -> number of states;  quit

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "gains_states.hpp"
#include "sdlqr/math/lqr.hpp"

int main(int argc, char** argv) {
  using namespace sdlqr;
  if (argc > 1) {
    std::cout << "usage: lqr_timing  (requests on stdin; see bench/compare_scipy)\n";
    return std::string(argv[1]) == "--help" ? 0 : 2;
  }
  std::vector<bench::GainsCase> cases = bench::loadGainsCases();
  for (bench::GainsCase& c : cases) c.dt = 0.01;
  const LqrParams params;
  std::string line;
  while (std::getline(std::cin, line)) {
    std::istringstream request(line);
    std::string command;
    size_t index = 0;
    request >> command >> index;
    if (command == "quit") break;
    if (command == "count") {
      std::cout << cases.size() << std::endl;
      continue;
    }
    if (index >= cases.size()) {
      std::cout << "error bad index" << std::endl;
      continue;
    }
    const bench::GainsCase& c = cases[index];
    if (command == "solve") {
      const auto start = std::chrono::steady_clock::now();
      const LqrResult result = solveLqr(c.x, c.u, params);
      const auto stop = std::chrono::steady_clock::now();
      std::cout << std::chrono::duration<double, std::micro>(stop - start).count() << " "
                << static_cast<int>(result.status) << std::endl;
    } else if (command == "warm") {
      int repeats = 1;
      request >> repeats;
      std::vector<double> samples;
      int failures = 0;
      for (int r = 0; r < std::max(1, repeats); ++r) {
        const auto start = std::chrono::steady_clock::now();
        const LqrResult result = solveLqr(c.x, c.u, params);
        const auto stop = std::chrono::steady_clock::now();
        failures += result.status != SolveStatus::kOk;
        samples.push_back(std::chrono::duration<double, std::micro>(stop - start).count());
      }
      std::sort(samples.begin(), samples.end());
      std::cout << samples[samples.size() / 2] << " " << failures << std::endl;
    } else if (command == "gain") {
      const LqrResult result = solveLqr(c.x, c.u, params);
      char buffer[32];
      std::cout << static_cast<int>(result.status);
      for (int i = 0; i < kInputDim; ++i) {
        for (int j = 0; j < kStateDim; ++j) {
          std::snprintf(buffer, sizeof(buffer), " %.17g", result.K(i, j));
          std::cout << buffer;
        }
      }
      std::cout << std::endl;
    } else {
      std::cout << "error unknown command" << std::endl;
    }
  }
  return 0;
}
