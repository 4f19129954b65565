// Runs the `fissure` command line the build made (FISSURE_APP) in a folder,
// as a user types it there, for the tests of its options and exit codes.
#pragma once

#include <filesystem>
#include <string>

namespace fissure::testing {

/// Runs `fissure ARGS` with `dir` as its working folder (relative paths in
/// ARGS, and the default output folder out/, are in it); returns the exit
/// code (-1 if it did not exit) and fills `err` with its standard error.
/// Its standard output goes to dir/stdout.txt.
int run_fissure(const std::string& args, const std::filesystem::path& dir, std::string& err);

/// Same, and `peak_bytes` is the command's peak resident memory (wait4's
/// ru_maxrss of the process).
int run_fissure_peak(const std::string& args, const std::filesystem::path& dir, std::string& err,
                     double& peak_bytes);

}  // namespace fissure::testing
