#pragma once
// One declaration per parameter. A plugin keeps its parameters in one struct whose member
// initialisers are the defaults (KISS-ICP's config struct), and declares a ParamTable that binds
// each INI key — name, unit, range, one-line doc — to the member it fills, one line a key (Stone
// Soup's declared Property). From that table come the ParamSpecs (INI validation, `pedtrack
// plugins NAME`, docs/plugins.md) with the member's initialiser as the default, and the reading
// of a validated section into the struct. A name, a default or a range is written once.
//
//   struct GateParams { double max_range = 8.0; bool keep_ground = false; };
//   const ParamTable<GateParams>& table() {
//     static const auto t = ParamTable<GateParams>()
//         .real(&GateParams::max_range, "max_range", "m", 0, 1000, "farthest range kept")
//         .boolean(&GateParams::keep_ground, "keep_ground", "keep the ground's points");
//     return t;
//   }
//   descriptor.params = table().specs();   ...   GateParams p = table().read(ctx.params);
//
// A member of a nested struct is bound through path(&Outer::inner, &Inner::member); a nested
// struct with a table of its own is included whole with include(&Outer::inner, innerTable()).
#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "pedtrack/errors.h"
#include "pedtrack/params.h"

namespace pedtrack {

/// Radians per degree: the scale of an angle an INI gives in degrees and a struct keeps in rad.
constexpr double kDegree = 3.14159265358979323846 / 180.0;

/// A member of a member: path(&A::b, &B::c)(a) is a.b.c, for binding nested structs' members.
template <class... Members>
auto path(Members... members) {
  return [=](auto& object) -> auto& {
    return (object.*....*members);
  };
}

/// Several members read as one list of numbers: fields(&P::var_x, &P::var_y) binds the key
/// "accel_var = 4 4" to var_x and var_y (each part a member pointer or a path()).
template <class... Parts>
struct Fields {
  std::tuple<Parts...> parts;
};
template <class... Parts>
Fields<Parts...> fields(Parts... parts) {
  return {{parts...}};
}

namespace param_detail {
template <class A>
struct IsFields : std::false_type {};
template <class... Parts>
struct IsFields<Fields<Parts...>> : std::true_type {};

/// `v` to 15 significant digits: a default shown in an INI unit after converting it (deg).
std::string roundedNumber(double v);
std::string joinNumbers(const std::vector<double>& v, bool exact);

template <class M, class = void>
struct Resizable : std::false_type {};
template <class M>
struct Resizable<M, std::void_t<decltype(std::declval<M&>().resize(1))>> : std::true_type {};
template <class M, class = void>
struct IsMatrix : std::false_type {};  // an Eigen matrix or vector: rows(), cols(), m(i, j)
template <class M>
struct IsMatrix<M, std::void_t<decltype(std::declval<const M&>()(0, 0) +
                                        double(std::declval<const M&>().cols()))>>
    : std::true_type {};

/// The member's numbers: a std::vector, a std::array, or an Eigen matrix row by row.
template <class M>
std::vector<double> numbers(const M& m) {
  if constexpr (IsMatrix<M>::value) {
    std::vector<double> v;
    for (long i = 0; i < long(m.rows()); ++i)
      for (long j = 0; j < long(m.cols()); ++j) v.push_back(m(i, j));
    return v;
  } else {
    return std::vector<double>(m.begin(), m.end());
  }
}
/// Fills the member from `v` (its length checked already): a matrix keeps its default's shape
/// when the count fits it, else becomes a column; a vector takes the count.
template <class M>
void assignNumbers(M& m, const std::vector<double>& v) {
  if constexpr (IsMatrix<M>::value) {
    if (std::size_t(m.rows() * m.cols()) != v.size()) m.resize(long(v.size()), 1);
    std::size_t k = 0;
    for (long i = 0; i < long(m.rows()); ++i)
      for (long j = 0; j < long(m.cols()); ++j) m(i, j) = v[k++];
  } else {
    if constexpr (Resizable<M>::value) m.resize(v.size());  // else fixed: the length is checked
    for (std::size_t i = 0; i < v.size(); ++i) m[i] = v[i];
  }
}
}  // namespace param_detail

template <class T>
class ParamTable {
 public:
  /// The type of the member `Access` reaches in a T (the value a choice word stands for).
  template <class Access>
  using MemberType = std::decay_t<std::invoke_result_t<Access, T&>>;

