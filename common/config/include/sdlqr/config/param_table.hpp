#pragma once
// One declaration per parameter: key, unit, default, accepted range and help, bound to the member
// of its struct. A struct's default constructor, its load() (unknown keys refused, wrong types and
// ranges reported as one "section.key: reason" ConfigError), its invalidReason() and the commented
// YAML of config/quad255.yaml all come from its table. The rows are data: each section's
// declaration file <component>/params/<name>.yaml, from which sdlqr_paramgen (common/config/gen)
// generates <name>_rows.hpp at build time; a new parameter is one entry there
// (docs/architecture.md, "Adding a parameter"), and the .cpp keeps what is logic:
//
//   #include "gains_params_rows.hpp"  // generated from gains/params/gains_params.yaml
//
//   const ParamTable<GainsParams>& GainsParams::declaration() {
//     static const ParamTable<GainsParams> table = gainsParamsRows();
//     return table;
//   }
//
// Rules that tie keys together (c_max > c_min) are explicit check()s on the table, each naming the
// key it blames. Ranges are checked first, in declaration order, then the checks in theirs.
// A key that a PARAMS update may change in flight says so in its row (`in_flight: kLimits`, its
// group), which becomes `.inFlight(ParamsUpdate::kLimits)`; sdlqr/math/in_flight.hpp derives the rest.

#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sdlqr/config/config.hpp"
#include "sdlqr/config/range.hpp"
#include "sdlqr/config/yaml_writer.hpp"

namespace sdlqr {

enum class ParamKind { kNumber, kInteger, kFlag, kChoice, kList };

// What a declaration says about one key: for the printer, for documentation and for the tests that
// derive their cases from the declarations.
struct ParamInfo {
  std::string key;                   // relative to its section; nested keys dotted: "vio.latency_max_s"
  ParamKind kind = ParamKind::kNumber;
  int size = 1;                      // elements of a list
  Range range;                       // of a number, an integer, or each element of a list
  std::vector<std::string> choices;  // the words a choice accepts
  std::string unit;                  // "-" when dimensionless
  std::string help;
  std::string default_text;          // the default as the vehicle file spells it
  bool derived = false;              // when absent, follows from other keys (printed commented out)
  int32_t in_flight = 0;             // the PARAMS group that changes it in flight; 0: fixed for a flight
  std::vector<double> choice_values; // a choice: the enum value of each word (as a number)
};

// A parameter's value as numbers: a number one, a list its elements, a choice its enum's value.
inline constexpr int kMaxParamValues = 16;
struct ParamValues {
  std::array<double, kMaxParamValues> v{};
  int size = 0;
};

// The struct-independent face of a declaration: what the vehicle-file registry, the printer and
// the tests see of a section.
class ParamSection {
 public:
  explicit ParamSection(std::string help) : help_(std::move(help)) {}
  virtual ~ParamSection() = default;

  const std::string& help() const { return help_; }
  // Every key, nested sections flattened, in declaration order.
  virtual std::vector<ParamInfo> params() const = 0;
  // Dotted paths of the nested sections ("imu", "battery"), in declaration order.
  virtual std::vector<std::string> subsections() const = 0;
  // Loads the section as its struct's load() does and drops the result: throws the same ConfigError.
  virtual void checkLoads(const ConfigReader& reader) const = 0;

 private:
  std::string help_;
};

namespace detail {
template <class V>
struct Same {
  using type = V;
};
std::string paramComment(const std::string& unit, const std::string& help);
std::string choiceList(const std::vector<std::string>& words);  // "tangent or iterative"
template <int N>
std::string listText(const Eigen::Matrix<double, N, 1>& v) {
  std::string text = "[";
  for (int i = 0; i < N; ++i) text += (i ? ", " : "") + yamlNumber(v[i]);
  return text + "]";
}
template <int N>
std::string elementReason(const std::string& key, const Eigen::Matrix<double, N, 1>& v, const Range& range,
                          const std::string& unit) {
  for (int i = 0; i < N; ++i) {
    if (!range.contains(v[i])) return key + "[" + std::to_string(i) + "]: " + range.rule(unit);
  }
  return {};
}
}  // namespace detail

template <class T>
class ParamTable final : public ParamSection {
 public:
  using ParamSection::ParamSection;
  template <int N>
  using List = Eigen::Matrix<double, N, 1>;

