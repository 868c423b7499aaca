#pragma once
// Runs another program (sbatch, squeue, scontrol) without a shell: no quoting of paths, its
// standard output and error captured.

#include <string>
#include <vector>

namespace sdlqr::batch {

struct CommandResult {
  int status = 0;      // exit code; 128 + signal when killed; 127 when it could not be started
  std::string out;     // standard output
  std::string error;   // standard error (or why it could not be started)
  bool ok() const { return status == 0; }
};

// argv[0] is looked up on PATH.
CommandResult runCommand(const std::vector<std::string>& argv);

}  // namespace sdlqr::batch
