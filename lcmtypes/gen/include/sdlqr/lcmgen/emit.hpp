#pragma once
// The C++ headers generated from lcmtypes/*.lcm beside lcm-gen's classes. Each emitter returns
// the text of one header, written to <out>/<package>/lcmtypes/generated/<name>:
//   plain.hpp         enums and plain structs (no LCM)
//   plain_fields.hpp  PlainFields<T>: every member of a plain struct with its name and unit
//   descriptors.hpp   field descriptors and CSV columns of each LCM type (no LCM)
//   lcm_fields.hpp    LcmFields<T>: every field of an lcm-gen class; type name -> class
//   wire_fits.hpp     encodingFits: the bytes hold exactly one encoding (allocation-free walk)
//   convert.hpp       fromLcm / toLcm between lcm-gen classes and plain structs
//   channels.hpp      each type's channel (@channel): names, streams, split-layout ports, traits
//   outbox.hpp        Outbox: one publish overload per type with a channel (no LCM)
//   json_schemas.hpp  the JSON Schema of each type's JSON encoding (no LCM)

#include <string>
#include <vector>

#include "sdlqr/lcmgen/plain_model.hpp"
#include "sdlqr/lcmgen/schema.hpp"

namespace sdlqr::lcmgen {

struct GeneratedHeader {
  std::string name;  // e.g. "plain.hpp"
  std::string text;
};

// `source_note` names the inputs in each banner comment.
std::string emitPlainHeader(const PlainModel& model, const std::string& source_note);
std::string emitPlainFieldsHeader(const PlainModel& model, const std::string& source_note);
std::string emitConvertHeader(const PlainModel& model, const std::string& source_note);
std::string emitDescriptorsHeader(const std::vector<LcmStruct>& types, const std::string& source_note);
std::string emitLcmFieldsHeader(const std::vector<LcmStruct>& types, const std::string& source_note);
std::string emitWireFitsHeader(const std::vector<LcmStruct>& types, const std::string& source_note);
// LcmSchemaError when two types name one channel.
std::string emitChannelsHeader(const PlainModel& model, const std::string& source_note);
std::string emitOutboxHeader(const PlainModel& model, const std::string& source_note);

std::string emitJsonSchemasHeader(const std::vector<LcmStruct>& types, const std::string& source_note);

// The JSON Schema (draft-07) of one type's JSON encoding, and its name "<package>.<type>".
std::string jsonSchemaText(const LcmStruct& type);
std::string jsonSchemaName(const LcmStruct& type);

// All nine, in the order above.
std::vector<GeneratedHeader> emitAll(const std::vector<LcmStruct>& types, const std::string& source_note);

// "<package path>/lcmtypes/generated/<name>", the include path of a generated header.
std::string generatedInclude(const std::string& package, const std::string& name);

}  // namespace sdlqr::lcmgen
