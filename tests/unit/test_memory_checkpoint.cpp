// core/io/memory_checkpoint.h: the checkpoint archives over a tree in
// memory, which the coordinator rolls coupling steps back with. What is
// written is read back to the bit (numbers, fixed and dynamic matrices,
// lists of structures, strings, sections), a missing name is a located
// IoError, and a name written twice a programming error.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "core/io/memory_checkpoint.h"

namespace fissure {
namespace {

struct Item {
  int id = 0;
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  std::vector<double> history;
};

template <class Archive>
void checkpoint(Archive& a, double& x, Eigen::MatrixXd& m, std::vector<Item>& items,
                std::string& label) {
  a("x", x);
  a("m", m);
  auto part = a.section("part");
  part.list("items", items, [](auto& e, auto& i) {
    e("id", i.id);
    e("at", i.at);
    e("history", i.history);
  });
  part("label", label);
}

TEST(memory_checkpoint, ReadsBackWhatWasWrittenToTheBit) {
  double x = std::nextafter(0.1, 1.0);
  Eigen::MatrixXd m(2, 3);
  m << 1, 2, 3, 4, 5, std::sqrt(2.0);
  std::vector<Item> items = {{3, {0.5, -1e-300}, {1, 2}}, {7, {2, 3}, {}}};
  std::string label = "state";
  MemoryCheckpoint saved;
  CheckpointWriter writer = saved.writer();
  checkpoint(writer, x, m, items, label);

  for (int twice = 0; twice < 2; ++twice) {  // read as often as needed
    double x2 = 0;
    Eigen::MatrixXd m2;
    std::vector<Item> items2;
    std::string label2;
    CheckpointReader reader = saved.reader();
    checkpoint(reader, x2, m2, items2, label2);
    EXPECT_EQ(x2, x);
    EXPECT_EQ(m2, m);
    ASSERT_EQ(items2.size(), 2u);
    for (std::size_t k = 0; k < items.size(); ++k) {
      EXPECT_EQ(items2[k].id, items[k].id);
      EXPECT_EQ(items2[k].at, items[k].at);
      EXPECT_EQ(items2[k].history, items[k].history);
    }
    EXPECT_EQ(label2, label);
  }
}

TEST(memory_checkpoint, AMissingNameIsLocatedAndANameIsWrittenOnce) {
  MemoryCheckpoint saved;
  CheckpointWriter writer = saved.writer();
  auto part = writer.section("part");
  part("x", 1.0);
  EXPECT_THROW(part("x", 2.0), std::logic_error);
  CheckpointReader reader = saved.reader();
  auto read_part = reader.section("part");
  double y = 0;
  try {
    read_part("y", y);
    FAIL() << "no error";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("memory checkpoint: /part/y"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(reader.section("other"), IoError);
}

}  // namespace
}  // namespace fissure