  /// A number in [min, max] (unit as the INI gives it). `scale` converts the INI's unit to the
  /// member's: an angle given in degrees and kept in radians has scale pi/180.
  template <class Access>
  ParamTable& real(Access member, std::string name, std::string unit, double min, double max,
                   std::string doc, double scale = 1) {
    Binding b;
    b.name = name;
    b.offset = offsetOf(member);
    b.size = sizeOf(member);
    b.spec = [=, name = std::move(name), unit = std::move(unit), doc = std::move(doc)](const T& d) {
      const double v = double(get(member, d)) / scale;
      ParamSpec s = ParamSpec::real(name, std::nullopt, unit, min, max, doc);
      s.default_value = scale == 1 ? shortestNumber(v) : param_detail::roundedNumber(v);
      return s;
    };
    b.read = [=](T& t, const ParamSet& p, const std::string& key) {
      using M = std::decay_t<decltype(get(member, t))>;
      get(member, t) = M(p.getDouble(key) * scale);
    };
    return add(std::move(b));
  }

  /// A whole number in [min, max].
  template <class Access>
  ParamTable& integer(Access member, std::string name, std::string unit, double min, double max,
                      std::string doc) {
    Binding b;
    b.name = name;
    b.offset = offsetOf(member);
    b.size = sizeOf(member);
    b.spec = [=, name = std::move(name), unit = std::move(unit), doc = std::move(doc)](const T& d) {
      return ParamSpec::integer(name, long(get(member, d)), unit, min, max, doc);
    };
    b.read = [=](T& t, const ParamSet& p, const std::string& key) {
      using M = std::decay_t<decltype(get(member, t))>;
      get(member, t) = M(p.getInt(key));
    };
    return add(std::move(b));
  }

  template <class Access>
  ParamTable& boolean(Access member, std::string name, std::string doc) {
    Binding b;
    b.name = name;
    b.offset = offsetOf(member);
    b.size = sizeOf(member);
    b.spec = [=, name = std::move(name), doc = std::move(doc)](const T& d) {
      return ParamSpec::boolean(name, bool(get(member, d)), doc);
    };
    b.read = [=](T& t, const ParamSet& p, const std::string& key) {
      get(member, t) = p.getBool(key);
    };
    return add(std::move(b));
  }

  /// Free text (a path that may be empty, a name, a list the plugin parses); into a
  /// std::vector<std::string> member, a list of words (white space or commas between them).
  template <class Access>
  ParamTable& text(Access member, std::string name, std::string doc) {
    using M = MemberType<Access>;
    Binding b;
    b.name = name;
    b.offset = offsetOf(member);
    b.size = sizeOf(member);
    b.spec = [=, name = std::move(name), doc = std::move(doc)](const T& d) {
      if constexpr (std::is_same_v<M, std::vector<std::string>>) {
        std::string words;
        for (const std::string& w : get(member, d)) words += (words.empty() ? "" : " ") + w;
        return ParamSpec::text(name, words, doc);
      } else {
        return ParamSpec::text(name, std::string(get(member, d)), doc);
      }
    };
    b.read = [=](T& t, const ParamSet& p, const std::string& key) {
      if constexpr (std::is_same_v<M, std::vector<std::string>>)
        get(member, t) = p.getList(key);
      else
        get(member, t) = p.getString(key);
    };
    return add(std::move(b));
  }

  /// A file that must exist before the first frame; required (relative to the pipeline file).
  template <class Access>
  ParamTable& inputFile(Access member, std::string name, std::string doc, bool folder_ok = false) {
    Binding b;
    b.name = name;
    b.offset = offsetOf(member);
    b.size = sizeOf(member);
    b.spec = [name = std::move(name), doc = std::move(doc), folder_ok](const T&) {
      return ParamSpec::inputFile(name, doc, folder_ok);
    };
    b.read = [=](T& t, const ParamSet& p, const std::string& key) {
      get(member, t) = p.getString(key);
    };
    return add(std::move(b));
  }

