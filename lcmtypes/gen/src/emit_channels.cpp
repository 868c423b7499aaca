// channels.hpp and outbox.hpp: what follows from each .lcm file's @channel (one type per channel).

#include <algorithm>
#include <set>
#include <sstream>

#include "emit_text.hpp"
#include "sdlqr/lcmgen/emit.hpp"

namespace sdlqr::lcmgen {

namespace {

std::vector<const PlainStruct*> withChannel(const PlainModel& model) {
  std::vector<const PlainStruct*> out;
  std::set<std::string> names, ids;
  for (const PlainStruct& s : model.structs) {
    if (s.channel.name.empty()) continue;
    if (!names.insert(s.channel.name).second) {
      throw LcmSchemaError(s.lcm->file + ": @channel " + s.channel.name + " is another type's channel (one type per channel)");
    }
    if (!ids.insert(s.channel.id).second) {
      throw LcmSchemaError(s.lcm->file + ": @channel identifier " + s.channel.id + " is another channel's");
    }
    out.push_back(&s);
  }
  return out;
}

std::string lowerCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

void emitNames(std::ostringstream& out, const std::vector<const PlainStruct*>& typed) {
  out << "namespace channel {\n\n";
  for (const PlainStruct* s : typed) {
    out << "inline constexpr std::string_view k" << s->channel.id << " = " << text::quoted(s->channel.name) << ";  // "
        << s->lcm->name << "\n";
  }
  out << "\n}  // namespace channel\n\n";
}

void emitStreams(std::ostringstream& out, const std::vector<const PlainStruct*>& typed) {
  out << "// The input streams a process counts rejections for: one per channel, named like the channel in\n"
         "// lower case (\"state_est\"). kOther: a channel of no known type.\n";
  out << "enum class Stream : int8_t {\n";
  for (const PlainStruct* s : typed) out << "  k" << s->channel.id << ",\n";
  out << "  kOther,\n  kCount\n};\n";
  out << "inline constexpr int kStreamCount = static_cast<int>(Stream::kCount);\n\n";
}

void emitTable(std::ostringstream& out, const std::vector<const PlainStruct*>& typed) {
  out << "// Every channel: its stream (and the stream's name in counters), its LCM type, and its port\n"
         "// offset in the split bus layout (0: the base port).\n";
  out << "struct ChannelInfo {\n  std::string_view name;\n  Stream stream;\n  std::string_view stream_name;\n"
         "  std::string_view lcm_type;\n  int split_port;\n};\n";
  out << "inline constexpr ChannelInfo kChannels[] = {\n";
  for (const PlainStruct* s : typed) {
    out << "    {channel::k" << s->channel.id << ", Stream::k" << s->channel.id << ", "
        << text::quoted(lowerCase(s->channel.name)) << ", " << text::quoted(s->lcm->name) << ", " << s->channel.split_port
        << "},\n";
  }
  out << "};\n\n";
}

void emitTraits(std::ostringstream& out, const std::vector<const PlainStruct*>& typed) {
  out << "// The channel and stream of a plain message type (undefined for a type without a channel).\n";
  out << "template <class Msg>\nstruct MessageChannel;\n";
  for (const PlainStruct* s : typed) {
    out << "template <>\nstruct MessageChannel<" << s->name << "> {\n";
    out << "  static constexpr std::string_view kName = channel::k" << s->channel.id << ";\n";
    out << "  static constexpr Stream kStream = Stream::k" << s->channel.id << ";\n};\n";
  }
  out << "template <class Msg>\nconstexpr std::string_view channelOf() {\n  return MessageChannel<Msg>::kName;\n}\n";
  out << "template <class Msg>\nconstexpr Stream streamOf() {\n  return MessageChannel<Msg>::kStream;\n}\n\n";
  out << "// Every plain type with a channel, in the order of kChannels.\n";
  out << "template <class... Msg>\nstruct MessageTypes {};\n";
  out << "using ChannelTypes = MessageTypes<";
  for (size_t i = 0; i < typed.size(); ++i) out << (i ? ", " : "") << typed[i]->name;
  out << ">;\n\n";
}

}  // namespace

std::string emitChannelsHeader(const PlainModel& model, const std::string& source_note) {
  const std::vector<const PlainStruct*> typed = withChannel(model);
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// The channel of every message type, declared with the type in its .lcm file (@channel NAME,\n"
                             "// @split_port N): one type per channel; names without the vehicle prefix.\n\n");
  out << "#include <cstdint>\n#include <string_view>\n\n";
  out << "#include \"" << generatedInclude(model.package, "plain.hpp") << "\"\n\n";
  const std::string ns = text::packageNamespace(model.package);
  out << "namespace " << ns << " {\n\n";
  emitNames(out, typed);
  emitStreams(out, typed);
  emitTable(out, typed);
  emitTraits(out, typed);
  out << "}  // namespace " << ns << "\n";
  return out.str();
}

std::string emitOutboxHeader(const PlainModel& model, const std::string& source_note) {
  const std::vector<const PlainStruct*> typed = withChannel(model);
  std::ostringstream out;
  out << text::headerOpening(source_note,
                             "// Where a process core puts the messages it publishes: one overload per message type with a\n"
                             "// channel. The bus publishes each on the channel of its type; the in-process loop and the replay\n"
                             "// route it by the cores' declared ports (sdlqr/messages/ports.hpp). Cores never see which.\n\n");
  out << "#include <utility>\n\n";
  out << "#include \"" << generatedInclude(model.package, "plain.hpp") << "\"\n\n";
  const std::string ns = text::packageNamespace(model.package);
  out << "namespace " << ns << " {\n\n";
  out << "class Outbox {\n public:\n  virtual ~Outbox() = default;\n";
  for (const PlainStruct* s : typed) out << "  virtual void publish(const " << s->name << "& m) = 0;\n";
  out << "};\n\n";
  out << "// An Outbox that hands every message to one generic callable, sink(const T&).\n";
  out << "template <class Sink>\nclass OutboxTo : public Outbox {\n public:\n";
  out << "  explicit OutboxTo(Sink sink) : sink_(std::move(sink)) {}\n";
  for (const PlainStruct* s : typed) out << "  void publish(const " << s->name << "& m) override { sink_(m); }\n";
  out << "\n private:\n  Sink sink_;\n};\n\n";
  out << "}  // namespace " << ns << "\n";
  return out.str();
}

}  // namespace sdlqr::lcmgen
