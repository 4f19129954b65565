#include "core/io/checkpoint.h"

#include <cmath>

namespace fissure {

namespace {

/// The dataset of a list column with the size of each element's field.
std::string sizes_name(const std::string& field) {
  return field + "@sizes";
}

}  // namespace

std::span<const double> CheckpointRow::field(const std::string& name) {
  const Column& c = column_(name);
  FISSURE_CHECK(row_ + 1 < c.offsets.size(), IoError,
                where_ << "/" << name << ": fewer elements than the list holds");
  return std::span<const double>(c.values).subspan(c.offsets[row_],
                                                   c.offsets[row_ + 1] - c.offsets[row_]);
}

CheckpointWriter::CheckpointWriter(Hdf5File& file, Hdf5Group group)
    : file_(&file), group_(std::make_shared<Hdf5Group>(std::move(group))) {}

CheckpointWriter CheckpointWriter::section(const std::string& name) {
  return CheckpointWriter(*file_, file_->create_group(*group_, name));
}

void CheckpointWriter::write_numbers(const std::string& name, const std::vector<double>& values) {
  file_->write(*group_, name, std::span<const double>(values), {values.size()});
}

void CheckpointWriter::write_strings(const std::string& name,
                                     const std::vector<std::string>& values) {
  file_->write_strings(*group_, name, values);
}

void CheckpointWriter::write_list(const std::string& name, std::size_t count,
                                  const CheckpointColumns& columns) {
  CheckpointWriter list = section(name);
  list("count", static_cast<double>(count));
  for (const auto& [field, column] : columns.columns_) {
    list.write_numbers(field, column.values);
    list.write_numbers(sizes_name(field), column.sizes);
  }
}

CheckpointReader::CheckpointReader(Hdf5File& file, Hdf5Group group)
    : file_(&file), group_(std::make_shared<Hdf5Group>(std::move(group))) {}

std::string CheckpointReader::where(const std::string& name) const {
  return file_->path().string() + ": " + (group_->path == "/" ? "" : group_->path) + "/" + name;
}

bool CheckpointReader::has(const std::string& name) {
  return file_->exists(*group_, name);
}

CheckpointReader CheckpointReader::section(const std::string& name) {
  FISSURE_CHECK(has(name), IoError,
                where(name) << " is missing: the checkpoint is incomplete or was written by "
                               "another version of Fissure");
  return CheckpointReader(*file_, file_->open_group(*group_, name));
}

std::vector<double> CheckpointReader::read_numbers(const std::string& name) {
  FISSURE_CHECK(has(name), IoError,
                where(name) << " is missing: the checkpoint is incomplete or was written by "
                               "another version of Fissure");
  return file_->read_doubles(*group_, name);
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
  values = file_->read_strings(*group_, name);
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
