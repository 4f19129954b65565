// Every key of a REV study's mechanics section is documented in
// docs/upscaling.md section 3.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "coupling/upscaling/stress_study.h"

namespace fissure {
namespace {

TEST(RevStressKeys, DocumentationListsEveryMechanicsKey) {
  std::ifstream in(std::filesystem::path(FISSURE_SOURCE_DIR) / "docs" / "upscaling.md");
  ASSERT_TRUE(in) << "docs/upscaling.md not found";
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::vector<std::string> keys = stress_study_keys();
  EXPECT_GT(keys.size(), 10u);
  for (const std::string& key : keys)
    EXPECT_NE(doc.find("| `" + key + "` |"), std::string::npos)
        << "docs/upscaling.md does not document the REV study key `" << key << "`";
}

}  // namespace
}  // namespace fissure
