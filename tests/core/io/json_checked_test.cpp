// The shared JSON reader: a number beyond a double, a key repeated in one object and
// a syntax error are lmc::Errors naming the file and the place, never the library's own text.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/common/error.h"
#include "core/io/json_checked.h"
#include "core/io/layout_json.h"
#include "tests/support/scratch_dir.h"

namespace lmc {
namespace {

std::string json_error_of(const std::string& text, const std::string& source = "in.json") {
  try {
    parse_json_text(text, source);
  } catch (const Error& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("not an lmc::Error: ") + e.what();
  }
  return "no error";
}

TEST(JsonChecked, NumberOverflowNamesFileAndPointer) {
  const std::string err = json_error_of(R"({"devices": [{"pose": {"x": 0}}, {"pose": {"y": 1, "x": 1e400}}]})");
  EXPECT_NE(err.find("in.json: at /devices/1/pose/x: "), std::string::npos) << err;
  EXPECT_NE(err.find("beyond the range of a double"), std::string::npos) << err;
  EXPECT_EQ(err.find("json.exception"), std::string::npos) << err;
  const std::string top = json_error_of("-1e999");
  EXPECT_NE(top.find("in.json: at /: "), std::string::npos) << top;
  const std::string escaped = json_error_of(R"({"a/b": {"c~d": [1, 2, 1e309]}})");
  EXPECT_NE(escaped.find("at /a~1b/c~0d/2: "), std::string::npos) << escaped;
}

TEST(JsonChecked, DuplicateKeysAreRefusedWithKeyAndPlace) {
  const std::string err = json_error_of(R"({"name": "a", "sensor": {"range_mm": 600, "range_mm": 60}})");
  EXPECT_NE(err.find("in.json: at /sensor/range_mm: "), std::string::npos) << err;
  EXPECT_NE(err.find("duplicate key 'range_mm'"), std::string::npos) << err;
  // The same key in sibling objects is fine.
  EXPECT_EQ(json_error_of(R"([{"a": 1}, {"a": 2}, {"b": {"a": 3}, "a": 4}])"), "no error");
}

TEST(JsonChecked, SyntaxErrorGivesLineAndColumnWithoutLibraryPrefix) {
  const std::string err = json_error_of("{\n  \"a\": 1,\n  \"b\": tru\n}");
  EXPECT_NE(err.find("in.json:3:"), std::string::npos) << err;
  EXPECT_NE(err.find("not valid JSON: "), std::string::npos) << err;
  EXPECT_EQ(err.find("json.exception"), std::string::npos) << err;
  EXPECT_EQ(err.find("parse error at line"), std::string::npos) << err;
}

TEST(JsonChecked, LayoutFileWithOverflowOrDuplicateNamesTheFile) {
  const auto dir = lmc::test::scratch_dir("json_checked");
  const auto path = dir / "hostile.json";
  std::ofstream(path) << R"({"format": 1, "name": "x", "sensor": {"range_mm": 1e400}})";
  try {
    load_layout(path);
    ADD_FAILURE() << "1e400 accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string() + ": at /sensor/range_mm: "), std::string::npos) << what;
  }
  std::ofstream(path) << R"({"format": 1, "name": "x", "name": "y"})";
  try {
    load_layout(path);
    ADD_FAILURE() << "duplicate key accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string() + ": at /name: duplicate key 'name'"), std::string::npos) << what;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lmc
