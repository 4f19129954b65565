// The continuum's monitors and its part of results.h5 / results.xdmf
// (docs/output.md, docs/continuum.md 5).
#include <array>
#include <cmath>
#include <limits>

#include "continuum/poroelasticity/continuum_process.h"
#include "core/io/point_markers.h"
#include "core/io/xdmf_items.h"

namespace fissure::continuum {

std::vector<MonitorColumn> ContinuumMonitors::columns() const {
  std::vector<MonitorColumn> c = {{"ux", 0, true}, {"uy", 0, true}, {"p", 1, true}};
  if (process_.controls().with_temperature()) c.push_back({"T", 2, true});
  for (const char* s : {"sxx", "syy", "sxy", "szz"}) c.push_back({s, 3});
  c.push_back({"qx", 1});
  c.push_back({"qy", 1});
  return c;
}

void ContinuumMonitors::values(const RockMass&, int point, std::span<double> out) const {
  // Before the mesh exists (its start failed; the output so far is kept): none.
  if (!process_.has_monitor_place(point) || process_.monitor_place(point).triangle < 0) {
    std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const ContinuumMesh::Place& place = process_.monitor_place(point);
  const PointValues v = process_.values_in(place.triangle, place.weights);
  std::size_t k = 0;
  out[k++] = v.displacement.x();
  out[k++] = v.displacement.y();
  out[k++] = v.pressure;
  if (process_.controls().with_temperature()) out[k++] = v.temperature;
  for (int i = 0; i < 4; ++i) out[k++] = v.stress(i);
  out[k++] = v.darcy_flux.x();
  out[k++] = v.darcy_flux.y();
}

std::string ContinuumMonitors::why_missing(const RockMass& state, int point,
                                           std::string_view) const {
  if (!process_.has_monitor_place(point)) return "has no value: the continuum did not start";
  // A block's point in the continuum's hole: the blocks watch it.
  if (point < static_cast<int>(state.points.size()) && state.points[point].block >= 0) return "";
  return process_.monitor_place(point).triangle < 0 ? "is outside the continuum's domain" : "";
}

namespace {

/// The stress components as results.h5 and results.xdmf name them: in the
/// axisymmetric geometry x is the radius r and y the axis z, and the
/// out-of-plane stress is the hoop stress.
std::array<const char*, 4> stress_names(bool axisymmetric) {
  if (axisymmetric) return {"srr", "szz", "srz", "shoop"};
  return {"sxx", "syy", "sxy", "szz"};
}

}  // namespace

void ContinuumResults::write_mesh(FrameWriter& frame, const RockMass&) {
  const ContinuumMesh& mesh = process_.mesh();
  std::vector<int> cells;
  cells.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) cells.insert(cells.end(), t.begin(), t.begin() + 3);
  std::vector<double> xy;
  xy.reserve(2 * mesh.n_vertices);
  for (int v = 0; v < mesh.n_vertices; ++v)
    xy.insert(xy.end(), {mesh.nodes[v].x(), mesh.nodes[v].y()});
  const hsize_t nt = mesh.triangles.size(), nv = mesh.n_vertices;
  frame.h5().write(frame.mesh(), "continuum_triangles", cells, {nt, 3});
  frame.h5().write(frame.mesh(), "continuum_vertices", xy, {nv, 2});
  frame.h5().write(frame.mesh(), "continuum_material", mesh.triangle_material, {nt});
  // The sources, marked on the pictures.
  PointMarkers heat{"continuum_heat_sources", "heat_source", {}, {}};
  PointMarkers wells{"continuum_wells", "well", {}, {}};
  for (const ContinuumSource& s : process_.controls().sources) {
    PointMarkers& m = s.kind == ContinuumSource::Kind::Heat ? heat : wells;
    m.names.push_back(s.name);
    m.points.push_back(s.point);
  }
  write_point_markers(frame, heat);
  write_point_markers(frame, wells);
}

std::size_t ContinuumResults::frame_bytes(const RockMass&) const {
  const ContinuumMesh& mesh = process_.mesh();
  return 8 * (7 * static_cast<std::size_t>(mesh.n_vertices) + 9 * mesh.triangles.size());
}

void ContinuumResults::write_frame(FrameWriter& frame, const RockMass&) {
  const ContinuumMesh& mesh = process_.mesh();
  const ContinuumControls& c = process_.controls();
  const PoroState& f = process_.fields();
  const int nv = mesh.n_vertices, nt = mesh.n_triangles();
  const bool heat = c.with_temperature();
  std::vector<double> u(3 * nv), p(f.pressure.data(), f.pressure.data() + nv),
      temperature(f.temperature.data(), f.temperature.data() + nv), excess(nv), change(nv),
      flux(3 * nt, 0.0);
  std::array<std::vector<double>, 4> stress;
  for (std::vector<double>& s : stress) s.resize(nt);
  for (int v = 0; v < nv; ++v) {
    u[3 * v] = f.displacement(2 * v);
    u[3 * v + 1] = f.displacement(2 * v + 1);
    u[3 * v + 2] = 0;
    // Against the initial state (the scene's continuum.initial), which the
    // stresses are measured from too.
    const double y = mesh.nodes[v].y();
    excess[v] = p[v] - c.initial_pressure_at(y);
    change[v] = temperature[v] - c.initial_temperature_at(y);
  }
  const Eigen::Vector3d centroid = Eigen::Vector3d::Constant(1.0 / 3);
  for (int t = 0; t < nt; ++t) {
    const PointValues v = process_.values_in(t, centroid);
    for (int i = 0; i < 4; ++i) stress[i][t] = v.stress(i);
    flux[3 * t] = v.darcy_flux.x();
    flux[3 * t + 1] = v.darcy_flux.y();
  }
  const std::array<const char*, 4> names = stress_names(c.axisymmetric);
  Hdf5File& h5 = frame.h5();
  const Hdf5Group& g = frame.frame_group("continuum");
  const hsize_t hv = nv, ht = nt;
  h5.write(g, "displacement", u, {hv, 3});
  h5.write(g, "pressure", p, {hv});
  h5.write(g, "excess_pressure", excess, {hv});
  h5.write(g, "temperature", temperature, {hv});
  if (heat) h5.write(g, "temperature_change", change, {hv});
  for (int i = 0; i < 4; ++i) h5.write(g, names[i], stress[i], {ht});
  h5.write(g, "darcy_flux", flux, {ht, 3});
  // A permeability that follows the stress: its geometric mean sqrt(det k)
  // and the decades it moved from the initial state.
  const bool stress_dependent = c.stress_dependent_permeability();
  if (stress_dependent) {
    std::vector<double> k(nt), decades(nt);
    const auto mean = [](const Eigen::Vector3d& x) { return std::sqrt(x(0) * x(1) - x(2) * x(2)); };
    for (int t = 0; t < nt; ++t) {
      k[t] = mean(process_.permeability()[t]);
      decades[t] = std::log10(k[t] / mean(process_.initial_permeability()[t]));
    }
    h5.write(g, "permeability", k, {ht});
    h5.write(g, "permeability_change", decades, {ht});
  }

  XdmfGrid& grid = frame.grid("continuum");
  const std::string at = g.path + "/", vertices = std::to_string(nv), cells = std::to_string(nt);
  constexpr auto Float = XdmfNumber::Float64;
  grid.topology_type = "Triangle";
  grid.n_elements = nt;
  grid.connectivity =
      xdmf_data_item(cells + " 3", XdmfNumber::Int32, frame.xdmf_path("/mesh/continuum_triangles"));
  grid.geometry =
      xdmf_data_item(vertices + " 2", Float, frame.xdmf_path("/mesh/continuum_vertices"));
  grid.information.push_back(xdmf_information(
      "geometry",
      c.axisymmetric ? "axisymmetric: x is the radius r, y the axis z; shoop is the hoop stress"
                     : "plane strain: szz is the out-of-plane stress",
      10));
  grid.mesh_attributes.push_back(xdmf_attribute("material", "Scalar", "Cell", cells,
                                                XdmfNumber::Int32,
                                                frame.xdmf_path("/mesh/continuum_material"), "-"));
  const auto node_scalar = [&](const char* name, const char* unit) {
    grid.frame_attributes.push_back(
        xdmf_attribute(name, "Scalar", "Node", vertices, Float, frame.xdmf_path(at + name), unit));
  };
  grid.frame_attributes.push_back(xdmf_attribute("displacement", "Vector", "Node", vertices + " 3",
                                                 Float, frame.xdmf_path(at + "displacement"), "m"));
  node_scalar("pressure", "Pa");
  node_scalar("excess_pressure", "Pa");
  if (heat) {
    node_scalar("temperature", "degC");
    node_scalar("temperature_change", "K");
  }
  for (const char* s : names)
    grid.frame_attributes.push_back(
        xdmf_attribute(s, "Scalar", "Cell", cells, Float, frame.xdmf_path(at + s), "Pa"));
  grid.frame_attributes.push_back(xdmf_attribute("darcy_flux", "Vector", "Cell", cells + " 3",
                                                 Float, frame.xdmf_path(at + "darcy_flux"), "m/s"));
  if (stress_dependent) {
    grid.frame_attributes.push_back(xdmf_attribute("permeability", "Scalar", "Cell", cells, Float,
                                                   frame.xdmf_path(at + "permeability"), "m^2"));
    grid.frame_attributes.push_back(
        xdmf_attribute("permeability_change", "Scalar", "Cell", cells, Float,
                       frame.xdmf_path(at + "permeability_change"), "decades"));
  }
}

}  // namespace fissure::continuum
