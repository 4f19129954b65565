#include "continuum/poroelasticity/continuum_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/base/errors.h"
#include "core/geometry/domain_sides.h"
#include "core/geometry/polygon.h"
#include "core/geometry/polygon_checks.h"
#include "core/geometry/polygon_mesher.h"

namespace fissure::continuum {

namespace {

Box domain_box(const std::vector<Vec2>& domain) {
  return bounding_box(Polygon(domain));
}

/// The structured grid of the bounding box: nx x ny cells, each cut along a
/// diagonal that alternates like a chessboard (no preferred direction).
void structured_triangles(const ContinuumControls& c, std::vector<Vec2>& vertices,
                          std::vector<std::array<int, 3>>& triangles) {
  const Box box = domain_box(c.domain);
  for (const Vec2& v : c.domain)
    FISSURE_CHECK((v.x() == box.lo.x() || v.x() == box.hi.x()) &&
                      (v.y() == box.lo.y() || v.y() == box.hi.y()) && c.domain.size() == 4,
                  Error,
                  "found a domain that is not an axis-aligned rectangle with mesh.divisions; "
                  "expected a rectangle of 4 vertices, or mesh.element_size for any polygon");
  const int nx = c.divisions[0], ny = c.divisions[1];
  const Vec2 size = box.size();
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      vertices.emplace_back(i == nx ? box.hi.x() : box.lo.x() + size.x() * i / nx,
                            j == ny ? box.hi.y() : box.lo.y() + size.y() * j / ny);
  auto at = [nx](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = at(i, j), b = at(i + 1, j), d = at(i + 1, j + 1), e = at(i, j + 1);
      if ((i + j) % 2 == 0) {
        triangles.push_back({a, b, d});
        triangles.push_back({a, d, e});
      } else {
        triangles.push_back({a, b, e});
        triangles.push_back({b, d, e});
      }
    }
}

/// A loop's points with every edge split evenly into pieces of at most h.
std::vector<Vec2> split_loop(const std::vector<Vec2>& loop, double h, bool closed) {
  std::vector<Vec2> out;
  const std::size_t n = loop.size(), edges = closed ? n : n - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % n];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / h - 1e-9)));
    for (int k = 0; k < pieces; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
  }
  if (!closed) out.push_back(loop.back());
  return out;
}

void unstructured_triangles(const ContinuumControls& c, std::vector<Vec2>& vertices,
                            std::vector<std::array<int, 3>>& triangles) {
  const double h = c.element_size;
  MesherInput input;
  input.loops.push_back(split_loop(c.domain, h, true));
  for (const ContinuumRegion& r : c.regions) {
    std::vector<Vec2> closed = r.polygon;
    closed.push_back(r.polygon.front());
    input.polylines.push_back(split_loop(closed, h, false));
  }
  TriangleMesh m = mesh_polygon(input, [h](const Vec2&) { return h; });
  vertices = std::move(m.nodes);
  triangles = std::move(m.triangles);
}

/// Each triangle's material: the last region that holds its centroid, or
/// the domain's.
std::vector<int> triangle_materials(const ContinuumControls& c, const std::vector<Vec2>& v,
                                    const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Polygon> regions;
  for (const ContinuumRegion& r : c.regions) regions.emplace_back(r.polygon);
  std::vector<int> material(triangles.size(), c.material);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Vec2 centroid = (v[triangles[t][0]] + v[triangles[t][1]] + v[triangles[t][2]]) / 3;
    for (std::size_t r = 0; r < regions.size(); ++r)
      if (locate_point(regions[r], centroid, 0) > 0) material[t] = c.regions[r].material;
  }
  return material;
}

/// Whether p lies on segment a-b, within tol.
bool on_segment(const Vec2& p, const Vec2& a, const Vec2& b, double tol) {
  const Vec2 d = b - a;
  const double len = d.norm();
  const double along = (p - a).dot(d) / len, across = std::abs(cross(d, p - a)) / len;
  return across <= tol && along >= -tol && along <= len + tol;
}

}  // namespace

