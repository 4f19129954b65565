// The contacts as they were in the system the linear solver last factorized,
// and how the current system differs from it. Between that system and the
// current one only contacts that changed state (closed, opened, started or
// stopped sliding) change A by much: each by a few rank-one terms
// (contact_springs.h). The rest is the drift of the geometry, which the
// solver's iteration absorbs. The solver corrects its factorization by these
// terms (core/linear/low_rank_correction.h) instead of computing a new one.
#pragma once

#include <vector>

#include "core/linear/low_rank_update.h"
#include "mechanics/dda/contact_springs.h"
#include "mechanics/dda/dda_contact.h"

namespace fissure::dda {

class FactoredContacts {
 public:
  /// The contacts of the system that was just factorized.
  void record(const std::vector<DdaContact>& contacts, const std::vector<ContactSlots>& slots);
  bool empty() const { return !recorded_any_; }
  /// The contact list is a new one (a new time step): contacts are matched
  /// to the recorded ones by key again at the next describe().
  void contacts_replaced() { matched_ = false; }

  /// The terms by which the system of `contacts` differs from the recorded
  /// one (beyond drift; a sliding contact whose law's friction coefficient
  /// changed between the two, in the same state, is drift too). Each
  /// contact's friction coefficient is friction_coefficient()'s: a recorded
  /// contact keeps the one it was factorized with. Both contact lists are sorted by key, as
  /// detection gives them. False, with `terms` incomplete, once there are more than `max_terms`.
  bool describe(const std::vector<DdaContact>& contacts, const std::vector<ContactSlots>& slots,
                const SpringConstants& k, const std::vector<double>& friction_coefficients,
                int max_terms, LowRankUpdate& terms);

  /// The recorded contacts (core/io/checkpoint.h); a new time step matches
  /// them again.
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a.list("recorded", self.recorded_, [](auto& e, auto& c) { checkpoint_fields(e, c); });
    a.list("recorded_slots", self.recorded_slots_, [](auto& e, auto& s) {
      e("dof_i", s.dof_i);
      e("dof_j", s.dof_j);
      e("ii", s.ii);
      e("jj", s.jj);
      e("ij", s.ij);
      e("ji", s.ji);
    });
    a("recorded_any", self.recorded_any_);
    if constexpr (Archive::reading) self.matched_ = false;
  }

 private:
  void match(const std::vector<DdaContact>& contacts);

  /// Closed contacts only (an open one adds nothing to the system), sorted by key.
  std::vector<DdaContact> recorded_;
  std::vector<ContactSlots> recorded_slots_;
  bool recorded_any_ = false;
  /// Per current contact its recorded one (-1: open then, or new), and the
  /// recorded contacts no current one matches (closed then, gone now).
  bool matched_ = false;
  std::vector<int> match_;
  std::vector<int> vanished_;
};

}  // namespace fissure::dda
