// results.h5 + results.xdmf (docs/architecture.md 6): the blocks' geometry and
// fields (block_results.h) and what each module adds (results_part.h: the
// contacts of the mechanics, the fracture network and its flow state) per
// output frame, readable by ParaView through the XDMF file. The HDF5 file
// is flushed and the XDMF index rewritten after every frame, so a run that
// stops early leaves a complete, readable record of every frame written so
// far.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "core/io/results_part.h"
#include "core/scene/units.h"
#include "core/state/rock_mass.h"

namespace fissure {

class CheckpointWriter;  // core/io/checkpoint.h
class CheckpointReader;

class ResultsWriter {
 public:
  /// Creates (truncates) OUTDIR/results.h5 and OUTDIR/results.xdmf. Every
  /// frame holds the blocks, then the parts of `parts` in order (they must
  /// outlive the writer). Times are in s; results.xdmf notes `time_unit`,
  /// the scene's unit, for a reader.
  explicit ResultsWriter(const std::filesystem::path& outdir, std::vector<ResultsPart*> parts = {},
                         TimeUnit time_unit = {});
  /// Continues the files of a checkpointed run (save()): frames written
  /// after the checkpoint are removed. `first_state` is the state the first
  /// frame was written from (the parts' /mesh).
  ResultsWriter(const std::filesystem::path& outdir, std::vector<ResultsPart*> parts,
                CheckpointReader& checkpoint, const RockMass& first_state, TimeUnit time_unit = {});
  ~ResultsWriter();
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  /// Append one frame at time t.
  void write_frame(const RockMass& state, double t);

  int n_frames() const;

  /// Which frames it has written (core/io/checkpoint.h).
  void save(CheckpointWriter& checkpoint) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fissure
