#include "core/io/checkpoint.h"

#include <algorithm>
#include <cmath>

namespace fissure {

namespace {

/// The dataset of a list column with the size of each element's field.
std::string sizes_name(const std::string& field) {
  return field + "@sizes";
}

/// A group of an HDF5 file.
class Hdf5Node final : public CheckpointNode {
 public:
  Hdf5Node(Hdf5File& file, Hdf5Group group) : file_(&file), group_(std::move(group)) {}

  std::shared_ptr<CheckpointNode> create_child(const std::string& name) override {
    return std::make_shared<Hdf5Node>(*file_, file_->create_group(group_, name));
  }
  std::shared_ptr<CheckpointNode> open_child(const std::string& name) override {
    return std::make_shared<Hdf5Node>(*file_, file_->open_group(group_, name));
  }
  bool has(const std::string& name) override { return file_->exists(group_, name); }
  void write_numbers(const std::string& name, const std::vector<double>& values) override {
    file_->write(group_, name, std::span<const double>(values), {values.size()});
  }
  void write_strings(const std::string& name, const std::vector<std::string>& values) override {
    file_->write_strings(group_, name, values);
  }
  std::vector<double> read_numbers(const std::string& name) override {
    return file_->read_doubles(group_, name);
  }
  std::vector<std::string> read_strings(const std::string& name) override {
    return file_->read_strings(group_, name);
  }
  std::string where(const std::string& name) const override {
    return file_->path().string() + ": " + (group_.path == "/" ? "" : group_.path) + "/" + name;
  }

 private:
  Hdf5File* file_;
  Hdf5Group group_;
};

}  // namespace

std::span<const double> CheckpointRow::field(const std::string& name) {
  const Column& c = column_(name);
  FISSURE_CHECK(row_ + 1 < c.offsets.size(), IoError,
                where_ << "/" << name << ": fewer elements than the list holds");
  return std::span<const double>(c.values).subspan(c.offsets[row_],
                                                   c.offsets[row_ + 1] - c.offsets[row_]);
}

CheckpointWriter::CheckpointWriter(Hdf5File& file, Hdf5Group group)
    : node_(std::make_shared<Hdf5Node>(file, std::move(group))) {}

CheckpointWriter CheckpointWriter::section(const std::string& name) {
  return CheckpointWriter(node_->create_child(name));
}

void CheckpointWriter::write_numbers(const std::string& name, const std::vector<double>& values) {
  node_->write_numbers(name, values);
}

void CheckpointWriter::write_strings(const std::string& name,
                                     const std::vector<std::string>& values) {
  node_->write_strings(name, values);
}

CheckpointColumns::Column& CheckpointColumns::column(const std::string& name) {
  if (next_ == columns_.size()) next_ = 0;  // the next element's first field
  if (next_ < columns_.size() && columns_[next_].name == name) return columns_[next_++];
  for (std::size_t k = 0; k < columns_.size(); ++k)
    if (columns_[k].name == name) {
      next_ = k + 1;
      return columns_[k];
    }
  columns_.push_back({name, {}, {}});
  next_ = columns_.size();
  return columns_.back();
}

void CheckpointWriter::write_list(const std::string& name, std::size_t count,
                                  const CheckpointColumns& columns) {
  CheckpointWriter list = section(name);
  list("count", static_cast<double>(count));
  // By name, as the datasets of a group are listed.
  std::vector<const CheckpointColumns::Column*> sorted;
  for (const CheckpointColumns::Column& c : columns.columns_) sorted.push_back(&c);
  std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->name < b->name; });
  for (const CheckpointColumns::Column* column : sorted) {
    list.write_numbers(column->name, column->values);
    list.write_numbers(sizes_name(column->name), column->sizes);
  }
}

CheckpointReader::CheckpointReader(Hdf5File& file, Hdf5Group group)
    : node_(std::make_shared<Hdf5Node>(file, std::move(group))) {}

std::string CheckpointReader::where(const std::string& name) const {
  return node_->where(name);
}

bool CheckpointReader::has(const std::string& name) {
  return node_->has(name);
}

CheckpointReader CheckpointReader::section(const std::string& name) {
  FISSURE_CHECK(has(name), IoError,
                where(name) << " is missing: the checkpoint is incomplete or was written by "
                               "another version of Fissure");
  return CheckpointReader(node_->open_child(name));
}

std::vector<double> CheckpointReader::read_numbers(const std::string& name) {
  FISSURE_CHECK(has(name), IoError,
                where(name) << " is missing: the checkpoint is incomplete or was written by "
                               "another version of Fissure");
  return node_->read_numbers(name);
}

void CheckpointReader::operator()(const std::string& name, std::string& value) {
  std::vector<std::string> values;
  (*this)(name, values);
  FISSURE_CHECK(values.size() == 1, IoError, where(name) << ": expected one string");
  value = values.front();
}

void CheckpointReader::operator()(const std::string& name, std::vector<std::string>& values) {
  FISSURE_CHECK(has(name), IoError,
                where(name) << " is missing: the checkpoint is incomplete or was written by "
                               "another version of Fissure");
  values = node_->read_strings(name);
}

std::size_t CheckpointReader::open_list(const std::string& name, CheckpointRow& row) {
  auto list = std::make_shared<CheckpointReader>(section(name));
  double count = 0;
  (*list)("count", count);
  FISSURE_CHECK(count >= 0 && count == std::floor(count), IoError,
                where(name) << ": not a list count: " << count);
  auto columns = std::make_shared<std::map<std::string, CheckpointRow::Column>>();
  row.where_ = where(name);
  // Columns are read when a field is first asked for.
  row.column_ = [list, columns](const std::string& field) -> const CheckpointRow::Column& {
    auto it = columns->find(field);
    if (it != columns->end()) return it->second;
    CheckpointRow::Column c;
    c.values = list->read_numbers(field);
    const std::vector<double> sizes = list->read_numbers(sizes_name(field));
    c.offsets.reserve(sizes.size() + 1);
    c.offsets.push_back(0);
    for (double s : sizes) c.offsets.push_back(c.offsets.back() + static_cast<std::size_t>(s));
    FISSURE_CHECK(c.offsets.back() == c.values.size(), IoError,
                  list->where(field) << ": its element sizes do not add up to its length");
    return columns->emplace(field, std::move(c)).first->second;
  };
  return static_cast<std::size_t>(count);
}

}  // namespace fissure
