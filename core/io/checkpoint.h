// Checkpoints (issue 22, item 6; docs/output.md "Checkpoint and restart"):
// the complete state of a run in an HDF5 file, from which `fissure run
// --restart` continues to the bit. Every class that carries state from step
// to step writes and reads it with one function template, so that what is
// saved and what is restored cannot drift apart (cereal's pattern):
//
//   template <class Self, class Archive> static void checkpoint(Self& self, Archive& a) {
//     a("next_step", self.next_step_);
//     a.list("items", self.items_, [](auto& e, auto& i) { e("value", i.value); ... });
//     auto part = a.section("part");  Part::checkpoint(self.part_, part); ...
//   }
//
// `save() const` calls checkpoint(*this, writer) with Self const (a writer
// only reads the values), `restore()` calls checkpoint(*this, reader): one
// function without a const_cast. What only reading does (a default for a
// key older checkpoints lack, a cache to drop) sits under
// `if constexpr (Archive::reading)`. A part held through a pointer is passed
// as const_like<Self>(*self.part_): a pointer does not pass its owner's
// constness on.
//
// CheckpointWriter and CheckpointReader are the two archives, over a
// CheckpointNode: a group of an HDF5 file (checkpoint files) or a tree in
// memory (memory_checkpoint.h: the coordinator's rollback of a coupling
// step, taken every step and so kept free of a file's per-dataset cost). A value is a
// number (any arithmetic or enum type), a fixed or dynamic Eigen matrix, a
// std::vector of numbers or of fixed-size Eigen matrices, or a string; all
// numbers are stored as doubles (integers up to 2^53 exactly), bit for bit.
// A list of structures is stored as one dataset per field (struct of
// arrays), so that a list of thousands of items takes a few datasets, not
// thousands of groups.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/base/errors.h"
#include "core/io/hdf5_file.h"

namespace fissure {

/// `part` as const as `Self`: what checkpoint(self, a) passes on to a part
/// it holds through a pointer.
template <class Self, class T>
constexpr auto& const_like(T& part) {
  if constexpr (std::is_const_v<Self>)
    return std::as_const(part);
  else
    return part;
}

namespace checkpoint_codec {

template <class T>
struct IsEigen : std::is_base_of<Eigen::EigenBase<T>, T> {};

template <class T>
struct IsVector : std::false_type {};
template <class T, class A>
struct IsVector<std::vector<T, A>> : std::true_type {};

/// Values of a fixed width (numbers, fixed-size Eigen matrices): their width.
template <class T>
constexpr int fixed_width() {
  if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
    return 1;
  } else if constexpr (IsEigen<T>::value) {
    if constexpr (T::SizeAtCompileTime != Eigen::Dynamic) return T::SizeAtCompileTime;
    return 0;
  } else {
    return 0;
  }
}

/// Appends the value's numbers to `out`.
template <class T>
void encode(const T& v, std::vector<double>& out) {
  if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
    out.push_back(static_cast<double>(v));
  } else if constexpr (IsEigen<T>::value) {
    if constexpr (fixed_width<T>() == 0) {  // dynamic: its shape first
      out.push_back(static_cast<double>(v.rows()));
      out.push_back(static_cast<double>(v.cols()));
    }
    for (Eigen::Index c = 0; c < v.cols(); ++c)
      for (Eigen::Index r = 0; r < v.rows(); ++r) out.push_back(v(r, c));
  } else if constexpr (IsVector<T>::value) {
    using E = typename T::value_type;
    static_assert(fixed_width<E>() > 0, "a checkpointed vector holds numbers or fixed matrices");
    for (const E& e : v) encode(static_cast<const E&>(e), out);
  } else {
    static_assert(sizeof(T) == 0, "no checkpoint encoding for this type");
  }
}

/// Decodes a value from exactly the numbers `in`; false if they do not fit.
template <class T>
bool decode(std::span<const double> in, T& v) {
  if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
    if (in.size() != 1) return false;
    if constexpr (std::is_enum_v<T>)
      v = static_cast<T>(static_cast<std::underlying_type_t<T>>(in[0]));
    else
      v = static_cast<T>(in[0]);
    return true;
  } else if constexpr (IsEigen<T>::value) {
    std::size_t k = 0;
    if constexpr (fixed_width<T>() == 0) {
      if (in.size() < 2) return false;
      const auto rows = static_cast<Eigen::Index>(in[0]), cols = static_cast<Eigen::Index>(in[1]);
      if (rows < 0 || cols < 0 || in.size() != 2 + static_cast<std::size_t>(rows * cols))
        return false;
      v.resize(rows, cols);
      k = 2;
    } else if (in.size() != static_cast<std::size_t>(fixed_width<T>())) {
      return false;
    }
    for (Eigen::Index c = 0; c < v.cols(); ++c)
      for (Eigen::Index r = 0; r < v.rows(); ++r) v(r, c) = in[k++];
    return true;
  } else if constexpr (IsVector<T>::value) {
    using E = typename T::value_type;
    constexpr std::size_t w = fixed_width<E>();
    if (in.size() % w != 0) return false;
    v.resize(in.size() / w);
    for (std::size_t i = 0; i < v.size(); ++i) {
      E e{};
      if (!decode(in.subspan(i * w, w), e)) return false;
      v[i] = e;
    }
    return true;
  } else {
    static_assert(sizeof(T) == 0, "no checkpoint encoding for this type");
  }
}

}  // namespace checkpoint_codec

