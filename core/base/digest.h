// FNV-1a, 64 bits (Fowler, Noll, Vo; IETF draft-eastlake-fnv): the digest
// by which a checkpoint names the scene file it belongs to and proves that
// none of its own bytes changed after it was written
// (coupling/checkpoint_file.h). Not a cryptographic hash: it guards against
// corruption (a disk, a copy, a truncation), not against forgery.
#pragma once

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace fissure {

class Fnv1a64 {
 public:
  void add(std::span<const char> bytes) {
    for (const char c : bytes) {
      h_ ^= static_cast<unsigned char>(c);
      h_ *= 1099511628211ull;
    }
  }
  std::uint64_t value() const { return h_; }
  /// The value as 16 hexadecimal digits.
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h_));
    return text;
  }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

}  // namespace fissure