  ParamTable& number(const char* key, double T::*member, double value, const char* unit, Range range,
                     const char* help) {
    Field& f = add(key, ParamKind::kNumber, unit, range, help);
    f.set_default = [member, value](T& p) { p.*member = value; };
    f.read = [member, key = f.info.key](const ConfigReader& r, T& p) { r.read(key, p.*member); };
    f.reason = [member, key = f.info.key, range, unit = f.info.unit](const T& p) {
      return range.contains(p.*member) ? std::string() : key + ": " + range.rule(unit);
    };
    f.text = [member](const T& p) { return yamlNumber(p.*member); };
    f.get = [member](const T& p) { return ParamValues{{p.*member}, 1}; };
    f.set = [member](T& p, const ParamValues& v) { p.*member = v.v[0]; };
    return *this;
  }

  template <class Int>
  ParamTable& integer(const char* key, Int T::*member, typename detail::Same<Int>::type value, const char* unit,
                      Range range, const char* help) {
    static_assert(std::is_integral_v<Int>, "integer() binds an integral member");
    Field& f = add(key, ParamKind::kInteger, unit, range, help);
    f.set_default = [member, value](T& p) { p.*member = value; };
    f.read = [member, key = f.info.key](const ConfigReader& r, T& p) {
      if constexpr (std::is_same_v<Int, int>) {
        r.read(key, p.*member);
      } else {
        long long wide = static_cast<long long>(p.*member);
        r.read(key, wide);
        p.*member = static_cast<Int>(wide);
      }
    };
    f.reason = [member, key = f.info.key, range, unit = f.info.unit](const T& p) {
      return range.contains(static_cast<double>(p.*member)) ? std::string() : key + ": " + range.rule(unit);
    };
    f.text = [member](const T& p) { return std::to_string(p.*member); };
    return *this;
  }

  ParamTable& flag(const char* key, bool T::*member, bool value, const char* help) {
    Field& f = add(key, ParamKind::kFlag, "-", Range::finite(), help);
    f.set_default = [member, value](T& p) { p.*member = value; };
    f.read = [member, key = f.info.key](const ConfigReader& r, T& p) { r.read(key, p.*member); };
    f.text = [member](const T& p) { return std::string(p.*member ? "true" : "false"); };
    return *this;
  }

  // A word naming one value of an enum: `names` lists every accepted word with its value.
  template <class E>
  ParamTable& choice(const char* key, E T::*member, typename detail::Same<E>::type value,
                     std::vector<std::pair<std::string, E>> names, const char* help) {
    Field& f = add(key, ParamKind::kChoice, "-", Range::finite(), help);
    for (const auto& entry : names) {
      f.info.choices.push_back(entry.first);
      f.info.choice_values.push_back(static_cast<double>(static_cast<int64_t>(entry.second)));
    }
    f.set_default = [member, value](T& p) { p.*member = value; };
    f.read = [member, names, key = f.info.key, words = f.info.choices](const ConfigReader& r, T& p) {
      if (!r.has(key)) return;
      std::string word;
      r.read(key, word);
      for (const auto& entry : names) {
        if (entry.first == word) {
          p.*member = entry.second;
          return;
        }
      }
      throw ConfigError(r.keyPath(key), "expected " + detail::choiceList(words));
    };
    f.reason = [member, names, key = f.info.key, words = f.info.choices](const T& p) {
      for (const auto& entry : names) {
        if (entry.second == p.*member) return std::string();
      }
      return key + ": expected " + detail::choiceList(words);
    };
    f.text = [member, names](const T& p) {
      for (const auto& entry : names) {
        if (entry.second == p.*member) return entry.first;
      }
      return std::string("?");
    };
    f.get = [member](const T& p) { return ParamValues{{static_cast<double>(static_cast<int64_t>(p.*member))}, 1}; };
    f.set = [member](T& p, const ParamValues& v) { p.*member = static_cast<E>(static_cast<int64_t>(v.v[0])); };
    return *this;
  }

  // A fixed-length list of numbers, each within `range`; errors name the element ("r_diag[2]").
  template <int N>
  ParamTable& list(const char* key, List<N> T::*member, const std::array<double, N>& value, const char* unit,
                   Range range, const char* help) {
    Field& f = add(key, ParamKind::kList, unit, range, help);
    f.info.size = N;
    f.set_default = [member, value](T& p) { p.*member = Eigen::Map<const List<N>>(value.data()); };
    f.read = [member, key = f.info.key](const ConfigReader& r, T& p) { r.read(key, p.*member); };
    f.reason = [member, key = f.info.key, range, unit = f.info.unit](const T& p) {
      return detail::elementReason<N>(key, p.*member, range, unit);
    };
    f.text = [member](const T& p) { return detail::listText<N>(p.*member); };
    static_assert(N <= kMaxParamValues, "a list longer than ParamValues holds");
    f.get = [member](const T& p) {
      ParamValues out;
      out.size = N;
      for (int i = 0; i < N; ++i) out.v[static_cast<size_t>(i)] = (p.*member)[i];
      return out;
    };
    f.set = [member](T& p, const ParamValues& v) {
      for (int i = 0; i < N && i < v.size; ++i) (p.*member)[i] = v.v[static_cast<size_t>(i)];
    };
    return *this;
  }

