#include "continuum/poroelasticity/continuum_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <tuple>

#include "core/base/errors.h"
#include "core/geometry/domain_sides.h"
#include "core/geometry/interior_point.h"
#include "core/geometry/polygon.h"
#include "core/geometry/polygon_checks.h"
#include "core/geometry/polygon_mesher.h"
#include "core/geometry/segment_predicates.h"

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

/// Whether p lies on segment a-b, within tol.
bool on_segment(const Vec2& p, const Vec2& a, const Vec2& b, double tol) {
  const Vec2 d = b - a;
  const double len = d.norm();
  const double along = (p - a).dot(d) / len, across = std::abs(cross(d, p - a)) / len;
  return across <= tol && along >= -tol && along <= len + tol;
}

/// A loop's points with every edge split into pieces of about the local
/// size: evenly in the integral of 1 / h along the edge.
std::vector<Vec2> split_loop(const std::vector<Vec2>& loop, const SizeFunction& h, bool closed) {
  constexpr int kSamples = 64;
  std::vector<Vec2> out;
  const std::size_t n = loop.size(), edges = closed ? n : n - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % n];
    const double length = (b - a).norm();
    std::vector<double> cumulative(kSamples + 1, 0.0);  // int_0^s ds / h
    for (int k = 1; k <= kSamples; ++k) {
      const Vec2 x0 = a + (b - a) * ((k - 1.0) / kSamples),
                 x1 = a + (b - a) * (double(k) / kSamples);
      cumulative[k] = cumulative[k - 1] + length / kSamples * 0.5 * (1 / h(x0) + 1 / h(x1));
    }
    const int pieces = std::max(1, static_cast<int>(std::ceil(cumulative.back() - 1e-9)));
    out.push_back(a);
    for (int p = 1, k = 1; p < pieces; ++p) {
      const double target = cumulative.back() * p / pieces;
      while (cumulative[k] < target) ++k;
      const double f = (target - cumulative[k - 1]) / (cumulative[k] - cumulative[k - 1]);
      out.push_back(a + (b - a) * ((k - 1 + f) / kSamples));
    }
  }
  if (!closed) out.push_back(loop.back());
  return out;
}

/// The regions' outlines as the mesh edges must follow them: without the
/// pieces that lie on the domain's outline (a layer that reaches the sides),
/// and split where two regions' outlines cross (a fault through a layer), so
/// that the mesher meets no crossing constraints. O(n^2) in the regions'
/// edges, which are few.
std::vector<std::pair<Vec2, Vec2>> region_segments(const ContinuumControls& c) {
  const double tol = 1e-9 * domain_box(c.domain).size().maxCoeff();
  std::vector<std::pair<Vec2, Vec2>> edges;
  for (const ContinuumRegion& r : c.regions)
    for (std::size_t i = 0; i < r.polygon.size(); ++i) {
      const Vec2 a = r.polygon[i], b = r.polygon[(i + 1) % r.polygon.size()];
      bool on_outline = false;
      for (std::size_t s = 0; s < c.domain.size() && !on_outline; ++s) {
        const Vec2 p = c.domain[s], q = c.domain[(s + 1) % c.domain.size()];
        on_outline = on_segment(a, p, q, tol) && on_segment(b, p, q, tol);
      }
      if (!on_outline) edges.emplace_back(a, b);
    }
  // Each crossing point is computed once and shared by both segments, so
  // that the pieces meet exactly there.
  std::vector<std::vector<std::pair<double, Vec2>>> cuts(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    cuts[i].emplace_back(0.0, edges[i].first);
    cuts[i].emplace_back(1.0, edges[i].second);
  }
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto [a, b] = edges[i];
      const auto [p, q] = edges[j];
      if (!segments_cross(a, b, p, q, tol)) continue;
      const double t = crossing_parameter(a, b, p, q);
      const Vec2 x = a + t * (b - a);
      cuts[i].emplace_back(t, x);
      cuts[j].emplace_back(closest_parameter(x, p, q), x);
    }
  std::vector<std::pair<Vec2, Vec2>> pieces;
  for (auto& list : cuts) {
    std::sort(list.begin(), list.end(),
              [](const auto& u, const auto& v) { return u.first < v.first; });
    for (std::size_t k = 0; k + 1 < list.size(); ++k)
      if (list[k + 1].first - list[k].first > 1e-12)
        pieces.emplace_back(list[k].second, list[k + 1].second);
  }
  return pieces;
}

/// The loop with each of `points` that lies inside one of its edges
/// inserted there, in order along the edge.
std::vector<Vec2> with_points_on_edges(const std::vector<Vec2>& loop,
                                       const std::vector<Vec2>& points) {
  const double tol = 1e-9 * domain_box(loop).size().maxCoeff();
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
    out.push_back(a);
    std::vector<std::pair<double, Vec2>> inside;
    for (const Vec2& p : points)
      if (on_segment(p, a, b, tol) && (p - a).norm() > tol && (p - b).norm() > tol)
        inside.emplace_back(closest_parameter(p, a, b), p);
    std::sort(inside.begin(), inside.end(),
              [](const auto& u, const auto& v) { return u.first < v.first; });
    for (std::size_t k = 0; k < inside.size(); ++k)
      if (k == 0 || (inside[k].second - inside[k - 1].second).norm() > tol)
        out.push_back(inside[k].second);
  }
  return out;
}

