// results.xdmf: the XDMF 3 index that lets ParaView read results.h5 (private
// to core/io). A Temporal collection holds one Spatial collection per frame
// with a "blocks" grid (triangles), when the frame has contacts a "contacts"
// grid (points), and when the rock mass has a fracture graph a "fractures"
// grid (two-node polylines). All heavy data stays in the HDF5 file; the index
// is rewritten atomically after every frame, so it never lists a frame that
// is not complete in the HDF5 file.
#pragma once

#include <filesystem>
#include <string>

namespace fissure {

struct XdmfFrame {
  double time = 0;     ///< s
  std::string group;   ///< HDF5 group of the frame, e.g. "/frames/000003"
  int n_contacts = 0;  ///< 0: no contacts grid
};

class XdmfIndex {
 public:
  /// `h5_name` is the HDF5 file as seen from the XDMF file's folder.
  XdmfIndex(std::filesystem::path file, std::string h5_name);

  /// Sizes of the fixed block mesh; call before the first add_frame.
  void set_mesh(int n_vertices, int n_triangles);
  /// Sizes of the fracture graph in /mesh/fractures (fracture_output.h); a
  /// "fractures" grid is listed in every frame when n_segments > 0.
  void set_fractures(int n_nodes, int n_segments);

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
  int n_fracture_nodes_ = 0;
  int n_fracture_segments_ = 0;
  std::string frames_xml_;  ///< every frame added so far, in order
};

}  // namespace fissure
