// `fissure mesh SCENE.yaml`: the rock mass of a scene (blocks and fracture
// graph) without running any physics (docs/rock-mass.md section 7).
#pragma once

#include <string>

namespace fissure {

/// Reads the scene (its rock mass is generated while it is read), writes
/// results.h5/.xdmf (frame 0) and summary.json into `outdir` (default
/// out/<scene file stem>, refused when it holds another scene file's
/// results: output_folder.h), prints the counts, and draws rock_mass.png
/// when `plot`. Returns the exit code.
int mesh_command(const std::string& scene_file, std::string outdir, bool plot);

}  // namespace fissure