  /// One of a few words, each standing for one value of the member (an enum, a function, a
  /// string); the default is the word of the member's initial value.
  template <class Access>
  ParamTable& choice(Access member, std::string name,
                     std::vector<std::pair<std::string, MemberType<Access>>> words,
                     std::string doc) {
    using V = MemberType<Access>;
    Binding b;
    b.name = name;
    b.offset = offsetOf(member);
    b.size = sizeOf(member);
    b.spec = [=, name = std::move(name), doc = std::move(doc)](const T& d) {
      std::vector<std::string> choices;
      std::string def;
      for (const auto& [word, value] : words) {
        choices.push_back(word);
        if (def.empty() && V(get(member, d)) == value) def = word;
      }
      if (def.empty())
        throw std::logic_error("parameter '" + name + "': the default is none of its words");
      return ParamSpec::choice(name, def, choices, doc);
    };
    b.read = [=](T& t, const ParamSet& p, const std::string& key) {
      const std::string& word = p.getString(key);
      for (const auto& [w, value] : words)
        if (w == word) get(member, t) = value;
    };
    return add(std::move(b));
  }

  /// A list of `length` numbers (0: any count, at least one) each in [min, max]; the member is a
  /// std::vector<double>, a std::array or an Eigen vector. `scale` as for real().
  template <class Access>
  ParamTable& vector(Access member, std::string name, std::string unit, std::size_t length,
                     double min, double max, std::string doc, double scale = 1) {
    // A member of a fixed count (several fields, a std::array, a fixed Eigen vector) must be
    // declared with that count: the reader writes `length` numbers into it.
    static const T probe{};
    const std::size_t count = numbersOf(member, probe).size();
    if (!resizable<Access>() && length != count)
      throw std::logic_error("parameter '" + name + "' has " + std::to_string(count) +
                             " numbers, declared " + std::to_string(length));
    Binding b;
    b.name = name;
    b.offset = offsetOf(member);
    b.size = sizeOf(member);
    b.spec = [=, name = std::move(name), unit = std::move(unit), doc = std::move(doc)](const T& d) {
      std::vector<double> v = numbersOf(member, d);
      for (double& x : v) x /= scale;
      ParamSpec s = ParamSpec::vector(name, std::nullopt, unit, length, min, max, doc);
      s.default_value = param_detail::joinNumbers(v, scale == 1);
      return s;
    };
    b.read = [=](T& t, const ParamSet& p, const std::string& key) {
      std::vector<double> v = p.getNumbers(key);
      for (double& x : v) x *= scale;
      assignNumbersOf(member, t, v);
    };
    return add(std::move(b));
  }

  /// A rule one key cannot state alone (a minimum below its maximum): after reading, `problem`
  /// returns what is wrong (empty when nothing is), and the error names the key of `member`.
  template <class Access>
  ParamTable& check(Access member, std::function<std::string(const T&)> problem) {
    const std::ptrdiff_t off = offsetOf(member);
    const std::size_t size = sizeOf(member);
    for (const auto& b : bindings_)
      if (b.offset == off && b.size == size) {
        checks_.push_back({b.name, std::move(problem)});
        return *this;
      }
    throw std::logic_error("ParamTable::check: the member has no key");
  }

  /// Every key (and rule) of `other`, a table of the same struct, after the keys declared so far.
  ParamTable& append(const ParamTable& other) {
    return include(
        [](auto& t) -> auto& { return t; }, other);
  }

  /// This table without the key `name` (a plugin that takes a shared group but one key).
  ParamTable without(const std::string& name) const {
    ParamTable t = *this;
    t.bindings_.erase(std::remove_if(t.bindings_.begin(), t.bindings_.end(),
                                     [&](const Binding& b) { return b.name == name; }),
                      t.bindings_.end());
    t.checks_.erase(std::remove_if(t.checks_.begin(), t.checks_.end(),
                                   [&](const Check& c) { return c.key == name; }),
                    t.checks_.end());
    return t;
  }

  /// The last key declared has no default: a pipeline must give it.
  ParamTable& required() {
    auto spec = bindings_.back().spec;
    bindings_.back().spec = [spec](const T& d) {
      ParamSpec s = spec(d);
      s.default_value.reset();
      return s;
    };
    return *this;
  }

  /// Every key of `sub`, filling the struct `member` (after the keys declared so far).
  template <class Access, class U>
  ParamTable& include(Access member, const ParamTable<U>& sub) {
    for (const auto& sb : sub.bindings_) {
      Binding b;
      b.name = sb.name;
      b.offset = offsetOf(member) + sb.offset;
      b.size = sb.size;
      b.spec = [=](const T& d) { return sb.spec(get(member, d)); };
      b.read = [=](T& t, const ParamSet& p, const std::string& key) {
        sb.read(get(member, t), p, key);
      };
      add(std::move(b));
    }
    for (const auto& sc : sub.checks_)
      checks_.push_back({sc.key, [=](const T& t) { return sc.problem(get(member, t)); }});
    return *this;
  }

