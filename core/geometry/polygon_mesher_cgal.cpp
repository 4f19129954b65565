// The one translation unit that includes CGAL's 2D mesher (its own object
// library, core/CMakeLists.txt, for CGAL's -frounding-math).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <list>

#include "core/base/errors.h"
#include "core/geometry/hilbert_key.h"
#include "core/geometry/lattice_seeds.h"
#include "core/geometry/polygon_mesher.h"

namespace fissure {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// Each vertex carries its node number (-1 until numbered).
using VertexBase =
    CGAL::Triangulation_vertex_base_with_info_2<int, Kernel,
                                                CGAL::Delaunay_mesh_vertex_base_2<Kernel>>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// No intersection tag: crossing constraints are an error, not a new vertex.
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::No_constraint_intersection_tag>;
using Point = Cdt::Point;

/// CGAL's size-and-shape criteria with the size bound taken from a size
/// function at the triangle's centroid instead of one constant (the shape
/// bound B = sin^2 of the smallest angle, 0.125: about 20.7 degrees).
class SizeFieldCriteria : public CGAL::Delaunay_mesh_size_criteria_2<Cdt> {
  using Base = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

 public:
  explicit SizeFieldCriteria(const SizeFunction& size) : Base(0.125, 1), size_(&size) {}

  class Is_bad : public Base::Is_bad {
   public:
    Is_bad(double aspect_bound, const SizeFunction* size, const Kernel& traits)
        : Base::Is_bad(aspect_bound, 1, traits), size_(size) {}
    using Base::Is_bad::operator();
    CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& f, Quality& q) const {
      const Point& a = f->vertex(0)->point();
      const Point& b = f->vertex(1)->point();
      const Point& c = f->vertex(2)->point();
      double l[3] = {CGAL::squared_distance(b, c), CGAL::squared_distance(c, a),
                     CGAL::squared_distance(a, b)};
      std::sort(l, l + 3);
      const Vec2 centroid((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
      const double h = (*size_)(centroid);
      q.second = l[2] / (h * h);
      if (q.size() > 1) {
        q.first = 1;
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      const double area2 = 2 * CGAL::area(a, b, c);
      q.first = area2 * area2 / (l[2] * l[1]);  // sin^2 of the smallest angle
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

   private:
    const SizeFunction* size_;
  };
  Is_bad is_bad_object() const { return Is_bad(this->bound(), size_, this->traits); }

 private:
  const SizeFunction* size_;
};

Point point(const Vec2& p) {
  return Point(p.x(), p.y());
}

/// Below this many lattice points the refinement alone meshes the polygon:
/// there the lattice saves little (measured, docs/performance.md
/// "continuum_vs_fenicsx"), and the meshes of small polygons stay as they
/// were.
constexpr std::size_t kMinLatticeSeeds = 20000;

/// Inserts the lattice seeds (lattice_seeds.h) along a Hilbert curve, each
/// located from the last one's face: a walk of a few faces instead of one
/// from the triangulation's start.
void insert_lattice(Cdt& cdt, const std::vector<Vec2>& seeds) {
  if (seeds.empty()) return;
  Vec2 lo = seeds[0], hi = seeds[0];
  for (const Vec2& p : seeds) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  Cdt::Face_handle hint;
  for (const int i : hilbert_order(seeds, lo, hi)) hint = cdt.insert(point(seeds[i]), hint)->face();
}

}  // namespace

TriangleMesh mesh_polygon(const MesherInput& input, const SizeFunction& size) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> boundary;
  try {
    for (const std::vector<Vec2>& loop : input.loops) {
      const std::size_t first = boundary.size();
      for (const Vec2& p : loop) boundary.push_back(cdt.insert(point(p)));
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const auto a = boundary[first + i], b = boundary[first + (i + 1) % loop.size()];
        if (a != b) cdt.insert_constraint(a, b);
      }
    }
    for (const std::vector<Vec2>& line : input.polylines)
      for (std::size_t i = 0; i + 1 < line.size(); ++i)
        cdt.insert_constraint(point(line[i]), point(line[i + 1]));
    for (const Vec2& p : input.points) cdt.insert(point(p));
  } catch (const std::exception& e) {  // CGAL's Failure_exception and its intersection error
    throw Error(std::string("a boundary crosses itself or a constrained line or point; expected "
                            "a simple polygon (CGAL: ") +
                e.what() + ")");
  }

  {
    const std::vector<Vec2> lattice = lattice_seeds(input, size);
    if (lattice.size() >= kMinLatticeSeeds) insert_lattice(cdt, lattice);
  }

  std::list<Point> seeds;
  for (const Vec2& s : input.hole_seeds) seeds.push_back(point(s));
  CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, SizeFieldCriteria> mesher(
      cdt, SizeFieldCriteria(size));
  mesher.set_seeds(seeds.begin(), seeds.end(), false);
  try {
    mesher.refine_mesh();
  } catch (const std::exception& e) {
    throw Error(std::string("the mesher could not refine the polygon (CGAL: ") + e.what() + ")");
  }

  // Nodes: the boundary points first, in input order, then the rest in
  // CGAL's (deterministic) order; only vertices of meshed triangles.
  TriangleMesh mesh;
  auto number = [&mesh](Cdt::Vertex_handle v) {
    if (v->info() < 0) {
      v->info() = static_cast<int>(mesh.nodes.size());
      mesh.nodes.emplace_back(v->point().x(), v->point().y());
    }
    return v->info();
  };
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) v->info() = -1;
  for (const auto& v : boundary) number(v);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    mesh.triangles.push_back({number(f->vertex(0)), number(f->vertex(1)), number(f->vertex(2))});
  }
  return mesh;
}

}  // namespace fissure
