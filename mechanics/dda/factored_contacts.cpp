#include "mechanics/dda/factored_contacts.h"

namespace fissure::dda {

void FactoredContacts::record(const std::vector<DdaContact>& contacts,
                              const std::vector<ContactSlots>& slots) {
  recorded_.clear();
  for (std::size_t c = 0; c < contacts.size(); ++c)
    if (contacts[c].state != ContactState::Open)
      recorded_.emplace(contacts[c].key, Recorded{contacts[c], slots[c]});
  recorded_any_ = true;
}

bool FactoredContacts::describe(const std::vector<DdaContact>& contacts,
                                const std::vector<ContactSlots>& slots, const SpringConstants& k,
                                const std::vector<double>& friction_coefficients, int max_terms,
                                LowRankUpdate& terms) {
  terms.clear();
  ++describes_;
  std::size_t found = 0;
  const ContactSlots none;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const DdaContact& now = contacts[c];
    const auto it = recorded_.find(now.key);
    const DdaContact* before = nullptr;
    if (it != recorded_.end()) {
      it->second.seen = describes_;
      ++found;
      before = &it->second.contact;
    }
    const ContactState was = before ? before->state : ContactState::Open;
    if (now.state == was && (was != ContactState::Sliding || now.slip_sign == before->slip_sign))
      continue;  // unchanged: only drift
    add_change_terms(now, slots[c], before, before ? it->second.slots : none, k,
                     friction_coefficients[now.joint], terms);
    if (static_cast<int>(terms.size()) > max_terms) return false;
  }
  if (found < recorded_.size())  // closed then, gone now
    for (const auto& [key, r] : recorded_) {
      if (r.seen == describes_) continue;
      DdaContact open = r.contact;
      open.state = ContactState::Open;
      add_change_terms(open, r.slots, &r.contact, r.slots, k,
                       friction_coefficients[r.contact.joint], terms);
      if (static_cast<int>(terms.size()) > max_terms) return false;
    }
  return true;
}

}  // namespace fissure::dda
