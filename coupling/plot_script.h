// The PNG plots of the command line (scripts/*.py with Debian's python3,
// h5py and matplotlib), drawn after a command has written its output.
#pragma once

#include <string>

namespace fissure {

/// Runs scripts/`script` on `outdir` (output silenced). False when python3
/// or its modules are missing, or the script failed.
bool run_plot_script(const std::string& script, const std::string& outdir);

/// The pictures of `fissure run` in `outdir` (docs/output.md): monitors.png
/// (scripts/plot_monitors.py) and final_state.png (scripts/plot_final_state.py),
/// drawn by one python process (scripts/plot_run.py).
/// Prints which were made and which were not. Best effort: a missing python3
/// or a script that fails leaves a note, never an error.
void draw_run_pictures(const std::string& outdir);

}  // namespace fissure
