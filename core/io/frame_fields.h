// The fields of one output frame, laid out on the output mesh as they are
// written to results.h5:/frames/NNNNNN (private to core/io): blocks, contacts
// and the fracture network with its flow state. Vectors get a zero z
// component so that ParaView treats them as vectors.
#pragma once

#include <vector>

#include "core/io/hydraulic_head.h"
#include "core/io/output_mesh.h"
#include "core/state/rock_mass.h"

namespace fissure {

struct FrameFields {
  std::vector<double> vertices;       ///< n_vertices x 2, current positions (m)
  std::vector<double> displacement;   ///< n_vertices x 3, current - initial (m)
  std::vector<double> velocity;       ///< n_vertices x 3 (m/s)
  std::vector<double> sxx, syy, sxy;  ///< per triangle, the block's stress (Pa)
  std::vector<int> block_id;          ///< per triangle
};

struct ContactFields {
  std::vector<double> points;        ///< n_contacts x 2 (m)
  std::vector<double> normal;        ///< n_contacts x 3
  std::vector<int> state;            ///< 0 open, 1 sliding, 2 locked
  std::vector<double> gap;           ///< m
  std::vector<double> normal_force;  ///< N per unit thickness
  std::vector<double> shear_force;   ///< N per unit thickness
  std::vector<int> block_i, block_j;
  std::vector<int> cells;  ///< 0 .. n_contacts - 1: one point cell per contact (XDMF)

  int size() const { return static_cast<int>(gap.size()); }
};

/// The fracture graph as two-node polylines and, when the flow process has
/// published a state for this graph, its pressures, apertures and fluxes.
struct FractureFields {
  std::vector<double> nodes;          ///< n_nodes x 2 (m)
  std::vector<int> segments;          ///< n_segments x 2: node_a, node_b
  bool flow = false;                  ///< the fields below are set
  std::vector<double> pressure;       ///< per node (Pa)
  std::vector<double> head;           ///< per node (m); empty when heads are off
  std::vector<double> aperture_a;     ///< per segment, hydraulic aperture at node_a (m)
  std::vector<double> aperture_b;     ///< per segment, at node_b (m)
  std::vector<double> aperture_mean;  ///< per segment, (aperture_a + aperture_b) / 2 (m)
  std::vector<double> flux;           ///< per segment, node_a -> node_b (m^2/s)

  int n_nodes() const { return static_cast<int>(nodes.size() / 2); }
  int n_segments() const { return static_cast<int>(segments.size() / 2); }
};

/// The mesh must match the state's topology (topology_mismatch is empty).
FrameFields gather_frame_fields(const OutputMesh& mesh, const RockMass& state);

ContactFields gather_contact_fields(const RockMass& state);

/// Geometry only (no flow fields).
FractureFields gather_fracture_geometry(const FractureGraph& graph);

/// Geometry of state.fractures plus the flow fields of state.flow when their
/// sizes match the graph (the flow process is active); heads when `head` is.
FractureFields gather_fracture_fields(const RockMass& state, const HeadDefinition& head);

}  // namespace fissure
