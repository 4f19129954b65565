// results.xdmf: the XDMF 3 index that lets ParaView read results.h5 (private
// to core/io). A Temporal collection holds one Spatial collection per frame
// with a "blocks" grid (triangles), when the frame has contacts a "contacts"
// grid (points), and when the rock mass has a fracture graph a "fractures"
// grid (two-node polylines, with the flow fields when flow is active), so
// ParaView shows blocks and fractures together. All heavy data stays in the
// HDF5 file; the index
// is rewritten atomically after every frame, so it never lists a frame that
// is not complete in the HDF5 file.
#pragma once

#include <filesystem>
#include <string>

namespace fissure {

/// Where a frame's "fractures" grid finds its arrays (fracture_output.h).
struct XdmfFractures {
  int n_nodes = 0;
  int n_segments = 0;    ///< 0: no fractures grid
  std::string geometry;  ///< HDF5 group holding `nodes` and `segments`
  /// Group of the graph's fixed per-segment fields (/mesh/fractures); empty
  /// when the frame's graph is not the one written there.
  std::string graph;
  std::string flow;   ///< group of the frame's flow fields; empty without flow
  bool head = false;  ///< `flow` holds `head`
};

struct XdmfFrame {
  double time = 0;     ///< s
  std::string group;   ///< HDF5 group of the frame, e.g. "/frames/000003"
  int n_contacts = 0;  ///< 0: no contacts grid
  XdmfFractures fractures;
};

class XdmfIndex {
 public:
  /// `h5_name` is the HDF5 file as seen from the XDMF file's folder.
  XdmfIndex(std::filesystem::path file, std::string h5_name);

  /// Sizes of the fixed block mesh; call before the first add_frame.
  void set_mesh(int n_vertices, int n_triangles);

  /// Appends a frame and rewrites the file.
  void add_frame(const XdmfFrame& frame);

  /// Rewrites the file (temporary file + rename) with the frames added so far.
  void write() const;

 private:
  std::string frame_xml(const XdmfFrame& frame) const;

  std::filesystem::path file_;
  std::string h5_name_;
  int n_vertices_ = 0;
  int n_triangles_ = 0;
  std::string frames_xml_;  ///< every frame added so far, in order
};

}  // namespace fissure
