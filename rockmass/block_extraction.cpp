// Step 4 of block cutting (block_cutter.h): one polygon per group of merged
// faces.
//
// The boundary of a group is made of its boundary half-edges (face in the
// group, twin face outside it). After boundary half-edge h the loop goes on
// with the next half-edge around the same vertex that is again a boundary
// half-edge: next(h), or, while that one has the group on both sides (a
// fracture inside the block, dangling or between merged faces), next(twin(.)),
// turning around the vertex. Outer loops come out counter-clockwise and holes
// clockwise (faces lie on the left of their half-edges). Vertices are then
// replaced by their merge representatives; an edge whose two ends merged
// disappears, and a back-and-forth pair a -> b -> a (a spike left by merged
// vertices) is removed.
//
// A group whose polygon is not valid (check_polygon at the geometry
// tolerance, exactly one outer loop) or is thinner than tol / 2 is merged into
// its neighbour across the longest shared fracture, and the new group is
// extracted again.
#include <algorithm>
#include <unordered_map>

#include "core/base/errors.h"
#include "core/geometry/polygon_checks.h"
#include "rockmass/cut_state.h"

namespace fissure {

namespace {

struct Corner {
  int node;
  int halfedge;  ///< leaves `node` along the loop
};

/// Removes cyclic back-and-forth pairs x -> y -> x (keeping x with the
/// half-edge that leaves it after the spike).
void remove_spikes(std::vector<Corner>& loop) {
  std::vector<Corner> stack;
  stack.reserve(loop.size());
  for (const Corner& c : loop) {
    if (!stack.empty() && stack.back().node == c.node) {  // duplicate
      stack.back().halfedge = c.halfedge;
      continue;
    }
    if (stack.size() >= 2 && stack[stack.size() - 2].node == c.node) {
      stack.pop_back();
      stack.back().halfedge = c.halfedge;
      continue;
    }
    stack.push_back(c);
  }
  // The same across the end of the loop.
  bool changed = true;
  while (changed && stack.size() >= 3) {
    changed = false;
    const size_t n = stack.size();
    if (stack[n - 1].node == stack[0].node) {
      stack[n - 1].halfedge = stack[0].halfedge;
      stack.erase(stack.begin());
      changed = true;
    } else if (stack[n - 2].node == stack[0].node) {  // ..., x, y | x, ...
      stack.pop_back();
      stack.pop_back();
      changed = true;
    } else if (stack[n - 1].node == stack[1].node) {  // ..., x | y, x, ...
      stack[n - 1].halfedge = stack[1].halfedge;
      stack.erase(stack.begin(), stack.begin() + 2);
      changed = true;
    }
  }
  loop.swap(stack);
}

/// Groups across the boundary half-edges of g at nodes that g's loops visit
/// more than once (a pinch: g wraps around blocks that touch at one point, or
/// around itself). Merging with one of them removes the pinch.
std::vector<int> pinch_neighbours(CutState& state, int g,
                                  const std::vector<std::vector<Corner>>& loops) {
  std::vector<int> nodes;
  for (const std::vector<Corner>& loop : loops)
    for (const Corner& c : loop) nodes.push_back(c.node);
  std::sort(nodes.begin(), nodes.end());
  std::vector<int> repeated;
  for (size_t i = 1; i < nodes.size(); ++i)
    if (nodes[i] == nodes[i - 1] && (repeated.empty() || repeated.back() != nodes[i]))
      repeated.push_back(nodes[i]);
  std::vector<int> groups;
  if (repeated.empty()) return groups;
  const PlanarSubdivision& sub = state.sub;
  for (const std::vector<Corner>& loop : loops)
    for (const Corner& c : loop) {
      const int h = c.halfedge;
      const int a = state.node_of(sub.origin[h]), b = state.node_of(sub.target(h));
      if (!std::binary_search(repeated.begin(), repeated.end(), a) &&
          !std::binary_search(repeated.begin(), repeated.end(), b))
        continue;
      const int n = state.group(sub.face[h ^ 1]);
      if (n >= 0 && n != g) groups.push_back(n);
    }
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  return groups;
}

/// The polygon of group g from its boundary half-edges; valid = false when it
/// must be merged, preferably with one of `preferred`.
ExtractedBlock build_block(CutState& state, int g, const std::vector<int>& halfedges,
                           std::vector<char>& visited, bool& valid, std::vector<int>& preferred) {
  const PlanarSubdivision& sub = state.sub;
  ExtractedBlock block;
  block.group = g;
  valid = false;

  std::vector<std::vector<Corner>> loops;
  for (int start : halfedges) {
    if (visited[start]) continue;
    std::vector<Corner> loop;
    int h = start;
    do {
      visited[h] = 1;
      const int a = state.node_of(sub.origin[h]), b = state.node_of(sub.target(h));
      if (a != b) loop.push_back(Corner{a, h});
      int c = sub.next[h];
      while (state.group(sub.face[c ^ 1]) == g) c = sub.next[c ^ 1];
      h = c;
    } while (h != start && !visited[h]);
    remove_spikes(loop);
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  for (int h : halfedges) visited[h] = 0;
  if (loops.empty()) return block;
  preferred = pinch_neighbours(state, g, loops);
  if (!preferred.empty()) return block;

  // Outer loop: the one loop of positive area.
  std::vector<std::vector<Vec2>> points(loops.size());
  std::vector<double> areas(loops.size());
  int outer = -1, n_positive = 0;
  double perimeter = 0;
  for (size_t k = 0; k < loops.size(); ++k) {
    for (const Corner& c : loops[k]) points[k].push_back(sub.vertices[c.node]);
    areas[k] = signed_area(points[k]);
    for (size_t i = 0; i < points[k].size(); ++i)
      perimeter += (points[k][(i + 1) % points[k].size()] - points[k][i]).norm();
    if (areas[k] > 0) {
      ++n_positive;
      outer = static_cast<int>(k);
    }
  }
  if (n_positive != 1) return block;
  block.polygon = Polygon(points[outer]);
  for (const Corner& c : loops[outer]) block.halfedge.push_back(c.halfedge);
  double area = areas[outer];
  for (size_t k = 0; k < loops.size(); ++k) {
    if (static_cast<int>(k) == outer) continue;
    block.polygon.add_loop(points[k]);
    for (const Corner& c : loops[k]) block.halfedge.push_back(c.halfedge);
    area += areas[k];
  }
  if (2 * area < 0.5 * state.tol * perimeter) return block;
  if (!check_polygon(block.polygon, state.check_tol).empty()) return block;
  block.centroid = section_properties(block.polygon).centroid;
  valid = true;
  return block;
}

}  // namespace

std::vector<ExtractedBlock> extract_blocks(CutState& state) {
  const PlanarSubdivision& sub = state.sub;
  const int n_faces = sub.n_faces;
  std::vector<char> visited(sub.n_halfedges(), 0);
  std::unordered_map<int, ExtractedBlock> blocks;  // by group root
  std::vector<int> dirty;
  for (int f = 0; f < n_faces; ++f)
    if (state.rock[f] && state.groups.find(f) == f) dirty.push_back(f);

  std::vector<int> start(n_faces + 1), boundary, halfedges;
  while (!dirty.empty()) {
    // 1. Boundary half-edges of every group.
    std::fill(start.begin(), start.end(), 0);
    for (int h = 0; h < sub.n_halfedges(); ++h) {
      const int g = state.group(sub.face[h]);
      if (g >= 0 && g != state.group(sub.face[h ^ 1])) ++start[g + 1];
    }
    for (int g = 0; g < n_faces; ++g) start[g + 1] += start[g];
    boundary.resize(start.back());
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int h = 0; h < sub.n_halfedges(); ++h) {
      const int g = state.group(sub.face[h]);
      if (g >= 0 && g != state.group(sub.face[h ^ 1])) boundary[fill[g]++] = h;
    }

    // 2. Extract the changed groups.
    std::vector<int> invalid;
    std::vector<std::vector<int>> preferred;
    for (int g : dirty) {
      halfedges.assign(boundary.begin() + start[g], boundary.begin() + start[g + 1]);
      bool valid = false;
      std::vector<int> pinch;
      ExtractedBlock block = build_block(state, g, halfedges, visited, valid, pinch);
      if (valid) {
        blocks[g] = std::move(block);
      } else {
        invalid.push_back(g);
        preferred.push_back(std::move(pinch));
      }
    }

    // 3. Merge the invalid ones into a neighbour.
    dirty.clear();
    std::vector<char> touched(n_faces, 0);
    for (size_t i = 0; i < invalid.size(); ++i) {
      const int g = invalid[i];
      if (touched[g]) {
        dirty.push_back(state.groups.find(g));
        continue;
      }
      halfedges.assign(boundary.begin() + start[g], boundary.begin() + start[g + 1]);
      // At a pinch: the touching group with the longest shared boundary.
      std::vector<int> candidates = halfedges;
      if (!preferred[i].empty())
        std::erase_if(candidates, [&](int h) {
          return !std::binary_search(preferred[i].begin(), preferred[i].end(),
                                     state.group(sub.face[h ^ 1]));
        });
      const int n = best_neighbour(state, g, candidates);
      FISSURE_CHECK(n >= 0, GeometryError,
                    "block cutting: a piece of rock near ("
                        << sub.vertices[sub.origin[halfedges.empty() ? 0 : halfedges[0]]].x()
                        << ", "
                        << sub.vertices[sub.origin[halfedges.empty() ? 0 : halfedges[0]]].y()
                        << ") is not a valid polygon and has no neighbour to merge with; expected "
                           "a rock region without pinched or sub-tolerance parts");
      if (touched[n]) {
        dirty.push_back(g);
        continue;
      }
      blocks.erase(n);
      const int root = state.groups.unite(g, n);
      touched[g] = touched[n] = 1;
      dirty.push_back(root);
      ++state.statistics.invalid_merged;
    }
    std::sort(dirty.begin(), dirty.end());
    dirty.erase(std::unique(dirty.begin(), dirty.end()), dirty.end());
  }

  std::vector<ExtractedBlock> result;
  result.reserve(blocks.size());
  for (auto& [g, block] : blocks) result.push_back(std::move(block));
  std::sort(result.begin(), result.end(),
            [](const ExtractedBlock& a, const ExtractedBlock& b) { return a.group < b.group; });
  return result;
}

}  // namespace fissure