  // A list whose default follows from other keys (declared before it): `derive` sets it from
  // them; `get`/`set` convert between the member and its list. Absent from a file, it follows;
  // while it equals what it would follow to, it is printed commented out with `placeholder`
  // ("[x0, y0, ...]") for its value.
  template <int N>
  ParamTable& derivedList(const char* key, const char* unit, Range range, const char* help, const char* placeholder,
                          void (*derive)(T&), List<N> (*get)(const T&), void (*set)(T&, const List<N>&)) {
    Field& f = add(key, ParamKind::kList, unit, range, help);
    f.info.size = N;
    f.info.derived = true;
    f.placeholder = placeholder;
    f.set_default = derive;
    f.read = [derive, set, key = f.info.key](const ConfigReader& r, T& p) {
      if (!r.has(key)) {
        derive(p);
        return;
      }
      List<N> values = List<N>::Zero();
      r.read(key, values);
      set(p, values);
    };
    f.reason = [get, key = f.info.key, range, unit = f.info.unit](const T& p) {
      return detail::elementReason<N>(key, get(p), range, unit);
    };
    f.text = [get](const T& p) { return detail::listText<N>(get(p)); };
    f.follows = [derive, get](const T& p) {
      T followed = p;
      derive(followed);
      return get(followed) == get(p);
    };
    return *this;
  }

  // A nested mapping with a declaration of its own (S::declaration()).
  template <class S>
  ParamTable& section(const char* key, S T::*member) {
    const ParamTable<S>* nested = &S::declaration();
    // Its keys are the nested table's: params() lists those, never this field's own info.
    Field& f = add(key, ParamKind::kNumber, "", Range::finite(), nested->help().c_str());
    f.nested = nested;
    f.set_default = [member, nested](T& p) { nested->setDefaults(p.*member); };
    f.read = [member, nested, key = f.info.key](const ConfigReader& r, T& p) { nested->read(r.child(key), p.*member); };
    f.reason = [member, nested, key = f.info.key](const T& p) {
      const std::string why = nested->invalidReason(p.*member);
      return why.empty() ? why : key + "." + why;
    };
    f.print_nested = [member, nested, key = f.info.key](const T& p, YamlWriter& out) {
      out.open(key, nested->help());
      nested->print(p.*member, out);
      out.close();
    };
    return *this;
  }

  // The key declared last may change in flight, through the PARAMS group `group` (a number, a
  // list or a choice: what a ParamsUpdate field can carry).
  ParamTable& inFlight(int32_t group) {
    Field& f = fields_.back();
    if (!f.get || !f.set) throw std::logic_error(f.info.key + ": only a number, a list or a choice may change in flight");
    f.info.in_flight = group;
    return *this;
  }
  // f(info) for every key declared in flight, in declaration order.
  template <class F>
  void forEachInFlight(F&& f) const {
    for (const Field& field : fields_) {
      if (field.info.in_flight != 0) f(field.info);
    }
  }
  const ParamInfo& info(const std::string& key) const {
    for (const Field& f : fields_) {
      if (f.info.key == key) return f.info;
    }
    throw std::logic_error("no key '" + key + "' in this table");
  }
  // The value of an in-flight key (a number, a list or a choice) as numbers, and setting it.
  ParamValues values(const T& p, const std::string& key) const { return field(key).get(p); }
  void setValues(T& p, const std::string& key, const ParamValues& v) const { field(key).set(p, v); }
  // Reads one key as load() would (no range check).
  void readKey(const ConfigReader& reader, const std::string& key, T& p) const { field(key).read(reader, p); }

  // A rule across keys: when `ok` is false, `key` is reported with `reason`.
  ParamTable& check(const char* key, std::function<bool(const T&)> ok, std::string reason) {
    checks_.push_back({key, std::move(ok), std::move(reason)});
    return *this;
  }

