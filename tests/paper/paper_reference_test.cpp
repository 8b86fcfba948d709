// The paper's tables as results/paper.json holds them, read by the typed reader of every input: the committed file
// reads, and a bad field is named with its file and path.
#include "paper/paper_reference.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "base/input_error.h"

namespace tcsb {
namespace {

namespace fs = std::filesystem;

TEST(PaperReference, TheCommittedFileReadsWithBothTables) {
  const PaperReference ref = load_paper_reference(fs::path(TCSB_SOURCE_DIR) / "results" / "paper.json");
  EXPECT_FALSE(ref.table1.empty());
  EXPECT_FALSE(ref.table2.empty());
  EXPECT_GT(ref.time_ratio("30%"), 0.0);
}

/// The message load_paper_reference refuses `text` with, "" if it reads it.
std::string refusal(const std::string& text) {
  const fs::path file = fs::temp_directory_path() / ("tcsb_paper_reference_" + std::to_string(::getpid()) + ".json");
  std::ofstream(file) << text;
  std::string message;
  try {
    load_paper_reference(file);
  } catch (const InputError& e) {
    message = e.what();
  }
  fs::remove(file);
  return message;
}

TEST(PaperReference, ABadFieldIsNamedWithItsPath) {
  const std::string table1 = R"("table1": {"rows": []})";
  EXPECT_EQ(refusal("{" + table1 + R"(, "table2": {"rows": []}})"), "");
  const std::string row = R"({"method": "TC-SB", "compression": "30%", "N": 1, "L": 2, "I": 0, "total_ms": )";
  EXPECT_NE(refusal("{" + table1 + R"(, "table2": {"rows": [)" + row + R"("fast"}]}})").find("table2.rows[0].total_ms"),
            std::string::npos);
  EXPECT_NE(refusal("{" + table1 + R"(, "table2": {"rows": [)" + row + "-1}]}}").find("table2.rows[0].total_ms"),
            std::string::npos)
      << "a time is never negative";
  EXPECT_NE(refusal("{" + table1 + "}").find("table2"), std::string::npos) << "a table missing";
}

}  // namespace
}  // namespace tcsb
