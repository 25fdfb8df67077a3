// Bounded reading of a case file: the nesting limit with the line and column of the bracket that
// passes it, JSON paths rebuilt from the open levels, the size limit, non-regular files, and the
// rules for names that become file names.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_file.hpp"
#include "silodem/case/json_text.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/case/path_name.hpp"

using namespace silodem;
namespace fs = std::filesystem;

namespace {

std::string parse_error(const std::string& text) {
  try {
    parse_case_text(text, "case.json");
  } catch (const CaseError& e) {
    return e.what();
  }
  return "accepted";
}

std::string read_error(const fs::path& file) {
  try {
    read_case_text(file);
  } catch (const CaseError& e) {
    return e.what();
  }
  return "accepted";
}

std::string nested(int levels) { return std::string(std::size_t(levels), '[') + std::string(std::size_t(levels), ']'); }

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("silodem_limits_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(JsonText, NestingUpToTheLimitParsesOneLevelMoreIsRefusedWithItsPosition) {
  ASSERT_EQ(limits::kJsonDepth, 256);
  EXPECT_EQ(parse_error(nested(256)), "accepted");
  // The object is level 1, so the 256th '[' on the third line opens level 257: column 2 + 255.
  const std::string text = "{\n  \"a\": 1,\n  \"b\": " + nested(300) + "\n}";
  const std::string want = "case.json: line 3, column " + std::to_string(std::string("  \"b\": ").size() + 256) +
                           ": arrays and objects nested deeper than 256 levels";
  EXPECT_EQ(parse_error(text).rfind(want, 0), 0u) << parse_error(text);
  // Brackets inside strings do not count (the scan for the position skips strings, escapes too).
  const std::string strings = "{\"s\": \"[[[\\\"[[\", \"t\": " + nested(257) + "}";
  EXPECT_NE(parse_error(strings).find("line 1, column " + std::to_string(std::string("{\"s\": \"[[[\\\"[[\", \"t\": ").size() + 256)),
            std::string::npos)
      << parse_error(strings);
}

TEST(JsonText, PathsAreRebuiltFromTheOpenLevels) {
  // Every step kind: keys, indices after scalars, after nested arrays and after nested objects.
  EXPECT_EQ(parse_error(R"({"a": [1, {"x": 1}, [0, [0]], {"y": 1, "y": 2}]})").rfind("$.a[3].y: duplicate key", 0), 0u);
  EXPECT_EQ(parse_error(R"({"a": {"b": [true, null, "s", 1e400]}})").rfind("$.a.b[3]: out of range", 0), 0u);
  EXPECT_EQ(parse_error(R"({"a": 1, "b": {"c": [{}, {"d": 1, "d": 1}]}})").rfind("$.b.c[1].d: duplicate key", 0), 0u);
  EXPECT_EQ(parse_error("1e400").rfind("$: out of range", 0), 0u);
}

TEST(JsonText, SyntaxErrorsStillGiveTheParsersLineAndColumn) {
  EXPECT_NE(parse_error("{\n  \"a\": 1,\n}").find("line 3, column 1"), std::string::npos) << parse_error("{\n  \"a\": 1,\n}");
}

TEST(CaseFile, ALargerFileIsRefusedWithThePositionWhereItPassesTheLimit) {
  const fs::path d = scratch("size");
  const std::string head = "{\n\"name\": \"x\",\n";  // two lines, then the third runs to the limit
  {
    std::ofstream(d / "big.json") << head;
  }
  fs::resize_file(d / "big.json", limits::kCaseFileBytes + 100);  // sparse: no disk used
  const std::string e = read_error(d / "big.json");
  const std::size_t column = limits::kCaseFileBytes - head.size() + 1;  // of byte limit + 1
  EXPECT_EQ(e.rfind((d / "big.json").string() + ": line 3, column " + std::to_string(column) + " (byte " +
                        std::to_string(limits::kCaseFileBytes + 1) + "): the case file is larger than 512 MiB",
                    0),
            0u)
      << e;
  fs::remove_all(d);
}

TEST(CaseFile, OnlyRegularFilesAreRead) {
  const fs::path d = scratch("kinds");
  ASSERT_EQ(::mkfifo((d / "fifo").c_str(), 0600), 0);
  // Would block on open without a writer if it were opened for reading like a file.
  EXPECT_NE(read_error(d / "fifo").find("is a FIFO (named pipe), not a case file"), std::string::npos);
  EXPECT_NE(read_error("/dev/zero").find("/dev/zero: is a character device, not a case file"), std::string::npos);
  EXPECT_NE(read_error(d).find("is a directory, not a case file"), std::string::npos);
  EXPECT_NE(read_error(d / "missing.json").find("cannot open the case file: No such file or directory"), std::string::npos);
  std::ofstream(d / "ok.json") << "{\"a\": 1}";
  EXPECT_EQ(read_case_text(d / "ok.json"), "{\"a\": 1}");
  fs::create_symlink(d / "ok.json", d / "link.json");  // a link to a regular file is that file
  EXPECT_EQ(read_case_text(d / "link.json"), "{\"a\": 1}");
  fs::remove_all(d);
}

TEST(PathName, NamesThatCannotBeOneFileNameAreRefused) {
  for (const std::string& ok : std::vector<std::string>{"silo_fill", "D0_30 mm", "kügel", "a.b", "x..y", std::string(100, 'n')})
    EXPECT_EQ(path_name_problem(ok), "") << ok;
  EXPECT_NE(path_name_problem("").find("must not be empty"), std::string::npos);
  EXPECT_NE(path_name_problem("..").find("names a directory"), std::string::npos);
  EXPECT_NE(path_name_problem(".").find("names a directory"), std::string::npos);
  EXPECT_NE(path_name_problem(".hidden").find("must not begin with '.'"), std::string::npos);
  EXPECT_NE(path_name_problem("a/b").find("'/'"), std::string::npos);
  EXPECT_NE(path_name_problem("a\\b").find("'\\'"), std::string::npos);
  EXPECT_NE(path_name_problem("a\x01" "b").find("control character (byte 1)"), std::string::npos);
  EXPECT_NE(path_name_problem(std::string("a\0b", 3)).find("control character (byte 0)"), std::string::npos);
  EXPECT_NE(path_name_problem("tab\there").find("byte 9"), std::string::npos);
  EXPECT_NE(path_name_problem(std::string(101, 'n')).find("101 bytes long"), std::string::npos);
  try {
    require_path_name("a\x1b[31m", "$.name");
    FAIL() << "accepted";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.path(), "$.name");
    // The name is shown escaped: no raw escape character reaches the terminal.
    EXPECT_EQ(std::string(e.what()).find('\x1b'), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("\\u001b"), std::string::npos) << e.what();
  }
}
