// The PNG plots of the command line (scripts/*.py with Debian's python3,
// h5py and matplotlib), drawn after a command has written its output.
#pragma once

#include <string>

namespace fissure {

/// Runs scripts/`script` on `outdir` (output silenced). False when python3
/// or its modules are missing, or the script failed.
bool run_plot_script(const std::string& script, const std::string& outdir);

}  // namespace fissure
