#include "mechanics/dem/zone_mesh.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/base/errors.h"
#include "core/geometry/edge_division.h"
#include "core/geometry/hilbert_key.h"
#include "core/geometry/interior_point.h"
#include "core/geometry/polygon_mesher.h"

namespace fissure::dem {

namespace {

/// Zones along a Hilbert curve through their centroids, nodes in the order
/// the zones first use them: a zone's neighbours and nodes are then near it
/// in memory (the zone loops gather and scatter at the nodes; 1e5 zones
/// step about a third faster, docs/performance.md).
void order_for_locality(ZoneMesh& mesh) {
  Box box;
  for (const Vec2& x : mesh.nodes) box.extend(x);
  std::vector<Vec2> centroids(mesh.zones.size());
  for (std::size_t z = 0; z < mesh.zones.size(); ++z) {
    const auto& t = mesh.zones[z];
    centroids[z] = (mesh.nodes[t[0]] + mesh.nodes[t[1]] + mesh.nodes[t[2]]) / 3;
  }
  const std::vector<int> order = hilbert_order(centroids, box.lo, box.hi);
  std::vector<int> renumber(mesh.nodes.size(), -1);
  std::vector<Vec2> nodes;
  std::vector<std::array<int, 3>> zones;
  for (int z : order) {
    std::array<int, 3> t = mesh.zones[z];
    for (int& a : t) {
      if (renumber[a] < 0) {
        renumber[a] = static_cast<int>(nodes.size());
        nodes.push_back(mesh.nodes[a]);
      }
      a = renumber[a];
    }
    zones.push_back(t);
  }
  for (std::size_t a = 0; a < mesh.nodes.size(); ++a)  // nodes of no zone (none expected)
    if (renumber[a] < 0) {
      renumber[a] = static_cast<int>(nodes.size());
      nodes.push_back(mesh.nodes[a]);
    }
  for (std::vector<int>& loop : mesh.boundary)
    for (int& a : loop) a = renumber[a];
  for (int& a : mesh.corner_nodes) a = renumber[a];
  mesh.nodes = std::move(nodes);
  mesh.zones = std::move(zones);
}

}  // namespace

ZoneMesh mesh_block(const Polygon& polygon, double zone_size) {
  FISSURE_CHECK(zone_size > 0 && std::isfinite(zone_size), GeometryError,
                "zone size " << zone_size << " m: expected a positive length");
  return mesh_block(polygon, [zone_size](const Vec2&) { return zone_size; });
}

ZoneMesh mesh_block(const Polygon& polygon, const SizeFunction& zone_size) {
  FISSURE_CHECK(polygon.n_loops() >= 1 && polygon.n_vertices() >= 3, GeometryError,
                "a block polygon needs at least 3 vertices, got " << polygon.n_vertices());
  for (const Vec2& v : polygon.vertices) {
    const double h = zone_size(v);
    FISSURE_CHECK(h > 0 && std::isfinite(h), GeometryError,
                  "zone size " << h << " m at (" << v.x() << ", " << v.y()
                               << "): expected a positive length");
  }
  const SizeFunction& size = zone_size;

  // The loops oriented as Polygon has them (outer counter-clockwise, holes
  // clockwise), whatever the input's orientation; each edge divided.
  MesherInput input;
  ZoneMesh mesh;
  std::vector<int> corner_at(polygon.n_vertices());
  int n_points = 0;
  for (int l = 0; l < polygon.n_loops(); ++l) {
    std::vector<Vec2> loop(polygon.loop(l).begin(), polygon.loop(l).end());
    std::vector<int> vertex(loop.size());
    for (std::size_t k = 0; k < loop.size(); ++k) vertex[k] = polygon.loop_offsets[l] + int(k);
    const double area = signed_area(loop);
    FISSURE_CHECK(area != 0 && std::isfinite(area), GeometryError,
                  "loop " << l << " of a block polygon has no area");
    if ((l == 0) != (area > 0)) {
      std::reverse(loop.begin(), loop.end());
      std::reverse(vertex.begin(), vertex.end());
    }
    std::vector<Vec2> points;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      corner_at[vertex[k]] = n_points + static_cast<int>(points.size());
      points.push_back(loop[k]);
      for (const Vec2& p : divide_edge(loop[k], loop[(k + 1) % loop.size()], size))
        points.push_back(p);
    }
    if (l > 0) input.hole_seeds.push_back(interior_point(Polygon(loop)).point);
    std::vector<int> nodes(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) nodes[k] = n_points + static_cast<int>(k);
    mesh.boundary.push_back(std::move(nodes));
    n_points += static_cast<int>(points.size());
    input.loops.push_back(std::move(points));
  }

  TriangleMesh m;
  try {
    m = mesh_polygon(input, size);
  } catch (const Error& e) {
    throw GeometryError(fmt::format("meshing a block into zones: {}", e.what()));
  }
  // The mesher lists the loops' points first, in order, unless two of them
  // coincide (a repeated vertex), which the boundary loops could not follow.
  bool kept = static_cast<int>(m.nodes.size()) >= n_points;
  for (int l = 0, k = 0; kept && l < static_cast<int>(input.loops.size()); ++l)
    for (const Vec2& p : input.loops[l]) kept = kept && m.nodes[k++] == p;
  FISSURE_CHECK(kept, GeometryError,
                "a block polygon has repeated vertices; expected a simple polygon");
  mesh.nodes = std::move(m.nodes);
  mesh.zones = std::move(m.triangles);
  mesh.corner_nodes = std::move(corner_at);
  order_for_locality(mesh);
  return mesh;
}

}  // namespace fissure::dem
