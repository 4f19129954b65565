// A module's part of results.h5 / results.xdmf (docs/output.md): the blocks
// (core/io/block_results.h), a process's own fields (the contacts of the
// mechanics, the flow state on the fracture network), a shared field (the
// fracture graph). The results writer asks every part, in order, for its
// share of each frame, and assembles each frame's XDMF grids from what the
// parts declare, so that core/io names no physics.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "core/io/hdf5_file.h"
#include "core/io/xdmf_items.h"
#include "core/state/rock_mass.h"

namespace fissure {

/// One ParaView data set of a frame ("blocks", "contacts", "fractures"): its
/// cells and points, and the attributes the parts add. A grid whose
/// topology no part set is left out of the frame.
struct XdmfGrid {
  std::string name;
  std::string topology_type;  ///< "Triangle", "Polyvertex", "Polyline"; empty: not set
  int n_elements = 0;
  int nodes_per_element = 0;  ///< written when > 0
  std::string connectivity;   ///< <DataItem> of the cells (xdmf_data_item)
  std::string geometry;       ///< <DataItem> of the XY point coordinates
  /// What the grid's numbers mean beyond their units (xdmf_information,
  /// indented 10): the axisymmetric continuum's x = r, y = z.
  std::vector<std::string> information;
  std::vector<std::string> mesh_attributes;   ///< <Attribute>s of fixed fields (xdmf_attribute)
  std::vector<std::string> frame_attributes;  ///< <Attribute>s of the frame's fields

  bool has_topology() const { return !topology_type.empty(); }
  /// The <Grid> element, indented for a frame's Spatial collection.
  std::string xml() const;
};

/// A frame being written: where the parts put their datasets, and its grids.
class FrameWriter {
 public:
  /// `h5_name` is the HDF5 file as seen from the XDMF file; `mesh` is /mesh.
  FrameWriter(Hdf5File& h5, std::string h5_name, double time, const Hdf5Group& mesh);

  Hdf5File& h5() { return h5_; }
  double time() const { return time_; }
  /// /mesh (written at the first frame only).
  const Hdf5Group& mesh() const { return mesh_; }
  /// The frame's group, /frames/NNNNNN; set by the results writer before
  /// the parts write their frame (it is linked only once complete).
  const Hdf5Group& frame() const { return *frame_; }
  void set_frame(const Hdf5Group& frame) { frame_ = &frame; }
  /// The group `name` of the frame, created when first asked for.
  const Hdf5Group& frame_group(const std::string& name);
  /// A dataset as results.xdmf names it: "results.h5:/frames/000003/vertices".
  std::string xdmf_path(const std::string& dataset_path) const;
  /// The grid `name`, created when first asked for; grids appear in the frame
  /// in that order.
  XdmfGrid& grid(const std::string& name);
  const std::deque<XdmfGrid>& grids() const { return grids_; }

 private:
  Hdf5File& h5_;
  std::string h5_name_;
  double time_ = 0;
  const Hdf5Group& mesh_;
  const Hdf5Group* frame_ = nullptr;
  // deques: references handed out stay valid as more are added
  std::deque<std::pair<std::string, Hdf5Group>> groups_;
  std::deque<XdmfGrid> grids_;
};

class ResultsPart {
 public:
  virtual ~ResultsPart() = default;
  /// Its part of /mesh, written once, with the first frame (frame.mesh()).
  virtual void write_mesh(FrameWriter& /*frame*/, const RockMass& /*state*/) {}
  /// What write_mesh remembers, without writing: a restarted run appends
  /// to a results.h5 whose /mesh was written from the same first state.
  virtual void restore_mesh(const RockMass& /*state*/) {}
  /// An upper bound of the bytes its arrays of a frame take (Hdf5File::reserve).
  virtual std::size_t frame_bytes(const RockMass& state) const = 0;
  /// Its part of the frame. Throws IoError.
  virtual void write_frame(FrameWriter& frame, const RockMass& state) = 0;
};

}  // namespace fissure