/// Where an archive's values are stored: one group (of an HDF5 file, or of
/// a tree in memory) with named datasets of numbers or strings and named
/// sub-groups.
class CheckpointNode {
 public:
  virtual ~CheckpointNode() = default;
  virtual std::shared_ptr<CheckpointNode> create_child(const std::string& name) = 0;
  virtual std::shared_ptr<CheckpointNode> open_child(const std::string& name) = 0;
  /// Whether it has a dataset or a group `name`.
  virtual bool has(const std::string& name) = 0;
  virtual void write_numbers(const std::string& name, const std::vector<double>& values) = 0;
  virtual void write_strings(const std::string& name, const std::vector<std::string>& values) = 0;
  virtual std::vector<double> read_numbers(const std::string& name) = 0;
  virtual std::vector<std::string> read_strings(const std::string& name) = 0;
  /// "file: /group/name", for messages.
  virtual std::string where(const std::string& name) const = 0;
};

/// The fields of one list element, collected into columns (writer side).
class CheckpointColumns {
 public:
  template <class T>
  void operator()(const std::string& name, const T& value) {
    Column& c = column(name);
    const std::size_t before = c.values.size();
    checkpoint_codec::encode(value, c.values);
    c.sizes.push_back(static_cast<double>(c.values.size() - before));
  }

 private:
  friend class CheckpointWriter;
  struct Column {
    std::string name;
    std::vector<double> values, sizes;
  };
  /// The column `name`. Every element names its fields in the same order,
  /// so the next one is looked for first where the last one was: a list of
  /// thousands of elements is collected at the cost of copying it (the
  /// coordinator saves one every coupling step, memory_checkpoint.h).
  Column& column(const std::string& name);

  std::vector<Column> columns_;  ///< in the order of their first field
  std::size_t next_ = 0;
};

/// One list element's fields, read from columns (reader side).
class CheckpointRow {
 public:
  template <class T>
  void operator()(const std::string& name, T& value) {
    const std::span<const double> in = field(name);
    FISSURE_CHECK(checkpoint_codec::decode(in, value), IoError,
                  where_ << "/" << name << ": element " << row_ << " has the wrong size");
  }

 private:
  friend class CheckpointReader;
  std::span<const double> field(const std::string& name);
  struct Column {
    std::vector<double> values;
    std::vector<std::size_t> offsets;  ///< per element, and the end
  };
  std::function<const Column&(const std::string&)> column_;
  std::string where_;
  std::size_t row_ = 0;
};

class CheckpointWriter {
 public:
  static constexpr bool reading = false;
  /// Writes into `group` of `file` (the file must outlive the writer).
  CheckpointWriter(Hdf5File& file, Hdf5Group group);
  explicit CheckpointWriter(std::shared_ptr<CheckpointNode> node) : node_(std::move(node)) {}

  /// A sub-group for one part of the state.
  CheckpointWriter section(const std::string& name);

  template <class T>
  void operator()(const std::string& name, const T& value) {
    std::vector<double> values;
    checkpoint_codec::encode(value, values);
    write_numbers(name, values);
  }
  void operator()(const std::string& name, const std::string& value) {
    write_strings(name, {value});
  }
  void operator()(const std::string& name, const std::vector<std::string>& values) {
    write_strings(name, values);
  }

  /// A list of structures (a std::vector): `fields(columns, item)` names
  /// each field of an item (generic in the item: const here, not when read).
  template <class List, class Fields>
  void list(const std::string& name, const List& items, Fields&& fields) {
    CheckpointColumns columns;
    for (const auto& item : items) fields(columns, item);
    write_list(name, items.size(), columns);
  }

 private:
  void write_numbers(const std::string& name, const std::vector<double>& values);
  void write_strings(const std::string& name, const std::vector<std::string>& values);
  void write_list(const std::string& name, std::size_t count, const CheckpointColumns& columns);

  std::shared_ptr<CheckpointNode> node_;
};

class CheckpointReader {
 public:
  static constexpr bool reading = true;
  CheckpointReader(Hdf5File& file, Hdf5Group group);
  explicit CheckpointReader(std::shared_ptr<CheckpointNode> node) : node_(std::move(node)) {}

  CheckpointReader section(const std::string& name);
  bool has(const std::string& name);

  template <class T>
  void operator()(const std::string& name, T& value) {
    const std::vector<double> values = read_numbers(name);
    FISSURE_CHECK(checkpoint_codec::decode(std::span<const double>(values), value), IoError,
                  where(name) << ": the stored value has the wrong size");
  }
  void operator()(const std::string& name, std::string& value);
  void operator()(const std::string& name, std::vector<std::string>& values);

  template <class List, class Fields>
  void list(const std::string& name, List& items, Fields&& fields) {
    CheckpointRow row;
    const std::size_t count = open_list(name, row);
    items.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      row.row_ = i;
      fields(row, items[i]);
    }
  }

 private:
  std::vector<double> read_numbers(const std::string& name);
  std::size_t open_list(const std::string& name, CheckpointRow& row);
  std::string where(const std::string& name) const;

  std::shared_ptr<CheckpointNode> node_;
};

}  // namespace fissure
