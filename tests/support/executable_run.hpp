#pragma once
// Runs a built executable as a user would, for the tests of its command line (--help, options,
// one-line errors and exit codes).

#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace sdlqr::testing {

struct ExecutableRun {
  int exit_code = -1;  // -1: it did not exit (a signal) or could not start
  std::string output;  // stdout and stderr
};

// bin/<name> of the build folder, with `arguments` as a shell would split them.
inline ExecutableRun runExecutable(const std::string& name, const std::string& arguments) {
  const std::string command = std::string(SDLQR_BINARY_DIR) + "/bin/" + name + " " + arguments + " 2>&1";
  ExecutableRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) run.output += buffer;
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace sdlqr::testing
