// `fissure rev STUDY.yaml`: a permeability upscaling (REV) study of a
// fracture network (docs/flow.md section 8), on threads and, under mpirun,
// MPI ranks.
#pragma once

#include <string>
#include <vector>

namespace fissure {

struct RevCommand {
  std::string study_file;
  std::string outdir;    ///< empty: out/rev/<study file stem> (output_folder.h)
  int threads = 0;       ///< per rank; 0: the study's, else all
  int realizations = 0;  ///< per size; 0: the study's (short variants for CI)
  /// Under stress: the indices of the stress states to solve; empty: all.
  std::vector<int> states;
  /// The indices of the sizes to solve (the smaller ones for a short
  /// check); empty: all.
  std::vector<int> sizes;
  bool plots = true;  ///< rev_size.png, rev_polar.png
  bool quiet = false;
};

/// Reads the study, runs it, writes domains.csv, fits.csv, sizes.csv and
/// rev.json (rank 0), prints the sizes and the REV size. Returns the exit
/// code.
int rev_command(const RevCommand& command);

}  // namespace fissure
