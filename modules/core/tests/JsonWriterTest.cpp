#include <dynslam/core/JsonWriter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using dynslam::core::JsonWriter;

TEST(JsonWriter, NestedObjectsArraysAndEscapes) {
  std::ostringstream s;
  JsonWriter j(s);
  j.beginObject().member("name", "a \"b\"\n").member("n", 3).member("x", 0.1).member("ok", true);
  j.key("list").beginArray().value(1).value(std::nan("")).endArray();
  j.key("empty").beginObject().endObject();
  j.endObject();
  EXPECT_EQ(s.str(),
            "{\n  \"name\": \"a \\\"b\\\"\\n\",\n  \"n\": 3,\n  \"x\": 0.10000000000000001,\n"
            "  \"ok\": true,\n  \"list\": [\n    1,\n    null\n  ],\n  \"empty\": {}\n}\n");
}
