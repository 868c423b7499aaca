#pragma once
// The parameters a PARAMS update may change in flight: every key whose declaration says
// `.inFlight(ParamsUpdate::kX)` (param_table.hpp), with the update's field of the same name
// (params_t.lcm) carrying its value. From those declarations follow, for every user of PARAMS:
//   - the keys a scenario's `params:` event may set, and which go together (one group);
//   - the one check of an update's values: known groups, choices, finite, each value within the
//     range its declaration gives, and the section's rules that blame an in-flight key
//     (c_max > c_min); a rule blaming a fixed key (whether the rotors lift a mass) is the owner's;
//   - the application of an update to a section (applyInFlight).
// In flight today: lqr.q_diag, r_diag (FIELD_WEIGHTS), lqr.omega_max, c_min, c_max
// (FIELD_LIMITS), lqr.law (FIELD_LAW), vehicle.mass (FIELD_MASS), controller.tracking
// (FIELD_TRACKING, declared by declareTracking below: every process that checks PARAMS knows it).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr {

struct InFlightParam {
  std::string section;  // "lqr"
  ParamInfo info;       // info.in_flight: its PARAMS group
  // Reads the key from a mapping as its declaration reads it (ConfigError naming the key).
  ParamValues (*read)(const ConfigReader& reader, const std::string& key);
};

// Every in-flight parameter: lqr's, vehicle's, then controller's, each in declaration order.
const std::vector<InFlightParam>& inFlightParams();
// The OR of every in-flight group.
int32_t inFlightGroups();

enum class InFlightVerdict { kOk, kUnknownGroup, kBadChoice, kNonFinite, kOutOfRange };
struct InFlightCheck {
  InFlightVerdict verdict = InFlightVerdict::kOk;
  std::string key;     // "mass" (the update's field, the declaration's key); "field_mask"
  std::string reason;  // "must be in (0, 100) kg"
  bool ok() const { return verdict == InFlightVerdict::kOk; }
};
// The one check of an update's values against their declarations (groups in field_mask only).
InFlightCheck checkInFlight(const ParamsUpdate& update);

// The values of the update's field `key` (a declaration's key), and setting them.
ParamValues inFlightValues(const ParamsUpdate& update, std::string_view key);
void setInFlightValues(ParamsUpdate& update, std::string_view key, const ParamValues& values);

// Sets the members of `p` that `table` declares in flight and the update's field_mask names.
template <class T>
void applyInFlight(const ParamTable<T>& table, T& p, const ParamsUpdate& update) {
  table.forEachInFlight([&](const ParamInfo& info) {
    if (update.field_mask & info.in_flight) table.setValues(p, info.key, inFlightValues(update, info.key));
  });
}

// controller.tracking: the reference scheme of trajectories that do not say; PARAMS
// FIELD_TRACKING switches it in flight.
template <class T>
void declareTracking(ParamTable<T>& t, ReferenceMode T::*member) {
  t.choice("tracking", member, ReferenceMode::kSpatial,
           {{"spatial", ReferenceMode::kSpatial}, {"temporal", ReferenceMode::kTemporal}},
           "reference scheme of trajectories that do not say (spatial or temporal)")
      .inFlight(ParamsUpdate::kTracking);
}

}  // namespace sdlqr
