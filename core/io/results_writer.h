// results.h5 + results.xdmf (architecture.md 4): block geometry and fields,
// contacts and the fracture network with its flow state per output frame,
// readable by ParaView through the XDMF file. The HDF5 file is
// flushed and the XDMF index rewritten after every frame, so a run that stops
// early leaves a complete, readable record of every frame written so far.
#pragma once

#include <filesystem>
#include <memory>

#include "core/io/hydraulic_head.h"
#include "core/state/rock_mass.h"

namespace fissure {

class ResultsWriter {
 public:
  /// Creates (truncates) OUTDIR/results.h5 and OUTDIR/results.xdmf. With an
  /// active `head`, every frame with a flow state also gets the fracture
  /// nodes' hydraulic heads.
  explicit ResultsWriter(const std::filesystem::path& outdir, HeadDefinition head = {});
  ~ResultsWriter();
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  /// Append one frame at time t.
  void write_frame(const RockMass& state, double t);

  int n_frames() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fissure
