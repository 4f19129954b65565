// The fracture graph in results.h5 and results.xdmf (private to core/io;
// docs/output.md, "/mesh/fractures"). The graph is written once, with the
// block mesh, in its initial geometry; every frame's XDMF entry shows it as a
// "fractures" grid of two-node polylines.
#pragma once

#include <string>

#include "core/io/hdf5_file.h"
#include "core/state/fracture_graph.h"

namespace fissure {

/// Writes /mesh/fractures (nodes, segments, per-segment fields including the
/// connected component and dead-end flag, and one node list per named
/// boundary) into `mesh`.
void write_fracture_mesh(Hdf5File& h5, const Hdf5Group& mesh, const FractureGraph& graph);

/// The XDMF grid of the fractures (indented for a frame's Spatial collection);
/// `h5_name` is the HDF5 file as seen from the XDMF file.
std::string fracture_grid_xml(const std::string& h5_name, int n_nodes, int n_segments);

}  // namespace fissure
