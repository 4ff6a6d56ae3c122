// JSON text (core/io/json_text.h): a top-level array read element by element hands over the same
// elements a whole parse gives, in order, one at a time, with the same errors in the same words.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/json_text.h"
#include "core/support/error.h"
#include "tests/support/error_of.h"

namespace gps {
namespace {

using Json = nlohmann::json;

std::vector<Json> elements_of(const std::string& text, bool* array = nullptr) {
  std::vector<Json> out;
  std::vector<size_t> indices;
  const bool is_array = parse_json_array(text, "ops.json", "ops", [&](size_t i, Json&& element) {
    indices.push_back(i);
    out.push_back(std::move(element));
  });
  for (size_t i = 0; i < indices.size(); ++i) EXPECT_EQ(indices[i], i);
  if (array) *array = is_array;
  return out;
}

std::string parse_error(const std::string& text) {
  try {
    elements_of(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(JsonText, AnArraysElementsAreThoseOfAWholeParse) {
  const std::string text =
      R"([{"op": "add", "shape": "cube", "size": [1, 2.5, {"deep": [[], {}]}]}, 7, "text", null, true, [1, [2]], -3e5])";
  bool array = false;
  const std::vector<Json> elements = elements_of(text, &array);
  EXPECT_TRUE(array);
  const Json whole = parse_json(text, "ops.json", "ops");
  ASSERT_EQ(elements.size(), whole.size());
  for (size_t i = 0; i < elements.size(); ++i) EXPECT_EQ(elements[i], whole[i]) << i;
  EXPECT_TRUE(elements_of(" [ ] ").empty());
}

TEST(JsonText, ValidJsonThatIsNotAnArrayGivesNoElements) {
  for (const std::string text : {R"({"op": "add"})", "3", "\"ops\"", "null"}) {
    bool array = true;
    EXPECT_TRUE(elements_of(text, &array).empty()) << text;
    EXPECT_FALSE(array) << text;
  }
}

std::string whole_parse_error(const std::string& text) {
  try {
    parse_json(text, "ops.json", "ops");
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(JsonText, ErrorsAreAWholeParses) {
  for (const std::string text : {R"([{"op": "add"}, {"op": )", R"({"op": )", "[1, 2] 3", "[1, 2,]", "[[[1]]"}) {
    EXPECT_EQ(parse_error(text), whole_parse_error(text));
    EXPECT_NE(parse_error(text).find("ops.json: not valid JSON (byte "), std::string::npos) << text;
  }
  EXPECT_EQ(parse_error(std::string("[1]\0x", 5)), "ops.json: not valid JSON (a NUL byte at byte 4)");
  EXPECT_EQ(parse_error(R"([{"op": "add"}, {"op": "extrude", "distance": 1e999}])"),
            "ops.json: ops[1].distance: a number beyond the range of a double");
  EXPECT_EQ(parse_error(R"([1, [2, 3e999]])"), "ops.json: ops[1][1]: a number beyond the range of a double");
  // A key given twice was the last one silently; a number that underflows was 0.
  EXPECT_EQ(parse_error(R"([{"op": "bevel", "width": 0.2, "width": 0.3}])"),
            "ops.json: ops[0].width: the key is given twice in its object");
  EXPECT_EQ(parse_error(R"([{"op": "subdivide", "op": "merge"}])"),
            "ops.json: ops[0].op: the key is given twice in its object");
  EXPECT_EQ(parse_error(R"([{"op": "extrude", "distance": 1e-400}])"),
            "ops.json: ops[0].distance: a number too small for a double (it would be read as 0)");
  EXPECT_NO_THROW(parse_json(R"([0.0, 0e5, 0.000e-400, -0.0, 1e-300, {"a": {"a": 1}}])", "ok.json"));
}

// Nesting past 64 levels is refused as it is read, naming where (a DOM of a million empty arrays would
// take a hundred times the file); 64 levels are read.
TEST(JsonText, NestingPast64LevelsIsRefusedAsRead) {
  const auto nested = [](size_t n) { return std::string(n, '[') + std::string(n, ']'); };
  EXPECT_NO_THROW(parse_json(nested(64), "a.json"));
  const std::string suffix = ": nested more than 64 levels deep";
  const std::string deep = test::error_of([&] { parse_json(nested(65), "a.json", "ops"); });
  EXPECT_EQ(deep.rfind("a.json: ops[0][0]", 0), 0u) << deep;
  EXPECT_EQ(deep.substr(deep.size() - suffix.size()), suffix) << deep;
  const std::string edits =
      test::error_of([&] { parse_json(R"({"renders":[{"edits":)" + nested(1000000) + "}]}", "s.json"); });
  EXPECT_EQ(edits.rfind("s.json: renders[0].edits[0]", 0), 0u) << edits.substr(0, 100);
  EXPECT_LT(edits.size(), 400u);
}

TEST(JsonText, WhatTheSinkThrowsStopsTheRead) {
  size_t calls = 0;
  EXPECT_THROW(parse_json_array("[1, 2, 3, 4]", "", "ops",
                                [&](size_t i, Json&&) {
                                  ++calls;
                                  if (i == 1) throw usage_error("stop");
                                }),
               Error);
  EXPECT_EQ(calls, 2u);
}

}  // namespace
}  // namespace gps
