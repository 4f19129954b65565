// The contacts of a frame in results.h5 / results.xdmf (docs/output.md,
// "contacts/" of a frame, and the "contacts" grid): the results part of the
// shared field "contacts", which the process that makes them (the DDA)
// hands to the output.
#pragma once

#include <vector>

#include "core/io/results_part.h"
#include "rockmass/fields/contacts.h"

namespace fissure {

/// Writes the group "contacts" of the frame and its "contacts" grid (points);
/// nothing when the state has no contacts.
class ContactResults final : public ResultsPart {
 public:
  std::size_t frame_bytes(const RockMass& state) const override;
  void write_frame(FrameWriter& frame, const RockMass& state) override;
};

}  // namespace fissure
