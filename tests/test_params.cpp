// Parameter declarations: validation of every type, range text, suggestions.
#include <catch2/catch.hpp>
#include <limits>

#include "pedtrack/errors.h"
#include "pedtrack/params.h"

using namespace pedtrack;

TEST_CASE("numbers are checked for type and range", "[params]") {
  const auto spec = ParamSpec::real("voxel", 0.1, "m", 0.01, 1.0, "voxel edge");
  CHECK(validateValue(spec, "0.25", "f: [s] voxel") == "0.25");
  CHECK_THROWS_WITH(validateValue(spec, "abc", "f: [s] voxel"),
                    "f: [s] voxel: 'abc' is not a number (m)");
  CHECK_THROWS_WITH(validateValue(spec, "0.2x", "f: [s] voxel"),
                    Catch::Contains("is not a number"));
  CHECK_THROWS_WITH(validateValue(spec, "2", "f: [s] voxel"),
                    "f: [s] voxel: 2 is out of range [0.01, 1] m");
  const auto k = ParamSpec::integer("k", 5, "", 1, 50, "neighbours");
  CHECK(validateValue(k, "7", "w") == "7");
  CHECK_THROWS_WITH(validateValue(k, "7.5", "w"), "w: '7.5' is not an integer");
  CHECK_THROWS_WITH(validateValue(k, "0", "w"), "w: 0 is out of range [1, 50]");
}

TEST_CASE("booleans, enums and files", "[params]") {
  const auto b = ParamSpec::boolean("skip_bad", false, "");
  CHECK(validateValue(b, "yes", "w") == "true");
  CHECK(validateValue(b, "Off", "w") == "false");
  CHECK_THROWS_AS(validateValue(b, "maybe", "w"), ConfigError);
  const auto e = ParamSpec::choice("rate", "max", {"max", "realtime"}, "");
  CHECK(e.rangeText() == "{max, realtime}");
  CHECK_THROWS_WITH(validateValue(e, "realtme", "w"),
                    "w: 'realtme' is not one of {max, realtime} (did you mean 'realtime'?)");
  const auto f = ParamSpec::inputFile("file", "");
  CHECK(f.required());
  CHECK_THROWS_WITH(validateValue(f, "/no/such/file.rawlog", "w"),
                    "w: file '/no/such/file.rawlog' does not exist");
  CHECK_THROWS_WITH(validateValue(f, "/tmp", "w"), Catch::Contains("is a directory"));
}

TEST_CASE("closest match suggests near misses only", "[params]") {
  const std::vector<std::string> keys = {"p_detect", "gate", "max_range", "file"};
  CHECK(closestMatch("p_detec", keys) == "p_detect");
  CHECK(closestMatch("max_rnage", keys) == "max_range");
  CHECK(closestMatch("fiel", keys) == "file");
  CHECK(closestMatch("completely_different", keys).empty());
}

TEST_CASE("ParamSet reads typed values and refuses undeclared keys", "[params]") {
  ParamSet p("a.ini", "src");
  p.set("x", "2.5");
  p.set("n", "3");
  p.set("on", "true");
  p.set("labels", "LIDAR, HOKUYO1  front");
  CHECK(p.getDouble("x") == 2.5);
  CHECK(p.getInt("n") == 3);
  CHECK(p.getBool("on"));
  CHECK(p.getList("labels") == std::vector<std::string>{"LIDAR", "HOKUYO1", "front"});
  CHECK(p.where("x") == "a.ini: [src] x");
  CHECK_THROWS_AS(p.getString("y"), std::logic_error);
}

TEST_CASE("vector parameters check count and element range", "[params]") {
  const auto spec = ParamSpec::vector("transition", std::vector<double>{0.9, 0.1, 0.2, 0.8}, "", 4,
                                      0, 1, "matrix");
  CHECK(spec.default_value == std::string("0.9 0.1 0.2 0.8"));
  CHECK(spec.rangeText() == "4 × [0, 1]");
  CHECK(validateValue(spec, "0.5, 0.5; 0.25 0.75", "w") == "0.5 0.5 0.25 0.75");
  CHECK_THROWS_WITH(validateValue(spec, "0.5 0.5 0.5", "f: [t] transition"),
                    "f: [t] transition: expected 4 numbers, got 3");
  CHECK_THROWS_WITH(validateValue(spec, "0.5 1.5 0 1", "w"),
                    "w: element 2 (1.5) is out of range 4 × [0, 1]");
  CHECK_THROWS_WITH(validateValue(spec, "0.5 x 0 1", "w"), "w: 'x' is not a number");
  CHECK_THROWS_WITH(validateValue(spec, "", "w"), "w: no numbers given");
  const auto any = ParamSpec::vector("rates", std::vector<double>{1.4, -1.4}, "rad/s", 0,
                                     -std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::infinity(), "turn rates");
  CHECK(any.rangeText() == "n numbers");
  CHECK(validateValue(any, "0.123456789012", "w") == "0.123456789012");
  ParamSet ps("f", "s");
  ps.set("rates", validateValue(any, "1 -2 3", "w"));
  CHECK(ps.getVector("rates") == std::vector<double>{1, -2, 3});
}
