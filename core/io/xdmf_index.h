// results.xdmf: the XDMF 3 index that lets ParaView read results.h5 (private
// to core/io). A Temporal collection holds one Spatial collection per frame
// with the grids that the results parts declared (results_part.h): the
// "blocks" (triangles), and what the modules add ("contacts", "fractures"),
// so ParaView shows them together. All heavy data stays in the HDF5 file;
// the index is rewritten atomically after every frame, so it never lists a
// frame that is not complete in the HDF5 file.
#pragma once

#include <deque>
#include <filesystem>
#include <string>

#include "core/io/results_part.h"
#include "core/scene/units.h"

namespace fissure {

class XdmfIndex {
 public:
  /// `h5_name` is the HDF5 file as seen from the XDMF file's folder. The
  /// times are in s; `time_unit`, the scene's, is noted for a reader.
  XdmfIndex(std::filesystem::path file, std::string h5_name, TimeUnit time_unit = {});

  /// Appends a frame (its HDF5 group, e.g. "/frames/000003", and its grids;
  /// grids without a topology are left out) and rewrites the file.
  void add_frame(double time, const std::string& group, const std::deque<XdmfGrid>& grids);

  /// Rewrites the file (temporary file + rename) with the frames added so far.
  void write() const;

  /// The frames added so far, as XML (for a checkpoint), and the index of a
  /// restarted run, which continues from them.
  const std::string& frames_xml() const { return frames_xml_; }
  void restore(std::string frames_xml) { frames_xml_ = std::move(frames_xml); }

 private:
  std::filesystem::path file_;
  std::string h5_name_;
  std::string header_;      ///< up to the frames: the Temporal collection and its Information
  std::string frames_xml_;  ///< every frame added so far, in order
};

}  // namespace fissure
