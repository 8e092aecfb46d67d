// ParamTable: one declaration binds a key to a struct member. The defaults come from the
// struct's initialisers, exactly; given keys are read into their members (with unit scales),
// nested structs and lists of members bind too, rules name their key, and a missing required key
// or a bad value is the one-line ConfigError of validateSection.
#include <Eigen/Core>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "pedtrack/errors.h"
#include "pedtrack/param_table.h"

using namespace pedtrack;

namespace {

enum class Mode { Fast, Exact };

struct Inner {
  double gain = 0.45;
  std::array<double, 2> bounds{0.1, 0.5};
};

struct Params {
  double angle = 12 * kDegree;  // kept in rad, given in deg
  double ratio = M_PI / 12;     // not a short decimal: must not be rounded
  long count = 3;
  bool on = true;
  std::string name = "x";
  std::string file;
  Mode mode = Mode::Exact;
  Eigen::VectorXd noise = Eigen::Vector3d(1, 2, 3);
  double var_x = 4, var_y = 5;
  Inner inner;
};

const ParamTable<Inner>& innerTable() {
  static const auto t = ParamTable<Inner>()
                            .real(&Inner::gain, "gain", "", 0, 1, "a gain")
                            .vector(&Inner::bounds, "bounds", "m", 2, 0, 10, "min max");
  return t;
}

const ParamTable<Params>& table() {
  using P = Params;
  static const auto t =
      ParamTable<P>()
          .real(&P::angle, "angle", "deg", 0, 90, "an angle", kDegree)
          .real(&P::ratio, "ratio", "", 0, 1, "a ratio")
          .integer(&P::count, "count", "", 1, 10, "a count")
          .boolean(&P::on, "on", "a switch")
          .text(&P::name, "name", "a name")
          .inputFile(&P::file, "file", "a file")
          .choice(&P::mode, "mode", {{"fast", Mode::Fast}, {"exact", Mode::Exact}}, "a mode")
          .vector(&P::noise, "noise", "", 3, 0, 100, "three variances")
          .vector(fields(&P::var_x, &P::var_y), "var", "", 2, 0, 100, "two members as one key")
          .include(&P::inner, innerTable())
          .check(path(&P::inner, &Inner::bounds), [](const P& p) {
            return p.inner.bounds[0] <= p.inner.bounds[1] ? "" : "min above max";
          });
  return t;
}

ParamSet section(const std::vector<std::pair<std::string, std::string>>& given) {
  return validateSection(table().specs(), given, "f.ini", "s", "plugin 't'");
}

}  // namespace

TEST_CASE("a table's declarations take their defaults from the struct", "[params][table]") {
  const std::vector<ParamSpec> specs = table().specs();
  REQUIRE(specs.size() == 11);
  auto spec = [&](const std::string& name) {
    for (const auto& s : specs)
      if (s.name == name) return s;
    FAIL("no key " << name);
    return ParamSpec();
  };
  CHECK(*spec("angle").default_value == "12");  // shown in the INI's unit
  CHECK(spec("angle").unit == "deg");
  CHECK(std::stod(*spec("ratio").default_value) == M_PI / 12);  // every digit kept
  CHECK(*spec("count").default_value == "3");
  CHECK(*spec("on").default_value == "true");
  CHECK(*spec("mode").default_value == "exact");
  CHECK(spec("mode").choices == std::vector<std::string>{"fast", "exact"});
  CHECK(*spec("noise").default_value == "1 2 3");
  CHECK(*spec("var").default_value == "4 5");
  CHECK(*spec("gain").default_value == "0.45");
  CHECK(*spec("bounds").default_value == "0.1 0.5");
  CHECK(spec("file").required());
}

TEST_CASE("keys not given keep the struct's values exactly; given keys are read",
          "[params][table]") {
  const Params d = table().read(section({{"file", "/etc/hostname"}}));
  CHECK(d.angle == 12 * kDegree);
  CHECK(d.ratio == M_PI / 12);  // not the 6 digits a text default would have kept
  CHECK(d.mode == Mode::Exact);
  CHECK(d.file == "/etc/hostname");
  const Params p = table().read(section({{"file", "/etc/hostname"},
                                         {"angle", "30"},
                                         {"count", "7"},
                                         {"on", "false"},
                                         {"mode", "fast"},
                                         {"noise", "4 5 6"},
                                         {"var", "7, 8"},
                                         {"gain", "0.5"},
                                         {"bounds", "1 2"}}));
  CHECK(p.angle == 30 * kDegree);
  CHECK(p.count == 7);
  CHECK_FALSE(p.on);
  CHECK(p.mode == Mode::Fast);
  CHECK(p.noise == Eigen::Vector3d(4, 5, 6));
  CHECK(p.var_x == 7);
  CHECK(p.var_y == 8);
  CHECK(p.inner.gain == 0.5);
  CHECK(p.inner.bounds == std::array<double, 2>{1, 2});
}

TEST_CASE("a table's rules, required keys and bad values are one-line errors naming the key",
          "[params][table]") {
  CHECK_THROWS_WITH(table().read(section({{"file", "/etc/hostname"}, {"bounds", "3 2"}})),
                    "f.ini: [s] bounds: min above max");
  CHECK_THROWS_WITH(section({}), "f.ini: [s] file: missing required key (a file)");
  CHECK_THROWS_WITH(section({{"file", "/etc/hostname"}, {"angle", "91"}}),
                    "f.ini: [s] angle: 91 is out of range [0, 90] deg");
  CHECK(table().where(section({{"file", "/etc/hostname"}}), path(&Params::inner, &Inner::gain)) ==
        "f.ini: [s] gain");
  CHECK(table().where(section({{"file", "/etc/hostname"}}), fields(&Params::var_x)) ==
        "f.ini: [s] var");
}

TEST_CASE("a table without one key, and one appended to another", "[params][table]") {
  const ParamTable<Params> t = table().without("ratio");
  CHECK(t.specs().size() == 10);
  const auto both = ParamTable<Inner>()
                        .append(innerTable())
                        .append(ParamTable<Inner>().real(&Inner::gain, "other", "", 0, 1,
                                                         "the same member twice"));
  CHECK(both.specs().size() == 3);
}
