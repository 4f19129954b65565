// The fracture network in results.h5 and results.xdmf (private to core/io;
// docs/output.md, "/mesh/fractures" and "fractures/" of a frame). The graph is
// written once, with the block mesh; each frame adds the flow state (node
// pressures and heads, segment apertures and fluxes) and, when its graph is
// not the one in /mesh/fractures, its own geometry. Every frame's XDMF entry
// shows the network as a "fractures" grid of two-node polylines.
#pragma once

#include <string>

#include "core/io/frame_fields.h"
#include "core/io/hdf5_file.h"
#include "core/io/xdmf_index.h"
#include "core/state/fracture_graph.h"

namespace fissure {

/// Writes /mesh/fractures (nodes, segments, per-segment fields including the
/// connected component and dead-end flag, and one node list per named
/// boundary) into `mesh`.
void write_fracture_mesh(Hdf5File& h5, const Hdf5Group& mesh, const FractureGraph& graph);

/// Writes the group `fractures` of a frame: `nodes` and `segments` when
/// `with_geometry`, the flow fields when `f.flow`. Returns where the frame's
/// XDMF grid finds its arrays; `mesh_group` is /mesh/fractures when the
/// frame's graph is the one written there, else empty.
XdmfFractures write_fracture_frame(Hdf5File& h5, const Hdf5Group& frame, const FractureFields& f,
                                   const std::string& mesh_group);

/// The XDMF grid of the fractures (indented for a frame's Spatial collection);
/// `h5_name` is the HDF5 file as seen from the XDMF file.
std::string fracture_grid_xml(const std::string& h5_name, const XdmfFractures& where);

}  // namespace fissure
