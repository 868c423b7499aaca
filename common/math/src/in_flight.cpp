#include "sdlqr/math/in_flight.hpp"

#include <cmath>
#include <type_traits>

#include "sdlqr/lcmtypes/generated/plain_fields.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/vehicle.hpp"

namespace sdlqr {

namespace {

// The controller's one in-flight key, as ControllerParams declares it (declareTracking).
struct TrackingSection {
  ReferenceMode tracking;
  TrackingSection() { declaration().setDefaults(*this); }
  static const ParamTable<TrackingSection>& declaration() {
    static const ParamTable<TrackingSection> table = [] {
      ParamTable<TrackingSection> t("the controller's keys PARAMS changes");
      declareTracking(t, &TrackingSection::tracking);
      return t;
    }();
    return table;
  }
};

template <class T>
ParamValues readValues(const ConfigReader& reader, const std::string& key) {
  T scratch;
  T::declaration().readKey(reader, key, scratch);
  return T::declaration().values(scratch, key);
}

// The section's rules that blame an in-flight key, on its defaults with the update applied (such a
// rule reads only its group's keys, all of which the update carries).
template <class T>
std::string rulesReason(const ParamsUpdate& update) {
  T candidate;
  applyInFlight(T::declaration(), candidate, update);
  return T::declaration().inFlightRulesReason(candidate);
}

struct Section {
  const char* name;
  const ParamSection* table;
  ParamValues (*read)(const ConfigReader&, const std::string&);
  std::string (*rules)(const ParamsUpdate&);
};

template <class T>
Section section(const char* name) {
  return {name, &T::declaration(), &readValues<T>, &rulesReason<T>};
}

const std::vector<Section>& sections() {
  static const std::vector<Section> all = {section<LqrParams>("lqr"), section<VehicleParams>("vehicle"),
                                           section<TrackingSection>("controller")};
  return all;
}

// A member of ParamsUpdate as numbers: a double one, an Eigen vector its elements, an enum its value.
template <class M>
bool toValues(const M& member, ParamValues& out) {
  if constexpr (std::is_enum_v<M>) {
    out.size = 1;
    out.v[0] = static_cast<double>(static_cast<int64_t>(member));
    return true;
  } else if constexpr (std::is_same_v<M, double>) {
    out.size = 1;
    out.v[0] = member;
    return true;
  } else if constexpr (std::is_base_of_v<Eigen::MatrixBase<M>, M>) {
    out.size = static_cast<int>(member.size());
    for (int i = 0; i < out.size; ++i) out.v[static_cast<size_t>(i)] = member.data()[i];
    return true;
  } else {
    return false;  // utime, seq, field_mask: no parameter's
  }
}

template <class M>
void fromValues(const ParamValues& values, M& member) {
  if constexpr (std::is_enum_v<M>) {
    member = static_cast<M>(static_cast<std::underlying_type_t<M>>(values.v[0]));
  } else if constexpr (std::is_same_v<M, double>) {
    member = values.v[0];
  } else if constexpr (std::is_base_of_v<Eigen::MatrixBase<M>, M>) {
    for (int i = 0; i < member.size() && i < values.size; ++i) member.data()[i] = values.v[static_cast<size_t>(i)];
  }
}

std::string elementKey(const InFlightParam& p, int i) {
  return p.info.kind == ParamKind::kList ? p.info.key + "[" + std::to_string(i) + "]" : p.info.key;
}

bool isChoice(const InFlightParam& p, double value) {
  for (double allowed : p.info.choice_values) {
    if (allowed == value) return true;
  }
  return false;
}

InFlightCheck failure(InFlightVerdict verdict, std::string key, std::string reason) {
  return {verdict, std::move(key), std::move(reason)};
}

}  // namespace

const std::vector<InFlightParam>& inFlightParams() {
  static const std::vector<InFlightParam> all = [] {
    std::vector<InFlightParam> out;
    for (const Section& s : sections()) {
      for (const ParamInfo& info : s.table->params()) {
        if (info.in_flight != 0) out.push_back({s.name, info, s.read});
      }
    }
    return out;
  }();
  return all;
}

namespace {
// Built before main, as the declarations are read: checking and applying a PARAMS update in flight
// then allocates nothing (the controller's and the gain solver's loops take them).
[[maybe_unused]] const bool kBuiltBeforeMain = !inFlightParams().empty();
}  // namespace

int32_t inFlightGroups() {
  int32_t groups = 0;
  for (const InFlightParam& p : inFlightParams()) groups |= p.info.in_flight;
  return groups;
}

ParamValues inFlightValues(const ParamsUpdate& update, std::string_view key) {
  ParamValues out;
  lcmtypes::visitFields([&](const lcmtypes::PlainField& field, const auto& member) {
    if (field.name == key) toValues(member, out);
  }, update);
  return out;
}

void setInFlightValues(ParamsUpdate& update, std::string_view key, const ParamValues& values) {
  lcmtypes::visitFields([&](const lcmtypes::PlainField& field, auto& member) {
    if (field.name == key) fromValues(values, member);
  }, update);
}

// Choices first (an unknown enum says more than its range), then finiteness, then ranges, then
// the rules across keys: the first violation found.
InFlightCheck checkInFlight(const ParamsUpdate& update) {
  if ((update.field_mask & ~inFlightGroups()) != 0) {
    return failure(InFlightVerdict::kUnknownGroup, "field_mask", "names a group no parameter is declared in flight with");
  }
  const std::vector<InFlightParam>& params = inFlightParams();
  auto given = [&](const InFlightParam& p) { return (update.field_mask & p.info.in_flight) != 0; };
  for (const InFlightParam& p : params) {
    if (given(p) && p.info.kind == ParamKind::kChoice && !isChoice(p, inFlightValues(update, p.info.key).v[0])) {
      return failure(InFlightVerdict::kBadChoice, p.info.key, "expected " + detail::choiceList(p.info.choices));
    }
  }
  for (const InFlightParam& p : params) {
    const ParamValues values = inFlightValues(update, p.info.key);
    for (int i = 0; given(p) && i < values.size; ++i) {
      if (!std::isfinite(values.v[static_cast<size_t>(i)])) return failure(InFlightVerdict::kNonFinite, elementKey(p, i), "must be finite");
    }
  }
  for (const InFlightParam& p : params) {
    const ParamValues values = inFlightValues(update, p.info.key);
    for (int i = 0; given(p) && p.info.kind != ParamKind::kChoice && i < values.size; ++i) {
      if (!p.info.range.contains(values.v[static_cast<size_t>(i)])) {
        return failure(InFlightVerdict::kOutOfRange, elementKey(p, i), p.info.range.rule(p.info.unit));
      }
    }
  }
  for (const Section& s : sections()) {
    const std::string why = s.rules(update);
    if (!why.empty()) {
      const size_t colon = why.find(": ");
      return failure(InFlightVerdict::kOutOfRange, why.substr(0, colon), colon == std::string::npos ? why : why.substr(colon + 2));
    }
  }
  return {};
}

}  // namespace sdlqr
