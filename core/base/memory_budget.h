// The memory a command may use (issue 35, item 2), known before it is
// spent: every allocation whose size a scene drives (its YAML tree, the
// meshes and their systems) is estimated from the scene first and refused,
// with the scene line and the estimate, when it exceeds the budget. The
// budget is the machine's available memory (MemAvailable, within an
// address-space limit such as `ulimit -v`), or what `--memory-limit` says.
// The estimates are lower bounds measured on real scenes
// (docs/performance.md, "Memory"): a refused scene cannot fit; one that
// passes may still need more than its estimate.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fissure {

/// The budget in bytes: the one set, else the machine's available memory
/// when this was first asked (the command's start).
double memory_budget();
/// Sets the budget (--memory-limit); 0 returns to the machine's.
void set_memory_budget(double bytes);
/// "8 GB", "512 MB", "1.5 GiB", "2e9" (bytes) -> bytes; throws Error on
/// anything else (the command line reports it with the option's name).
double parse_memory_size(const std::string& text);
/// "1.43 GB" (decimal units, as the limit is given).
std::string format_bytes(double bytes);

/// Throws SceneError "`where`: found `what`, which needs at least N GB of
/// memory; expected at most the memory budget of M GB ..." when `bytes`
/// exceeds the budget. `where` is "file:line:column: key.path".
void check_memory(double bytes, std::string_view where, std::string_view what);

}  // namespace fissure
