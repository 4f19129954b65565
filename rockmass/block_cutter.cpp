// cut_blocks (block_cutter.h): input preparation, the arrangement, rock
// classification, then the merging, block and graph steps of cut_state.h.
#include "rockmass/block_cutter.h"

#include "core/base/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/errors.h"
#include "core/geometry/box_grid.h"
#include "core/geometry/domain_sides.h"
#include "core/geometry/segment_clip.h"
#include "rockmass/cut_state.h"

namespace fissure {

namespace {

constexpr double kRelativeCheckTolerance = 1e-9;  // the scene's geometry tolerance

std::vector<Vec2> counter_clockwise(std::vector<Vec2> loop) {
  if (signed_area(loop) < 0) std::reverse(loop.begin() + 1, loop.end());
  return loop;
}

Box segment_box(const Vec2& a, const Vec2& b, double grow) {
  Box box;
  box.extend(a);
  box.extend(b);
  box.lo -= Vec2(grow, grow);
  box.hi += Vec2(grow, grow);
  return box;
}

/// Parameter t > 0 at which the ray p + t u (|u| = 1) meets segment [c, d],
/// or infinity.
double ray_hit(const Vec2& p, const Vec2& u, const Vec2& c, const Vec2& d) {
  const Vec2 e = d - c;
  const double denom = cross(u, e);
  if (std::abs(denom) <= 1e-12 * e.norm()) return std::numeric_limits<double>::infinity();
  const Vec2 w = c - p;
  const double t = cross(w, e) / denom;
  const double s = cross(w, u) / denom;
  if (s < 0 || s > 1 || t <= 0) return std::numeric_limits<double>::infinity();
  return t;
}

/// Step 1: the segments to arrange. Boundary segments first (domain, then
/// excavations, counter-clockwise), then the traces that are long enough and
/// near the domain, with ends that stop within tol of another segment
/// extended across it by tol / 2.
std::vector<Segment2> prepare_segments(const CutInput& in, const std::vector<Vec2>& domain,
                                       CutState& state,
                                       std::vector<std::vector<std::string>>& names) {
  std::vector<Segment2> segments;
  auto add_loop = [&](const std::vector<Vec2>& loop, const std::string* name) {
    const int n = static_cast<int>(loop.size());
    std::vector<std::vector<std::string>> sides;
    if (!name) sides = domain_side_names(loop);
    for (int i = 0; i < n; ++i) {
      segments.push_back(Segment2{loop[i], loop[(i + 1) % n]});
      names.push_back(name ? std::vector<std::string>{*name} : std::move(sides[i]));
    }
  };
  add_loop(domain, nullptr);
  for (const ExcavationSpec& e : in.excavations) add_loop(counter_clockwise(e.vertices), &e.name);
  state.n_boundary = static_cast<int>(segments.size());

  Box domain_box;
  for (const Vec2& p : domain) domain_box.extend(p);
  const double tol = state.tol;
  const Box near = segment_box(domain_box.lo, domain_box.hi, tol);
  // Beyond one extent of the domain a trace cannot change the rock: its
  // parts farther out are cut off, so that long fractures neither cross each
  // other far outside (a 1e4 m DFN in a 30 m box made 8e5 crossings, 12 s)
  // nor widen the extent to which the arrangement rounds (segment_arrangement.cpp).
  // Trace ends within that far box stay exactly where they were drawn.
  const double extent = domain_box.size().maxCoeff();
  const Box far = segment_box(domain_box.lo, domain_box.hi, extent);
  auto inside = [&far](const Vec2& p) { return far.overlaps(segment_box(p, p, 0)); };
  for (int t = 0; t < static_cast<int>(in.traces.size()); ++t) {
    const FractureTrace& f = in.traces[t];
    Vec2 a = f.a, b = f.b;
    bool kept = a.allFinite() && b.allFinite();
    if (kept && !(inside(f.a) && inside(f.b))) {
      kept = clip_to_box(a, b, far);
      if (inside(f.a)) a = f.a;
      if (inside(f.b)) b = f.b;
    }
    if (!kept || (b - a).norm() <= tol || !segment_box(a, b, 0).overlaps(near)) {
      ++state.statistics.traces_dropped;
      continue;
    }
    segments.push_back(Segment2{a, b});
    state.trace_of_segment.push_back(t);
  }

  // Extensions: a grid over every segment's box grown by tol.
  std::vector<Box> boxes;
  boxes.reserve(segments.size());
  for (const Segment2& s : segments) boxes.push_back(segment_box(s.a, s.b, tol));
  BoxGrid grid;
  grid.build(boxes);
  for (int i = state.n_boundary; i < static_cast<int>(segments.size()); ++i) {
    const Segment2 original = segments[i];
    bool extended = false;
    for (int end = 0; end < 2; ++end) {
      const Vec2 p = end == 0 ? original.a : original.b;
      const Vec2 u = (end == 0 ? original.a - original.b : original.b - original.a).normalized();
      double best = std::numeric_limits<double>::infinity();
      grid.for_each_overlapping(segment_box(p, p, tol), [&](int j) {
        if (j != i) best = std::min(best, ray_hit(p, u, segments[j].a, segments[j].b));
      });
      if (best <= tol) {
        (end == 0 ? segments[i].a : segments[i].b) = p + (best + 0.5 * tol) * u;
        extended = true;
      }
    }
    if (extended) ++state.statistics.traces_extended;
  }
  return segments;
}

/// Step 2b: rock faces. Crossing a boundary edge changes membership of its
/// loop: leaving it when the half-edge runs along the counter-clockwise loop
/// edge (the loop's inside is on the half-edge's left). A breadth-first walk
/// from the unbounded face (outside everything) gives every face its domain
/// and excavation counts; rock is inside the domain and no excavation.
void classify_rock(const std::vector<Segment2>& segments, const std::vector<int>& loop_of_segment,
                   CutState& state) {
  const PlanarSubdivision& sub = state.sub;
  std::vector<int> in_domain(sub.n_faces, 0), in_excavations(sub.n_faces, 0);
  std::vector<char> seen(sub.n_faces, 0);
  std::vector<int> queue{sub.unbounded_face};
  seen[sub.unbounded_face] = 1;
  for (size_t q = 0; q < queue.size(); ++q) {
    const int f = queue[q];
    for (int k = state.face_start[f]; k < state.face_start[f + 1]; ++k) {
      const int h = state.face_halfedges[k];
      const int g = sub.face[h ^ 1];
      if (seen[g]) continue;
      seen[g] = 1;
      int d = in_domain[f], x = in_excavations[f];
      for (int c : sub.edge_curves(h / 2)) {
        if (c >= state.n_boundary) break;
        const Segment2& s = segments[c];
        const bool segment_left_to_right =
            s.a.x() < s.b.x() || (s.a.x() == s.b.x() && s.a.y() < s.b.y());
        const int step = (sub.left_to_right[h] != 0) == segment_left_to_right ? -1 : 1;
        (loop_of_segment[c] == 0 ? d : x) += step;
      }
      in_domain[g] = d;
      in_excavations[g] = x;
      queue.push_back(g);
    }
  }
  state.rock.assign(sub.n_faces, 0);
  for (int f = 0; f < sub.n_faces; ++f) state.rock[f] = in_domain[f] == 1 && in_excavations[f] == 0;
}

}  // namespace

CutResult cut_blocks(const CutInput& in) {
  CutResult result;
  const std::vector<Vec2> domain = counter_clockwise(in.domain);
  Box box;
  for (const Vec2& p : domain) box.extend(p);
  FISSURE_CHECK(domain.size() >= 3 && !box.empty(), GeometryError,
                "cut_blocks: the domain needs at least 3 vertices");
  FISSURE_CHECK(in.merge_tolerance > 0, GeometryError,
                "cut_blocks: the merge tolerance must be > 0, found " << in.merge_tolerance);

  CutState state;
  state.tol = in.merge_tolerance;
  state.check_tol =
      in.check_tolerance > 0 ? in.check_tolerance : kRelativeCheckTolerance * box.size().maxCoeff();

  Stopwatch clock;
  CutStatistics& stats = state.statistics;
  // 1-2. Segments, arrangement, faces, rock.
  const std::vector<Segment2> segments = prepare_segments(in, domain, state, result.boundary_names);
  std::vector<int> loop_of_segment;
  loop_of_segment.assign(domain.size(), 0);
  for (size_t k = 0; k < in.excavations.size(); ++k)
    loop_of_segment.insert(loop_of_segment.end(), in.excavations[k].vertices.size(),
                           static_cast<int>(k) + 1);
  stats.prepare_seconds = clock.lap();
  state.sub = arrange_segments(segments);
  const PlanarSubdivision& sub = state.sub;
  state.face_start.assign(sub.n_faces + 1, 0);
  for (int h = 0; h < sub.n_halfedges(); ++h) ++state.face_start[sub.face[h] + 1];
  for (int f = 0; f < sub.n_faces; ++f) state.face_start[f + 1] += state.face_start[f];
  state.face_halfedges.resize(sub.n_halfedges());
  {
    std::vector<int> fill(state.face_start.begin(), state.face_start.end() - 1);
    for (int h = 0; h < sub.n_halfedges(); ++h) state.face_halfedges[fill[sub.face[h]]++] = h;
  }
  classify_rock(segments, loop_of_segment, state);
  FISSURE_CHECK(std::count(state.rock.begin(), state.rock.end(), 1) > 0, GeometryError,
                "the excavations remove all of the domain; expected some rock to cut");
  state.groups.reset(sub.n_faces);

  // 3-5. Merging, blocks, fracture graph.
  stats.arrange_seconds = clock.lap();
  merge_slivers(state);
  merge_vertices(state);
  stats.merge_seconds = clock.lap();
  std::vector<ExtractedBlock> blocks = extract_blocks(state);
  stats.extract_seconds = clock.lap();
  std::sort(blocks.begin(), blocks.end(), [](const ExtractedBlock& a, const ExtractedBlock& b) {
    return a.centroid.y() != b.centroid.y() ? a.centroid.y() < b.centroid.y()
                                            : a.centroid.x() < b.centroid.x();
  });
  std::vector<int> block_of_group(sub.n_faces, -1);
  for (size_t b = 0; b < blocks.size(); ++b) block_of_group[blocks[b].group] = static_cast<int>(b);
  result.graph =
      build_fracture_graph(state, blocks, block_of_group, in.traces, result.boundary_names);
  result.blocks.reserve(blocks.size());
  std::vector<char> trace_used(in.traces.size(), 0);
  for (const FractureSegment& s : result.graph.segments) trace_used[s.fracture] = 1;
  for (ExtractedBlock& b : blocks) {
    CutBlock block;
    block.edge_source.reserve(b.halfedge.size());
    for (int h : b.halfedge) {
      block.edge_source.push_back(state.edge_source(h / 2));
      if (block.edge_source.back() >= 0) trace_used[block.edge_source.back()] = 1;
    }
    block.polygon = std::move(b.polygon);
    result.blocks.push_back(std::move(block));
  }
  stats.traces_used = static_cast<int>(std::count(trace_used.begin(), trace_used.end(), 1));
  stats.graph_seconds = clock.lap();
  result.statistics = stats;
  return result;
}

}  // namespace fissure
