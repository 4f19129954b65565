#include "flow/hm/hm_coupling.h"

#include "flow/hm/pressure_loads.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fields/pressure_loads.h"

namespace fissure::flow {

void HmCoupling::apertures(const FractureGraph& graph, const std::vector<Vec2>& nodes,
                           const BlockReference& blocks, const RockMass& state,
                           std::vector<SegmentWalls>& walls, std::vector<double>& aperture_a,
                           std::vector<double>& aperture_b) {
  walls = segment_walls(graph, nodes, block_maps(state.blocks, blocks));
  static const std::vector<ContactRecord> kNoContacts;
  const std::vector<ContactRecord>* contacts = state.fields.find(kContacts);
  hm_apertures(graph, walls, contacts ? *contacts : kNoContacts, laws_, aperture_a, aperture_b,
               &wall_state_);
}

void HmCoupling::load_blocks(const FractureGraph& graph, const std::vector<SegmentWalls>& walls,
                             const std::vector<double>& pressure, RockMass& state) const {
  state.fields.set(kPressureLoads, wall_pressure_loads(graph, walls, pressure, state.blocks));
}

}  // namespace fissure::flow
