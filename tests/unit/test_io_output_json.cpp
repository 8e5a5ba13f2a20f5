// JsonObject: ordered keys, replacement in place, escaping, null for non-finite numbers,
// exact number round trip.
#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>

#include "io/json_writer.h"

namespace slamsph {
namespace {

TEST(IoOutputJson, CompactOutputOrderAndTypes) {
  JsonObject inner;
  inner.set("peak [N/m]", 2796.5).set("ok", true);
  JsonObject o;
  o.set("name", "cylinder")
      .set("steps", 12345)
      .set("dt", 1e-7)
      .set("inner", inner)
      .set("series", std::vector<double>{1, 0.5, std::numeric_limits<double>::quiet_NaN()})
      .set("empty", JsonObject{})
      .set_null("nothing");
  EXPECT_EQ(o.to_string(false),
            "{\"name\":\"cylinder\",\"steps\":12345,\"dt\":1e-07,\"inner\":{\"peak "
            "[N/m]\":2796.5,\"ok\":true},\"series\":[1,0.5,null],\"empty\":{},\"nothing\":null}");
  o.set("steps", 7);  // replaced in place, order kept
  EXPECT_EQ(o.to_string(false).rfind("{\"name\":\"cylinder\",\"steps\":7,\"dt\":", 0), 0u);
  EXPECT_EQ(o.size(), 7u);
}

TEST(IoOutputJson, StringEscaping) {
  JsonObject o;
  o.set("s", std::string("a\"b\\c\nd\te\x01 f/é"));
  EXPECT_EQ(o.to_string(false), "{\"s\":\"a\\\"b\\\\c\\nd\\te\\u0001 f/é\"}");
  JsonObject k;
  k.set("quote\"key", false);
  EXPECT_EQ(k.to_string(false), "{\"quote\\\"key\":false}");
}

TEST(IoOutputJson, NonFiniteIsNullAndNumbersRoundTrip) {
  EXPECT_EQ(json_number(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(json_number(std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(json_number(-std::numeric_limits<double>::infinity()), "null");
  const double x = 0.1 + 0.2;
  EXPECT_EQ(std::strtod(json_number(x).c_str(), nullptr), x);
  JsonObject o;
  o.set("nan", std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(o.to_string(false), "{\"nan\":null}");
}

TEST(IoOutputJson, PrettyLayout) {
  JsonObject inner;
  inner.set("a", 1);
  JsonObject row;
  row.set("x", 2.5);
  JsonObject o;
  o.set("inner", inner)
      .set("v", std::vector<double>{1, 2})
      .set("rows", std::vector<JsonObject>{row});
  EXPECT_EQ(o.to_string(true),
            "{\n  \"inner\": {\n    \"a\": 1\n  },\n  \"v\": [1, 2],\n  \"rows\": [\n    {\n"
            "      \"x\": 2.5\n    }\n  ]\n}");
}

TEST(IoOutputJson, CopyIsDeep) {
  JsonObject a;
  a.set("k", 1);
  JsonObject b = a;
  b.set("k", 2);
  EXPECT_EQ(a.to_string(false), "{\"k\":1}");
  EXPECT_EQ(b.to_string(false), "{\"k\":2}");
}

}  // namespace
}  // namespace slamsph
