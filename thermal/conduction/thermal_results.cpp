// The thermal process's part of results.h5 / results.xdmf (docs/output.md):
// the triangles of the block meshes once in /mesh, and per frame the nodes'
// current positions and temperatures, as the "thermal" grid; with
// thermal.convection the water's mean temperature per fracture segment, on
// the "fractures" grid (whose cells are the fracture graph's segments), and
// at the nodes of the water's own grid, the "fracture_fluid" grid.
#include "core/base/errors.h"
#include "core/io/point_markers.h"
#include "rockmass/fields/fracture_temperature.h"
#include "rockmass/fracture_graph.h"
#include "thermal/conduction/thermal_process.h"

namespace fissure::thermal {

void ThermalResults::write_mesh(FrameWriter& frame, const RockMass&) {
  // The sources, marked on the pictures: a line or an area at its centroid.
  PointMarkers sources{"thermal_sources", "heat_source", {}, {}};
  for (const HeatSource& s : process_.controls().sources) {
    Vec2 centre = Vec2::Zero();
    for (const Vec2& p : s.points) centre += p / static_cast<double>(s.points.size());
    sources.names.push_back(s.name);
    sources.points.push_back(centre);
  }
  write_point_markers(frame, sources);
  const ThermalMesh& mesh = process_.mesh();
  std::vector<int> cells;
  cells.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) cells.insert(cells.end(), t.begin(), t.end());
  const hsize_t nt = mesh.triangles.size();
  frame.h5().write(frame.mesh(), "thermal_triangles", cells, {nt, 3});
  frame.h5().write(frame.mesh(), "thermal_triangle_block", mesh.triangle_block, {nt});
}

namespace {

/// The water's temperature per segment when it belongs to the state's
/// graph; null otherwise.
const std::vector<double>* fluid_on_graph(const RockMass& state) {
  const std::vector<double>* t = state.fields.find(kFractureFluidTemperature);
  const FractureGraph* graph = state.fields.find(kFractureGraph);
  return t && graph && !t->empty() && static_cast<int>(t->size()) == graph->n_segments() ? t
                                                                                         : nullptr;
}

/// The fluid grid when the state has its temperatures; null otherwise.
const FluidGrid* fluid_grid(const ThermalProcess& process, const ThermalState& s) {
  const FractureFluid* fluid = process.fluid();
  return fluid && fluid->built() && static_cast<int>(s.fluid_temperature.size()) == fluid->n_nodes()
             ? &fluid->grid()
             : nullptr;
}

}  // namespace

std::size_t ThermalResults::frame_bytes(const RockMass& state) const {
  const ThermalState* s = &process_.inner_state();
  if (s->temperature.empty()) return 0;
  const std::vector<double>* fluid = fluid_on_graph(state);
  const FluidGrid* grid = fluid_grid(process_, *s);
  return 8 * 3 * process_.mesh().nodes.size() + (fluid ? 8 * fluid->size() : 0) +
         (grid ? 8 * 3 * grid->positions.size() + 4 * 2 * grid->pieces.size() : 0);
}

void ThermalResults::write_frame(FrameWriter& frame, const RockMass& state) {
  const ThermalState* s = &process_.inner_state();
  if (s->temperature.empty()) return;
  const std::vector<Vec2> positions = process_.node_positions(state);
  std::vector<double> xy;
  xy.reserve(2 * positions.size());
  for (const Vec2& p : positions) xy.insert(xy.end(), {p.x(), p.y()});
  const hsize_t nn = positions.size();
  Hdf5File& h5 = frame.h5();
  const Hdf5Group& g = frame.frame_group("thermal");
  h5.write(g, "nodes", xy, {nn, 2});
  h5.write(g, "temperature", s->temperature, {nn});

  XdmfGrid& grid = frame.grid("thermal");
  const std::string at = g.path + "/";
  const std::string nodes = std::to_string(nn);
  const std::string cells = std::to_string(process_.mesh().triangles.size());
  constexpr auto Float = XdmfNumber::Float64;
  grid.topology_type = "Triangle";
  grid.n_elements = static_cast<int>(process_.mesh().triangles.size());
  grid.connectivity =
      xdmf_data_item(cells + " 3", XdmfNumber::Int32, frame.xdmf_path("/mesh/thermal_triangles"));
  grid.geometry = xdmf_data_item(nodes + " 2", Float, frame.xdmf_path(at + "nodes"));
  grid.mesh_attributes.push_back(
      xdmf_attribute("block_id", "Scalar", "Cell", cells, XdmfNumber::Int32,
                     frame.xdmf_path("/mesh/thermal_triangle_block"), "-"));
  grid.frame_attributes.push_back(xdmf_attribute("temperature", "Scalar", "Node", nodes, Float,
                                                 frame.xdmf_path(at + "temperature"), "degC"));

  if (const std::vector<double>* fluid = fluid_on_graph(state)) {
    const hsize_t ns = fluid->size();
    h5.write(g, "fluid_temperature", *fluid, {ns});
    frame.grid("fractures")
        .frame_attributes.push_back(
            xdmf_attribute("fluid_temperature", "Scalar", "Cell", std::to_string(ns), Float,
                           frame.xdmf_path(at + "fluid_temperature"), "degC"));
  }

  // The water at the nodes of its own grid (the walls' nodes along each
  // fracture): the "fracture_fluid" grid, one line cell per piece.
  if (const FluidGrid* fluid = fluid_grid(process_, *s)) {
    std::vector<double> fluid_xy;
    fluid_xy.reserve(2 * fluid->positions.size());
    for (const Vec2& p : fluid->positions) fluid_xy.insert(fluid_xy.end(), {p.x(), p.y()});
    std::vector<int> pieces;
    pieces.reserve(2 * fluid->pieces.size());
    for (const FluidPiece& p : fluid->pieces) pieces.insert(pieces.end(), {p.from, p.to});
    const hsize_t nf = fluid->positions.size(), np = fluid->pieces.size();
    h5.write(g, "fluid_nodes", fluid_xy, {nf, 2});
    h5.write(g, "fluid_pieces", pieces, {np, 2});
    h5.write(g, "fluid_node_temperature", s->fluid_temperature, {nf});
    XdmfGrid& water = frame.grid("fracture_fluid");
    water.topology_type = "Polyline";
    water.n_elements = static_cast<int>(np);
    water.nodes_per_element = 2;
    water.connectivity = xdmf_data_item(std::to_string(np) + " 2", XdmfNumber::Int32,
                                        frame.xdmf_path(at + "fluid_pieces"));
    water.geometry =
        xdmf_data_item(std::to_string(nf) + " 2", Float, frame.xdmf_path(at + "fluid_nodes"));
    water.frame_attributes.push_back(
        xdmf_attribute("temperature", "Scalar", "Node", std::to_string(nf), Float,
                       frame.xdmf_path(at + "fluid_node_temperature"), "degC"));
  }
}

}  // namespace fissure::thermal
