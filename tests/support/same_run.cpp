#include "tests/support/same_run.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "tests/support/results_file_reader.h"
#include "tests/support/run_scene.h"

namespace fissure::testing {

namespace fs = std::filesystem;

namespace {

/// Every dataset below `group` of two results.h5 files, equal to the bit;
/// returns how many were compared.
int compare_datasets(const test::H5Reader& a, const test::H5Reader& b, const std::string& group) {
  EXPECT_EQ(b.members(group), a.members(group)) << group;
  int compared = 0;
  for (const std::string& m : a.members(group)) {
    const std::string path = group + "/" + m;
    if (a.is_group(path)) {
      compared += compare_datasets(a, b, path);
    } else if (a.type(path).first == H5T_FLOAT) {
      EXPECT_EQ(a.doubles(path), b.doubles(path)) << path;
      ++compared;
    } else if (a.type(path).first == H5T_INTEGER) {
      EXPECT_EQ(a.ints(path), b.ints(path)) << path;
      ++compared;
    }
  }
  return compared;
}

}  // namespace

nlohmann::json comparable_summary(const fs::path& file) {
  nlohmann::json j = without_measured_times(nlohmann::json::parse(file_bytes(file)));
  // Erases `key` at `path` where the run has it (a thermal run has no mechanics).
  auto erase = [&j](std::initializer_list<const char*> path, const char* key) {
    nlohmann::json* node = &j;
    for (const char* p : path) {
      if (!node->is_object() || !node->contains(p)) return;
      node = &(*node)[p];
    }
    if (node->is_object()) node->erase(key);
  };
  // The checkpoints written, and where the run restarted from.
  erase({"processes", "coordinator"}, "checkpoints");
  // A restored factor of the mechanics is computed again from the matrix it
  // stands for. A restart analyses a sparsity pattern again.
  erase({"processes", "mechanics", "linear_solver", "reused_factorization"}, "factorizations");
  erase({"processes", "mechanics", "linear_solver", "reused_factorization"},
        "cholesky_factorizations");
  erase({"processes", "mechanics", "linear_solver", "direct"}, "analyses");
  erase({"processes", "flow", "steady_solver", "linear_solver"}, "analyses");
  return j;
}

void expect_same_run(const fs::path& uninterrupted, const fs::path& restarted) {
  EXPECT_TRUE(file_bytes(uninterrupted / "monitors.csv") == file_bytes(restarted / "monitors.csv"))
      << "monitors.csv";
  EXPECT_TRUE(file_bytes(uninterrupted / "results.xdmf") == file_bytes(restarted / "results.xdmf"))
      << "results.xdmf";
  const test::H5Reader a(uninterrupted / "results.h5"), b(restarted / "results.h5");
  EXPECT_GT(compare_datasets(a, b, "/frames"), 0);
  EXPECT_EQ(comparable_summary(restarted / "summary.json"),
            comparable_summary(uninterrupted / "summary.json"));
}

}  // namespace fissure::testing
