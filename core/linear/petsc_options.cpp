#include "core/linear/petsc_options.h"

#ifdef FISSURE_WITH_PETSC
#include <petscsys.h>

#include <algorithm>
#include <cctype>
#include <iterator>
#include <map>
#include <sstream>

#include "core/linear/petsc_session.h"

namespace fissure {

namespace {

/// The options that leases set, with the number of live leases holding
/// each; options set otherwise (before any lease) are not in it.
std::map<std::string, int>& leased_options() {
  static std::map<std::string, int> held;
  return held;
}

}  // namespace

bool is_petsc_option_name(const std::string& token) {
  return token.size() > 1 && token[0] == '-' &&
         !std::isdigit(static_cast<unsigned char>(token[1])) && token[1] != '.';
}

void PetscOptionsLease::add(const std::string& options) {
  std::istringstream in(options);
  const std::vector<std::string> tokens{std::istream_iterator<std::string>(in), {}};
  std::map<std::string, int>& leased = leased_options();
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const std::string& name = tokens[k];
    if (!is_petsc_option_name(name) || std::find(held_.begin(), held_.end(), name) != held_.end())
      continue;
    const bool valued = k + 1 < tokens.size() && !is_petsc_option_name(tokens[k + 1]);
    PetscBool set = PETSC_FALSE;
    FISSURE_PETSC_CALL(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &set));
    if (!set) {
      FISSURE_PETSC_CALL(
          PetscOptionsSetValue(nullptr, name.c_str(), valued ? tokens[k + 1].c_str() : nullptr));
      leased[name] = 0;
    }
    if (auto it = leased.find(name); it != leased.end()) {
      ++it->second;
      held_.push_back(name);
    }
  }
}

PetscOptionsLease::~PetscOptionsLease() {
  PetscBool finalized = PETSC_FALSE;
  PetscFinalized(&finalized);
  if (finalized) return;  // the database is gone with PETSc
  std::map<std::string, int>& leased = leased_options();
  for (const std::string& name : held_) {
    auto it = leased.find(name);
    if (it == leased.end() || --it->second > 0) continue;
    leased.erase(it);
    PetscOptionsClearValue(nullptr, name.c_str());  // a destructor does not throw
  }
}

}  // namespace fissure
#endif
