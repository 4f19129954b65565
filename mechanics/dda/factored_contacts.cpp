#include "mechanics/dda/factored_contacts.h"

#include "core/base/errors.h"

namespace fissure::dda {

void FactoredContacts::record(const std::vector<DdaContact>& contacts,
                              const std::vector<ContactSlots>& slots) {
  recorded_.clear();
  recorded_slots_.clear();
  match_.assign(contacts.size(), -1);
  vanished_.clear();
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    if (contacts[c].state == ContactState::Open) continue;
    match_[c] = static_cast<int>(recorded_.size());
    recorded_.push_back(contacts[c]);
    recorded_slots_.push_back(slots[c]);
  }
  recorded_any_ = matched_ = true;
}

// Once per time step (matching tens of thousands of contacts costs more than
// comparing their states in every open-close iteration): one merge of the two
// sorted lists, cheaper than a hash lookup per contact.
void FactoredContacts::match(const std::vector<DdaContact>& contacts) {
  FISSURE_CHECK(sorted_by_key(contacts) && sorted_by_key(recorded_), Error,
                "factored contacts: a contact list is not sorted by key");
  match_.assign(contacts.size(), -1);
  vanished_.clear();
  std::size_t r = 0;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    for (; r < recorded_.size() && recorded_[r].key < contacts[c].key; ++r)
      vanished_.push_back(static_cast<int>(r));
    if (r < recorded_.size() && recorded_[r].key == contacts[c].key)
      match_[c] = static_cast<int>(r++);
  }
  for (; r < recorded_.size(); ++r) vanished_.push_back(static_cast<int>(r));
  matched_ = true;
}

bool FactoredContacts::describe(const std::vector<DdaContact>& contacts,
                                const std::vector<ContactSlots>& slots, const SpringConstants& k,
                                const std::vector<double>& friction_coefficients, int max_terms,
                                LowRankUpdate& terms) {
  terms.clear();
  if (!matched_ || match_.size() != contacts.size()) match(contacts);
  const ContactSlots none;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const DdaContact& now = contacts[c];
    const DdaContact* before = match_[c] >= 0 ? &recorded_[match_[c]] : nullptr;
    const ContactState was = before ? before->state : ContactState::Open;
    if (now.state == was && (was != ContactState::Sliding || now.slip_sign == before->slip_sign))
      continue;  // unchanged: only drift
    add_change_terms(now, slots[c], before, before ? recorded_slots_[match_[c]] : none, k,
                     friction_coefficient(now, friction_coefficients),
                     before ? friction_coefficient(*before, friction_coefficients) : 0.0, terms);
    if (static_cast<int>(terms.size()) > max_terms) return false;
  }
  for (const int r : vanished_) {
    DdaContact open = recorded_[r];
    open.state = ContactState::Open;
    const double mu = friction_coefficient(recorded_[r], friction_coefficients);
    add_change_terms(open, recorded_slots_[r], &recorded_[r], recorded_slots_[r], k, mu, mu, terms);
    if (static_cast<int>(terms.size()) > max_terms) return false;
  }
  return true;
}

}  // namespace fissure::dda