const std::vector<BoundaryEdge>* ContinuumMesh::boundary(std::string_view name) const {
  for (const auto& [n, edges] : boundaries)
    if (n == name) return &edges;
  return nullptr;
}

ContinuumMesh::Place ContinuumMesh::locate(const Vec2& p) const {
  Place best;
  double best_min = -std::numeric_limits<double>::infinity();
  for (int t = 0; t < n_triangles(); ++t) {
    const Vec2 a = nodes[triangles[t][0]], b = nodes[triangles[t][1]], d = nodes[triangles[t][2]];
    const double area = cross(b - a, d - a);
    const Eigen::Vector3d w(cross(b - p, d - p) / area, cross(d - p, a - p) / area,
                            cross(a - p, b - p) / area);
    if (w.minCoeff() > best_min) {
      best_min = w.minCoeff();
      best = {t, w};
    }
  }
  return best;
}

double estimate_elements(const ContinuumControls& c) {
  if (c.divisions[0] > 0) return 2.0 * c.divisions[0] * c.divisions[1];
  // An equilateral triangle of edge h has the area sqrt(3)/4 h^2; the
  // mesher's triangles are about that size.
  const double area = std::abs(signed_area(c.domain));
  return area / (std::sqrt(3.0) / 4 * c.element_size * c.element_size);
}

ContinuumMesh build_continuum_mesh(const ContinuumControls& c) {
  std::vector<Vec2> vertices;
  std::vector<std::array<int, 3>> corners;
  if (c.divisions[0] > 0)
    structured_triangles(c, vertices, corners);
  else
    unstructured_triangles(c, vertices, corners);
  FISSURE_CHECK(!corners.empty(), Error,
                "the domain gave no triangles; expected a polygon with area");

  ContinuumMesh mesh;
  mesh.n_vertices = static_cast<int>(vertices.size());
  mesh.nodes = vertices;
  mesh.triangle_material = triangle_materials(c, vertices, corners);

  // Midpoint nodes, one per edge; an edge met once is on the boundary.
  std::map<std::pair<int, int>, std::pair<int, int>> edges;  // (lo, hi) -> (node, uses)
  std::vector<std::pair<int, int>> oriented;                 // a -> b of each first use
  for (const auto& t : corners) {
    std::array<int, 6> six{t[0], t[1], t[2], -1, -1, -1};
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      auto [it, added] = edges.try_emplace({std::min(a, b), std::max(a, b)}, -1, 0);
      if (added) {
        it->second.first = mesh.n_nodes();
        mesh.nodes.push_back((vertices[a] + vertices[b]) / 2);
        oriented.emplace_back(a, b);
      }
      ++it->second.second;
      six[3 + k] = it->second.first;
    }
    mesh.triangles.push_back(six);
  }

  // Boundary edges and the names of the domain's sides they lie on.
  const std::vector<std::vector<std::string>> side_names = domain_side_names(c.domain);
  const double tol = 1e-9 * domain_box(c.domain).size().maxCoeff();
  for (std::string_view name : kNamedSides)
    mesh.boundaries.emplace_back(std::string(name), std::vector<BoundaryEdge>{});
  for (const auto& [a, b] : oriented) {
    const auto& e = edges.at({std::min(a, b), std::max(a, b)});
    if (e.second != 1) continue;
    const BoundaryEdge edge{a, b, e.first};
    mesh.boundaries.back().second.push_back(edge);  // exterior
    const Vec2 mid = mesh.nodes[e.first];
    for (std::size_t s = 0; s < c.domain.size(); ++s) {
      if (!on_segment(vertices[a], c.domain[s], c.domain[(s + 1) % c.domain.size()], tol) ||
          !on_segment(mid, c.domain[s], c.domain[(s + 1) % c.domain.size()], tol) ||
          !on_segment(vertices[b], c.domain[s], c.domain[(s + 1) % c.domain.size()], tol))
        continue;
      for (const std::string& n : side_names[s])
        for (auto& [name, list] : mesh.boundaries)
          if (name == n) list.push_back(edge);
      break;
    }
  }
  return mesh;
}

}  // namespace fissure::continuum
