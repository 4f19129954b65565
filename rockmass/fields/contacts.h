// The contacts between blocks, as the shared field "contacts" (written by
// the mechanics, read by the HM coupling of the flow and by the output).
#pragma once

#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/vec2.h"

namespace fissure {

enum class ContactState : int { Open = 0, Sliding = 1, Locked = 2 };

/// A contact as the output and the other processes see it.
struct ContactRecord {
  int block_i = -1;  ///< block of the vertex
  int block_j = -1;  ///< block of the edge
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();  ///< unit normal of the edge, pointing out of block_j
  ContactState state = ContactState::Open;
  double gap = 0;           ///< normal distance, < 0 penetration (m)
  double normal_force = 0;  ///< compressive > 0 (N per unit thickness)
  double shear_force = 0;   ///< along the edge tangent (N)
  int vertex = -1;          ///< the vertex: block_i's polygon vertex index
  int edge = -1;            ///< the edge: block_j's polygon edge edge -> next(edge)
};

inline constexpr Key<std::vector<ContactRecord>> kContacts{"contacts"};

}  // namespace fissure
