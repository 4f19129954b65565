#include "core/io/memory_checkpoint.h"

#include <map>
#include <string>
#include <vector>

#include "core/base/errors.h"

namespace fissure {

namespace {

/// One group: its datasets and sub-groups by name.
class MemoryNode final : public CheckpointNode {
 public:
  explicit MemoryNode(std::string path) : path_(std::move(path)) {}

  std::shared_ptr<CheckpointNode> create_child(const std::string& name) override {
    check_new(name);
    auto child = std::make_shared<MemoryNode>(where(name));
    children_[name] = child;
    return child;
  }
  std::shared_ptr<CheckpointNode> open_child(const std::string& name) override {
    const auto it = children_.find(name);
    FISSURE_CHECK(it != children_.end(), IoError, where(name) << ": no such group");
    return it->second;
  }
  bool has(const std::string& name) override {
    return children_.count(name) || numbers_.count(name) || strings_.count(name);
  }
  void write_numbers(const std::string& name, const std::vector<double>& values) override {
    check_new(name);
    numbers_[name] = values;
  }
  void write_strings(const std::string& name, const std::vector<std::string>& values) override {
    check_new(name);
    strings_[name] = values;
  }
  std::vector<double> read_numbers(const std::string& name) override {
    const auto it = numbers_.find(name);
    FISSURE_CHECK(it != numbers_.end(), IoError, where(name) << ": no dataset of numbers");
    return it->second;
  }
  std::vector<std::string> read_strings(const std::string& name) override {
    const auto it = strings_.find(name);
    FISSURE_CHECK(it != strings_.end(), IoError, where(name) << ": no dataset of strings");
    return it->second;
  }
  std::string where(const std::string& name) const override {
    return "memory checkpoint: " + path_ + "/" + name;
  }

 private:
  /// As in a file, a name is written once.
  void check_new(const std::string& name) {
    FISSURE_CHECK(!has(name), std::logic_error, where(name) << " is written twice");
  }

  std::string path_;
  std::map<std::string, std::shared_ptr<MemoryNode>> children_;
  std::map<std::string, std::vector<double>> numbers_;
  std::map<std::string, std::vector<std::string>> strings_;
};

}  // namespace

MemoryCheckpoint::MemoryCheckpoint() : root_(std::make_shared<MemoryNode>("")) {}

CheckpointWriter MemoryCheckpoint::writer() {
  return CheckpointWriter(root_);
}

CheckpointReader MemoryCheckpoint::reader() {
  return CheckpointReader(root_);
}

}  // namespace fissure
