#include "core/base/memory_budget.h"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "core/base/errors.h"

namespace fissure {

namespace {

std::atomic<double> chosen_budget{0};

/// The value, in bytes, of a "Key: N kB" line of a /proc file (0 when
/// there is none).
double proc_bytes(const char* file, std::string_view key) {
  std::ifstream in(file);
  std::string name;
  double kilobytes = 0;
  while (in >> name) {
    if (name == key && in >> kilobytes) return kilobytes * 1024;
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return 0;
}

/// MemAvailable (what can be allocated without swapping), else the
/// physical memory.
double available_memory() {
  const double available = proc_bytes("/proc/meminfo", "MemAvailable:");
  if (available > 0) return available;
  return static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

/// VmSize: the address space the process maps already (its libraries,
/// PETSc's and Open MPI's among them: about 390 MB for a DDA run), which an
/// address-space limit counts too.
double mapped_address_space() {
  return proc_bytes("/proc/self/status", "VmSize:");
}

/// The budget when none is set: what was available at the first question
/// (the command's start), not what its own allocations have left since,
/// and where it comes from, for messages.
struct MachineBudget {
  double bytes;
  const char* source;
};

const MachineBudget& machine_budget() {
  static const MachineBudget machine = [] {
    MachineBudget m{available_memory(), "the memory this machine has available"};
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
      const double address_space = static_cast<double>(limit.rlim_cur) - mapped_address_space();
      if (address_space < m.bytes)
        m = {address_space, "the address-space limit (ulimit -v) less what the process maps"};
    }
    return m;
  }();
  return machine;
}

}  // namespace

double memory_budget() {
  const double chosen = chosen_budget.load();
  return chosen > 0 ? chosen : machine_budget().bytes;
}

void set_memory_budget(double bytes) {
  chosen_budget = bytes;
}

double parse_memory_size(const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  std::string unit = text.substr(used);
  unit.erase(0, unit.find_first_not_of(' '));
  static const std::pair<const char*, double> units[] = {{"", 1},
                                                         {"B", 1},
                                                         {"kB", 1e3},
                                                         {"MB", 1e6},
                                                         {"GB", 1e9},
                                                         {"TB", 1e12},
                                                         {"KiB", 1024.0},
                                                         {"MiB", 1048576.0},
                                                         {"GiB", 1073741824.0},
                                                         {"TiB", 1099511627776.0}};
  for (const auto& [name, factor] : units)
    if (used > 0 && unit == name && std::isfinite(value) && value > 0) return value * factor;
  throw Error(
      fmt::format("found '{}'; expected a memory size > 0 such as 8 GB, 512 MB or 1.5 GiB", text));
}

std::string format_bytes(double bytes) {
  if (bytes >= 1e9) return fmt::format("{:.3g} GB", bytes / 1e9);
  return fmt::format("{:.3g} MB", bytes / 1e6);
}

void check_memory(double bytes, std::string_view where, std::string_view what) {
  const double budget = memory_budget();
  FISSURE_CHECK(
      !(bytes > budget), SceneError,
      where << ": found " << what << ", which needs at least " << format_bytes(bytes)
            << " of memory; expected at most the memory budget of " << format_bytes(budget)
            << (chosen_budget.load() > 0
                    ? std::string(" (--memory-limit)")
                    : fmt::format(" ({}; --memory-limit sets another)", machine_budget().source)));
}

}  // namespace fissure
