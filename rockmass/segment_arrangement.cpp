// arrange_segments (planar_subdivision.h) with CGAL's 2D arrangements. The
// only translation unit of mechanics/ that includes CGAL (compile time, and
// CGAL's -frounding-math stays off the DDA kernels: mechanics/CMakeLists.txt).
//
// Kernel: exact predicates and exact constructions (Epeck), so that
// intersection points of nearly parallel or nearly coincident fractures and
// T-junctions are computed exactly; the tolerance-based merging that follows
// (block_cutter.cpp) decides what is "the same" for the rock mass. Each curve
// carries its input index; where curves overlap the consolidated data traits
// keep the set of indices on the shared edges.
#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/base/errors.h"
#include "core/geometry/polygon.h"
#include "rockmass/planar_subdivision.h"

namespace fissure {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
// Vertex, half-edge and face data: their index in the exported arrays.
using Dcel = CGAL::Arr_extended_dcel<Traits, int, int, int>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;

/// An exact coordinate rounded to a double, within max(slack / 2, 2 ulps) of
/// its exact value: the midpoint of its interval approximation when that is
/// at most max(slack, 4 ulps) wide (the usual case), else from the exact
/// value (computed only then). CGAL::to_double alone accepts an interval up
/// to 1e-5 relative wide, which for fractures crossing at a grazing angle can
/// misplace a vertex by a sizeable part of the merge tolerance.
double rounded(const Kernel::FT& c, double slack) {
  const std::pair<double, double> i = CGAL::to_interval(c);
  const double magnitude = std::max(std::abs(i.first), std::abs(i.second));
  if (i.second - i.first <= std::max(slack, 4 * std::numeric_limits<double>::epsilon() * magnitude))
    return 0.5 * (i.first + i.second);
  return CGAL::to_double(CGAL::exact(c));
}

}  // namespace

PlanarSubdivision arrange_segments(std::span<const Segment2> segments) {
  // 1. The curves, each tagged with its input index, in the order of their
  // left ends: the sweep then meets them in the order they were built, and
  // its structures stay near in memory (about 8 % faster at 1e5 fractures;
  // docs/performance-history.md, block_cutting).
  std::vector<Traits::Curve_2> curves;
  curves.reserve(segments.size());
  std::vector<int> order(segments.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return std::min(segments[a].a.x(), segments[a].b.x()) <
           std::min(segments[b].a.x(), segments[b].b.x());
  });
  for (int i : order) {
    const Segment2& s = segments[i];
    FISSURE_CHECK(s.a.allFinite() && s.b.allFinite() && s.a != s.b, GeometryError,
                  "arrange_segments: segment " << i << " is degenerate or not finite");
    curves.emplace_back(SegmentTraits::Curve_2(Kernel::Point_2(s.a.x(), s.a.y()),
                                               Kernel::Point_2(s.b.x(), s.b.y())),
                        static_cast<int>(i));
  }

  // 2. Aggregated insertion: one sweep over all curves.
  Arrangement arrangement;
  CGAL::insert(arrangement, curves.begin(), curves.end());

  // 3. Export: number vertices, edges (two half-edges each) and faces.
  PlanarSubdivision sub;
  sub.vertices.reserve(arrangement.number_of_vertices());
  int index = 0;
  // Vertices within 5e-13 x the extent of the input of their exact position:
  // three orders below the geometry tolerance (1e-9 x extent) of every check
  // that follows.
  Box extent;
  for (const Segment2& seg : segments) {
    extent.extend(seg.a);
    extent.extend(seg.b);
  }
  const double slack = 1e-12 * extent.size().maxCoeff();
  for (auto v = arrangement.vertices_begin(); v != arrangement.vertices_end(); ++v) {
    v->set_data(index++);
    sub.vertices.emplace_back(rounded(v->point().x(), slack), rounded(v->point().y(), slack));
  }
  index = 0;
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    if (f->is_unbounded()) sub.unbounded_face = index;
    f->set_data(index++);
  }
  sub.n_faces = index;
  index = 0;
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    e->set_data(index);
    e->twin()->set_data(index + 1);
    index += 2;
  }
  const int n_halfedges = index;
  sub.origin.resize(n_halfedges);
  sub.next.resize(n_halfedges);
  sub.face.resize(n_halfedges);
  sub.left_to_right.resize(n_halfedges);
  sub.curves.reserve(n_halfedges / 2);
  sub.curve_start.reserve(n_halfedges / 2 + 1);
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    for (Arrangement::Halfedge_handle h : {Arrangement::Halfedge_handle(e), e->twin()}) {
      const int i = h->data();
      sub.origin[i] = h->source()->data();
      sub.next[i] = h->next()->data();
      sub.face[i] = h->face()->data();
      sub.left_to_right[i] = h->direction() == CGAL::ARR_LEFT_TO_RIGHT ? 1 : 0;
    }
    const size_t first = sub.curves.size();
    for (auto c = e->curve().data().begin(); c != e->curve().data().end(); ++c)
      sub.curves.push_back(*c);
    std::sort(sub.curves.begin() + static_cast<std::ptrdiff_t>(first), sub.curves.end());
    sub.curve_start.push_back(static_cast<int>(sub.curves.size()));
  }
  return sub;
}

}  // namespace fissure