  /// The declarations, defaults taken from a default-constructed T.
  std::vector<ParamSpec> specs() const {
    const T defaults{};
    std::vector<ParamSpec> out;
    for (const auto& b : bindings_) out.push_back(b.spec(defaults));
    return out;
  }

  /// A T from a validated section: each key the pipeline gave is read into its member; the
  /// others keep T's initialisers (exactly: never rounded through text).
  /// Then every rule is checked: ConfigError "file: [section] key: problem" for the first broken.
  T read(const ParamSet& p) const {
    T t{};
    readInto(p, t);
    return t;
  }
  void readInto(const ParamSet& p, T& t) const {
    for (const auto& b : bindings_)
      if (p.given(b.name)) b.read(t, p, b.name);
    for (const auto& c : checks_) {
      const std::string problem = c.problem(t);
      if (!problem.empty()) throw ConfigError(p.where(c.key) + ": " + problem);
    }
  }

  /// "file: [section] key" of the key that fills `member`, to start an error message with.
  template <class Access>
  std::string where(const ParamSet& p, Access member) const {
    const std::ptrdiff_t off = offsetOf(member);
    const std::size_t size = sizeOf(member);
    for (const auto& b : bindings_)
      if (b.offset == off && b.size == size) return p.where(b.name);
    throw std::logic_error("ParamTable::where: the member has no key");
  }

 private:
  template <class U>
  friend class ParamTable;

  struct Binding {
    std::string name;
    // Where the member lies in T and its size: identify it for where() and check() (a nested
    // struct and its first member share the offset, not the size).
    std::ptrdiff_t offset = 0;
    std::size_t size = 0;
    std::function<ParamSpec(const T&)> spec;
    std::function<void(T&, const ParamSet&, const std::string&)> read;
  };

  template <class Access, class Object>
  static decltype(auto) get(const Access& member, Object& object) {
    return std::invoke(member, object);
  }
  // Whether the member takes any count of numbers (a std::vector, a dynamic Eigen matrix).
  template <class Access>
  static constexpr bool resizable() {
    if constexpr (param_detail::IsFields<Access>::value) {
      return false;
    } else {
      using M = MemberType<Access>;
      if constexpr (param_detail::IsMatrix<M>::value)
        return M::SizeAtCompileTime < 0;  // Eigen::Dynamic
      else
        return param_detail::Resizable<M>::value;
    }
  }
  template <class Access>
  static std::vector<double> numbersOf(const Access& member, const T& t) {
    if constexpr (param_detail::IsFields<Access>::value)
      return std::apply([&](const auto&... a) { return std::vector<double>{double(get(a, t))...}; },
                        member.parts);
    else
      return param_detail::numbers(get(member, t));
  }
  template <class Access>
  static void assignNumbersOf(const Access& member, T& t, const std::vector<double>& v) {
    if constexpr (param_detail::IsFields<Access>::value) {
      std::size_t i = 0;
      std::apply([&](const auto&... a) { ((get(a, t) = v[i++]), ...); }, member.parts);
    } else {
      param_detail::assignNumbers(get(member, t), v);
    }
  }
  template <class Access>
  static std::size_t sizeOf(const Access& member) {
    if constexpr (param_detail::IsFields<Access>::value)
      return sizeOf(std::get<0>(member.parts));
    else
      return sizeof(MemberType<Access>);
  }
  template <class... Parts>
  static std::ptrdiff_t offsetOf(const Fields<Parts...>& f) {
    return offsetOf(std::get<0>(f.parts));
  }
  template <class Access>
  static std::ptrdiff_t offsetOf(const Access& member) {
    static const T probe{};
    return reinterpret_cast<const char*>(&get(member, probe)) -
           reinterpret_cast<const char*>(&probe);
  }

  ParamTable& add(Binding b) {
    for (const Binding& other : bindings_)
      if (other.name == b.name)
        throw std::logic_error("parameter '" + b.name + "' declared twice in one table");
    bindings_.push_back(std::move(b));
    return *this;
  }

  struct Check {
    std::string key;
    std::function<std::string(const T&)> problem;
  };

  std::vector<Binding> bindings_;
  std::vector<Check> checks_;
};

}  // namespace pedtrack
