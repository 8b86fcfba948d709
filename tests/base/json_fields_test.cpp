// The one typed reader of every JSON input: its integer rule (3.0 is 3), its null rule (only where a field may be
// null), and its messages naming the file and the field, the same for both JSON types the inputs are parsed into.
#include "base/json_fields.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace tcsb {
namespace {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

/// The message of the InputError `read` throws ("" when it throws none).
template <class Read>
std::string error_of(Read read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonFields, AnIntegerIsANumberWithoutAFractionalPart) {
  const JsonFields<json> f("s.json");
  EXPECT_EQ(f.integer(json(3), "n", 0, 10), 3);
  EXPECT_EQ(f.integer(json(3.0), "n", 0, 10), 3) << "3.0 is an integer, as JSON Schema has it";
  EXPECT_EQ(f.integer(json(-2.0), "n", -5, 10), -2);
  EXPECT_EQ(f.unsigned_integer(json(7.0), "n"), 7u);
  EXPECT_EQ(error_of([&] { f.integer(json(3.5), "n", 0, 10); }), "s.json: n: must be an integer in [0, 10], got 3.5");
  EXPECT_EQ(error_of([&] { f.integer(json(11.0), "n", 0, 10); }), "s.json: n: must be an integer in [0, 10], got 11.0");
  // Beyond 2^53 a float is not exactly the integer it looks like.
  EXPECT_NE(error_of([&] { f.integer(json(0x1p60), "n", 0, std::numeric_limits<std::int64_t>::max()); }), "");
  EXPECT_EQ(error_of([&] { f.integer(json(std::numeric_limits<std::uint64_t>::max()), "n", 0, 10); }),
            "s.json: n: must be an integer in [0, 10], got 18446744073709551615");
  EXPECT_EQ(error_of([&] { f.integer(json("3"), "n", 0, 10); }),
            "s.json: n: must be an integer in [0, 10], got string \"3\"");
  EXPECT_EQ(error_of([&] { f.unsigned_integer(json(-1), "n"); }), "s.json: n: must be a non-negative integer, got -1");
}

TEST(JsonFields, NullIsReadOnlyWhereAFieldMayBeNull) {
  const JsonFields<ojson> f("r.json");
  const ojson doc = {{"a", nullptr}, {"b", 2.5}, {"c", -1.0}, {"n", nullptr}};
  EXPECT_FALSE(f.number_or_null(doc, "x", "a").has_value());
  EXPECT_EQ(f.number_or_null(doc, "x", "b"), 2.5);
  EXPECT_FALSE(f.integer_or_null(doc, "x", "n").has_value());
  EXPECT_EQ(error_of([&] { f.integer(doc, "x", "a"); }), "r.json: x.a: must be an integer, got null");
  EXPECT_EQ(error_of([&] { f.number(doc["a"], "x.a", kAnyFinite); }), "r.json: x.a: must be a finite number, got null");
  EXPECT_EQ(error_of([&] { f.string(doc, "x", "a"); }), "r.json: x.a: must be a string, got null");
  EXPECT_EQ(error_of([&] { f.non_negative_or_null(doc, "x", "c"); }),
            "r.json: x.c: must be a finite number >= 0 or null, got -1.0");
}

TEST(JsonFields, MembersAreNamedByTheirPath) {
  const JsonFields<ojson> f("r.json");
  const ojson doc = {{"cases", ojson::array({ojson::object()})}, {"s", "text"}};
  EXPECT_EQ(error_of([&] { f.string(doc["cases"][0], index_path("cases", 0), "label"); }),
            "r.json: cases[0].label: required key is missing");
  EXPECT_EQ(error_of([&] { f.member(doc, "", "absent"); }), "r.json: absent: required key is missing");
  EXPECT_EQ(error_of([&] { f.array(doc, "", "s"); }), "r.json: s: must be an array, got string \"text\"");
  EXPECT_EQ(error_of([&] { f.member(doc["s"], "s", "x"); }), "r.json: s: must be an object, got string \"text\"");
  EXPECT_EQ(f.find(doc, "", "absent"), nullptr);
  EXPECT_EQ(f.string(doc, "", "s"), "text");
}

TEST(JsonFields, AnEmptyArrayIsRefusedUnlessAllowed) {
  const JsonFields<json> f("s.json");
  EXPECT_EQ(error_of([&] { f.array(json::array(), "nets"); }), "s.json: nets: must not be empty");
  EXPECT_TRUE(f.array(json::array(), "nets", EmptyArray::kAllowed).empty());
}

}  // namespace
}  // namespace tcsb