  void setDefaults(T& p) const {
    for (const Field& f : fields_) f.set_default(p);
  }
  // Reads the keys present (unknown keys refused), leaving the others as they are; no range checks.
  void read(const ConfigReader& reader, T& p) const {
    reader.allowOnly(keys_);
    for (const Field& f : fields_) f.read(reader, p);
  }
  // Empty when valid, else "key: reason" for the first violation (key relative to the section).
  std::string invalidReason(const T& p) const {
    for (const Field& f : fields_) {
      if (!f.reason) continue;
      std::string why = f.reason(p);
      if (!why.empty()) return why;
    }
    for (const Check& c : checks_) {
      if (!c.ok(p)) return c.key + ": " + c.reason;
    }
    return {};
  }
  // The rules that blame a key declared in flight (c_max > c_min), in declaration order: what a
  // PARAMS update is checked against. Such a rule reads only keys of its key's group, which the
  // update carries; a rule blaming a fixed key (max_rotor_thrust lifts the mass) is the owner's.
  std::string inFlightRulesReason(const T& p) const {
    for (const Check& c : checks_) {
      if (inFlightKey(c.key) && !c.ok(p)) return c.key + ": " + c.reason;
    }
    return {};
  }
  // Defaults, then the keys present in `reader`, then every check: throws ConfigError naming the key.
  T load(const ConfigReader& reader) const {
    T p;
    read(reader, p);
    throwIfInvalid(reader, invalidReason(p));
    return p;
  }
  void print(const T& p, YamlWriter& out) const {
    for (const Field& f : fields_) {
      if (f.print_nested) {
        f.print_nested(p, out);
      } else {
        const bool follows = f.follows && f.follows(p);
        out.value(f.info.key, follows ? f.placeholder : f.text(p), detail::paramComment(f.info.unit, f.info.help),
                  follows);
      }
    }
  }

  std::vector<ParamInfo> params() const override {
    const T defaults;
    std::vector<ParamInfo> out;
    for (const Field& f : fields_) {
      if (f.nested) {
        for (ParamInfo info : f.nested->params()) {
          info.key = f.info.key + "." + info.key;
          out.push_back(std::move(info));
        }
        continue;
      }
      ParamInfo info = f.info;
      info.default_text = f.text(defaults);
      out.push_back(std::move(info));
    }
    return out;
  }
  std::vector<std::string> subsections() const override {
    std::vector<std::string> out;
    for (const Field& f : fields_) {
      if (!f.nested) continue;
      out.push_back(f.info.key);
      for (const std::string& inner : f.nested->subsections()) out.push_back(f.info.key + "." + inner);
    }
    return out;
  }
  void checkLoads(const ConfigReader& reader) const override { load(reader); }

 private:
  struct Field {
    ParamInfo info;
    std::function<void(T&)> set_default;
    std::function<void(const ConfigReader&, T&)> read;
    std::function<std::string(const T&)> reason;  // empty function: nothing to check
    std::function<std::string(const T&)> text;
    std::function<bool(const T&)> follows;        // derived lists: equal to what they follow to
    std::function<ParamValues(const T&)> get;     // a number, a list or a choice: its value as numbers
    std::function<void(T&, const ParamValues&)> set;
    std::string placeholder;                      // derived lists: printed while they follow
    std::function<void(const T&, YamlWriter&)> print_nested;
    const ParamSection* nested = nullptr;
  };
  struct Check {
    std::string key;
    std::function<bool(const T&)> ok;
    std::string reason;
  };

  bool inFlightKey(const std::string& key) const {
    for (const Field& f : fields_) {
      if (f.info.key == key) return f.info.in_flight != 0;
    }
    return false;
  }

  const Field& field(const std::string& key) const {
    for (const Field& f : fields_) {
      if (f.info.key == key && f.get) return f;
    }
    throw std::logic_error("no number, list or choice '" + key + "' in this table");
  }

  Field& add(const char* key, ParamKind kind, const char* unit, Range range, const char* help) {
    Field f;
    f.info.key = key;
    f.info.kind = kind;
    f.info.unit = unit;
    f.info.range = range;
    f.info.help = help;
    fields_.push_back(std::move(f));
    keys_.push_back(key);
    return fields_.back();
  }

  std::vector<Field> fields_;
  std::vector<Check> checks_;
  std::vector<std::string> keys_;
};

// What every parameter section P declared by a table (static const ParamTable<P>& declaration())
// offers, written once: struct P : DeclaredParams<P> { ... }.
template <class P>
struct DeclaredParams {
  // Reads the given mapping (defaults for the keys absent); throws ConfigError naming the key on a
  // wrong type or value.
  static P load(const ConfigReader& reader) { return P::declaration().load(reader); }
  // Empty when valid, else "key: reason" for the first violation found (nested keys dotted).
  std::string invalidReason() const { return P::declaration().invalidReason(static_cast<const P&>(*this)); }
  bool valid() const { return invalidReason().empty(); }
};

}  // namespace sdlqr
