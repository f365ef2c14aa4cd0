#include "tendril/dashboard/json_writer.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace tendril::dashboard {
namespace {

TEST(JsonWriter, PlacesCommasAndEscapesStrings) {
  JsonWriter json;
  const float numbers[3] = {1.5f, -0.25f, std::numeric_limits<float>::quiet_NaN()};
  json.begin_object()
      .key("name")
      .value("a \"quoted\"\\ line\n\x01")
      .key("list")
      .begin_array()
      .value(int64_t{3})
      .value(true)
      .null()
      .end_array()
      .key("numbers")
      .numbers(numbers, 3)
      .key("empty")
      .numbers(std::vector<double>{})
      .key("inf")
      .value(std::numeric_limits<double>::infinity())
      .key("nested")
      .begin_object()
      .key("x")
      .value(0.1)
      .end_object()
      .end_object();
  EXPECT_EQ(
      json.str(),
      R"({"name":"a \"quoted\"\\ line\n\u0001","list":[3,true,null],)"
      R"("numbers":[1.5,-0.25,null],"empty":[],"inf":null,"nested":{"x":0.10000000000000001}})");
}

}  // namespace
}  // namespace tendril::dashboard
