// sdlqr-deploy: checks a deployment file against the stack table and prints its description for
// scripts/deploy (which builds the emulated hosts and starts each process on its host).

#include <iostream>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/deploy/deployment.hpp"

using namespace sdlqr;

int main(int argc, char** argv) {
  return runMain("sdlqr-deploy", [&] {
    std::string describe_path, procs_path;
    ArgParser parser("sdlqr-deploy", "Which emulated host runs which process (config/deploy/*.yaml).");
    parser.addOption("--describe", &describe_path, "FILE", "check FILE and print one key=value line per field and host");
    parser.addOption("--procs", &procs_path, "FILE",
                     "the stack table whose processes FILE places, when FILE names none (key procs)");
    parser.setEpilog(
        "example: sdlqr-deploy --describe config/deploy/three_hosts.yaml --procs config/stack.procs\n"
        "exit codes: 0 valid, 2 bad option or an invalid FILE (the error names the key)");
    parser.parseOrExit(argc, argv);
    if (describe_path.empty() || procs_path.empty()) throw std::invalid_argument("give --describe FILE and --procs FILE");
    const std::string named = deploy::deploymentProcs(describe_path);
    if (!named.empty()) procs_path = named;
    std::cout << deploy::describe(deploy::loadDeployment(describe_path, deploy::stackProcessNames(procs_path)));
    return 0;
  });
}