void unstructured_triangles(const ContinuumControls& c, std::vector<Vec2>& vertices,
                            std::vector<std::array<int, 3>>& triangles) {
  const SizeFunction h = size_function(c);
  MesherInput input;
  // The mesher takes no constraint that ends on another: the regions' ends
  // on the outline become vertices of the outline.
  const std::vector<std::pair<Vec2, Vec2>> regions = region_segments(c);
  std::vector<Vec2> ends;
  for (const auto& [a, b] : regions) ends.insert(ends.end(), {a, b});
  input.loops.push_back(split_loop(with_points_on_edges(c.domain, ends), h, true));
  for (const NamedOutline& hole : c.holes) {
    input.loops.push_back(split_loop(hole.points, h, true));
    input.hole_seeds.push_back(interior_point(Polygon(hole.points)).point);
  }
  for (const auto& [a, b] : regions) input.polylines.push_back(split_loop({a, b}, h, false));
  // A node at each source that is not on the boundary.
  const Polygon domain(c.domain);
  const double tol = 1e-9 * bounding_box(domain).size().maxCoeff();
  for (const ContinuumSource& s : c.sources)
    if (locate_point(domain, s.point, tol) > 0) input.points.push_back(s.point);
  TriangleMesh m = mesh_polygon(input, h);
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

}  // namespace

SizeFunction size_function(const ContinuumControls& c) {
  const double h = c.element_size, hf = c.fine_element_size, grading = c.size_grading;
  // The features the mesh is refined towards: points and segments.
  std::vector<std::pair<Vec2, Vec2>> features;
  for (const ContinuumSource& s : c.sources) features.emplace_back(s.point, s.point);
  for (const NamedOutline& hole : c.holes)
    for (std::size_t i = 0; i < hole.points.size(); ++i)
      features.emplace_back(hole.points[i], hole.points[(i + 1) % hole.points.size()]);
  for (const NamedOutline& line : c.boundaries)
    for (std::size_t i = 0; i + 1 < line.points.size(); ++i)
      features.emplace_back(line.points[i], line.points[i + 1]);
  if (!(hf > 0) || hf >= h || features.empty()) return [h](const Vec2&) { return h; };
  return [h, hf, grading, features](const Vec2& x) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& [a, b] : features) {
      const Vec2 e = b - a;
      const double s =
          e.squaredNorm() > 0 ? std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0) : 0.0;
      d = std::min(d, (x - (a + s * e)).norm());
    }
    return std::min(h, hf + grading * d);
  };
}

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
  // As the thermal block meshes (polygon_mesher.h): the area at the global
  // size, a triangle per boundary node and two per outline vertex, and the
  // refined zones around the sources and along the holes and named lines.
  const double h = c.element_size, hf = c.fine_element_size;
  const bool refined = hf > 0 && hf < h;
  double n = std::abs(signed_area(c.domain)) / (kMeshedAreaPerTriangle * h * h);
  auto outline = [&](const std::vector<Vec2>& points, bool closed, bool refines) {
    double length = 0;
    for (std::size_t i = 0; i + 1 < points.size() + (closed ? 1 : 0); ++i)
      length += (points[(i + 1) % points.size()] - points[i]).norm();
    n += length / h + 2.0 * points.size();
    if (refines && refined) n += length * refined_line_triangles_per_length(h, hf, c.size_grading);
  };
  outline(c.domain, true, false);
  for (const ContinuumRegion& r : c.regions) outline(r.polygon, true, false);
  for (const NamedOutline& o : c.holes) outline(o.points, true, true);
  for (const NamedOutline& o : c.boundaries) outline(o.points, false, true);
  if (refined) n += c.sources.size() * refined_point_triangles(h, hf, c.size_grading);
  return n;
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
  // The holes' and named lines' edges take their names: (name, polyline, closed).
  std::vector<std::tuple<std::string, const std::vector<Vec2>*, bool>> outlines;
  for (const NamedOutline& o : c.holes) outlines.emplace_back(o.name, &o.points, true);
  for (const NamedOutline& o : c.boundaries) outlines.emplace_back(o.name, &o.points, false);
  for (const auto& o : outlines)
    mesh.boundaries.emplace_back(std::get<0>(o), std::vector<BoundaryEdge>{});
  for (const auto& [a, b] : oriented) {
    const auto& e = edges.at({std::min(a, b), std::max(a, b)});
    if (e.second != 1) continue;
    const BoundaryEdge edge{a, b, e.first};
    mesh.boundaries[4].second.push_back(edge);  // exterior
    const Vec2 mid = mesh.nodes[e.first];
    auto on = [&](const Vec2& p, const Vec2& q) {
      return on_segment(vertices[a], p, q, tol) && on_segment(mid, p, q, tol) &&
             on_segment(vertices[b], p, q, tol);
    };
    for (std::size_t s = 0; s < c.domain.size(); ++s) {
      if (!on(c.domain[s], c.domain[(s + 1) % c.domain.size()])) continue;
      for (const std::string& n : side_names[s])
        for (auto& [name, list] : mesh.boundaries)
          if (name == n) list.push_back(edge);
      break;
    }
    for (std::size_t k = 0; k < outlines.size(); ++k) {
      const auto& [name, points, closed] = outlines[k];
      const std::size_t segments = closed ? points->size() : points->size() - 1;
      for (std::size_t s = 0; s < segments; ++s)
        if (on((*points)[s], (*points)[(s + 1) % points->size()])) {
          mesh.boundaries[std::size(kNamedSides) + k].second.push_back(edge);
          break;
        }
    }
  }
  return mesh;
}

}  // namespace fissure::continuum
