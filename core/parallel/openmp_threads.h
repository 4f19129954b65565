// The OpenMP threads of the calling thread's parallel regions (the DEM's
// cycle): a driver that already spreads its work over threads of its own
// (the REV study's domains) gives each of them one, so that two levels of
// threads do not compete for the cores.
#pragma once

namespace fissure {

/// Sets the calling thread's OpenMP threads (its own ICV) for its lifetime
/// and restores the previous number after.
class OpenMpThreadsOfThisThread {
 public:
  explicit OpenMpThreadsOfThisThread(int n);
  ~OpenMpThreadsOfThisThread();
  OpenMpThreadsOfThisThread(const OpenMpThreadsOfThisThread&) = delete;
  OpenMpThreadsOfThisThread& operator=(const OpenMpThreadsOfThisThread&) = delete;

 private:
  int before_;
};

}  // namespace fissure
