// triangulate (triangulate.h) with CGAL's constrained Delaunay triangulation.
// Every CGAL include stays in this file (compile time).
//
// The polygon's edges are inserted as constraints; the faces inside the
// polygon are found by nesting level: flood-fill from the infinite face
// without crossing constraints (level 0), then from the faces just across
// those constraints (level 1), and so on. Odd levels are inside, so holes
// (level 2) are excluded whatever the loop orientation. No Steiner points:
// for a valid polygon the constraints meet only at shared vertices.
#include "core/geometry/triangulate.h"

#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "core/base/errors.h"

namespace fissure {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;  // polygon index
using FaceInfoBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;  // nesting level
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, FaceInfoBase>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Constraints may touch at vertices (as collinear runs do) but must never
// cross: a crossing would need a constructed Steiner point, and CGAL throws.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Kernel, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Face = Cdt::Face_handle;
using VertexHandle = Cdt::Vertex_handle;

/// Sets face->info() to the nesting level (number of constraints crossed from
/// the infinite face).
void mark_nesting_levels(Cdt& cdt) {
  for (Face f : cdt.all_face_handles()) f->info() = -1;
  std::vector<Face> seeds{cdt.infinite_face()}, next_seeds, stack;
  for (int level = 0; !seeds.empty(); ++level) {
    next_seeds.clear();
    for (Face seed : seeds) {
      if (seed->info() != -1) continue;
      seed->info() = level;
      stack.assign(1, seed);
      while (!stack.empty()) {
        const Face f = stack.back();
        stack.pop_back();
        for (int i = 0; i < 3; ++i) {
          const Face g = f->neighbor(i);
          if (g->info() != -1) continue;
          if (f->is_constrained(i)) {
            next_seeds.push_back(g);
          } else {
            g->info() = level;
            stack.push_back(g);
          }
        }
      }
    }
    seeds.swap(next_seeds);
  }
}

}  // namespace

std::vector<std::array<int, 3>> triangulate(const Polygon& polygon) {
  std::vector<std::array<int, 3>> triangles;
  const int n = polygon.n_vertices();
  if (n < 3) return triangles;
  for (int v = 0; v < n; ++v)
    FISSURE_CHECK(polygon.vertices[v].allFinite(), GeometryError,
                  "triangulate: vertex " << v << " has non-finite coordinates");

  Cdt cdt;
  std::vector<VertexHandle> handles(n);
  VertexHandle hint;
  for (int v = 0; v < n; ++v) {
    const std::size_t before = cdt.number_of_vertices();
    const Vec2& p = polygon.vertices[v];
    handles[v] = hint =
        cdt.insert(Kernel::Point_2(p.x(), p.y()), hint == VertexHandle() ? Face() : hint->face());
    // A repeated point maps to the first polygon vertex at that position.
    if (cdt.number_of_vertices() > before) handles[v]->info() = v;
  }
  try {
    for (int v = 0; v < n; ++v) {
      const int w = polygon.next(v);
      if (handles[v] != handles[w]) cdt.insert_constraint(handles[v], handles[w]);
    }
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    throw GeometryError(
        "triangulate: polygon edges cross each other (run check_polygon on the input)");
  }

  mark_nesting_levels(cdt);
  triangles.reserve(cdt.number_of_faces());
  for (Face f : cdt.finite_face_handles()) {
    if (f->info() % 2 != 1) continue;
    // CGAL stores finite faces counter-clockwise.
    triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  return triangles;
}

}  // namespace fissure
