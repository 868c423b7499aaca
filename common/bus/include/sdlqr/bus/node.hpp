#pragma once
// The LCM side of every process: one bus connection, vehicle-prefixed channels, decoding with
// reject counting, sequence-gap (drop) counting, queue capacity 1 for state and command
// channels, HEARTBEAT once a second of wall time, and a stop flag set by SIGINT/SIGTERM.
// Before decoding, every message's bytes are checked to hold exactly one complete encoding
// (logger's generated, allocation-free walk), so a forged array length cannot allocate.
// Optional seeded fault injection (drop, delay) on received messages, for tests: see
// FaultInjection, enabled by the SDLQR_FAULTS environment variable or setFaultInjection().
// Algorithm code never sees this header; mains hand plain structs (common/messages.hpp) on.
// Bus layout (bus_layout.hpp): under the split layout a channel travels on the port the layout
// gives it, so the Node opens one connection per URL it subscribes or publishes on, and polls
// the ones it subscribes on together; a URL it only publishes on never opens a receive socket.
// It publishes with LCM; on udpm:// it reads its sockets itself, in the calling thread
// (src/udpm_inbox.hpp says why), every datagram ready at once; a subscription of queue
// capacity N gets the first N of its channel's messages waiting, later ones are dropped (as LCM).
// Signed bus (signature.hpp): with a key (SDLQR_BUS_KEY, or setBusKey()) the node signs every
// message it publishes and admits on its typed subscriptions only messages signed with that key,
// newer than the last from their link and inside the replay window; the others are rejected
// (kUnsigned, kBadMac, kReplayed, kSignatureWindow, counted per stream like any rejection) on
// arrival, before the size walk, the decode, any fault injection or handler. Raw (recorder)
// subscriptions get the bytes as sent, trailer included: a log holds what was on the wire.

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/bus/bus_key.hpp"
#include "sdlqr/bus/bus_layout.hpp"
#include "sdlqr/bus/decode.hpp"
#include "sdlqr/bus/signature.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/health/process_health.hpp"
#include "sdlqr/messages/channels.hpp"

namespace sdlqr::bus {

class UdpmInbox;
struct WireMessage;

// Health lives in common/health (bus-free, shared with the replay and the in-process loop).
using ProcessState = ::sdlqr::ProcessState;
using Counters = ::sdlqr::Counters;

// Seeded loss and latency on every typed subscription of a process (the kernel here has no
// netem). Spec text: "drop=0.1,delay_ms=0:5,seed=7" (any subset, comma-separated). Each received
// message is dropped with probability `drop`, else delivered after a delay drawn uniformly from
// [delay_min_ms, delay_max_ms]; a channel's messages keep their order (the delay is a queue's).
// Raw (recorder) subscriptions are never faulted: the log shows what was sent.
struct FaultInjection {
  double drop = 0.0;           // [-] probability in [0, 1)
  double delay_min_ms = 0.0;   // [ms]
  double delay_max_ms = 0.0;   // [ms]
  uint64_t seed = 1;
  bool enabled() const { return drop > 0.0 || delay_max_ms > 0.0; }
  // Throws std::invalid_argument naming the field on a bad spec.
  static FaultInjection parse(const std::string& spec);
};

class Node {
 public:
  Node(std::string process, const ProcessOptions& options);
  // The heartbeat reports `health`: a process core's (what its handlers count), or the node's own.
  Node(std::string process, const ProcessOptions& options, ProcessHealth& health);
  ~Node();
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  std::string channel(std::string_view base) const { return channel::name(vehicle_, base); }
  // The connection of the --lcm-url itself (the base port): under the split layout it carries
  // only the low-rate channels; publishEncoded() routes any channel to its own URL.
  lcm::LCM& lcm() { return *endpoints_.front()->lcm; }
  BusLayout busLayout() const { return layout_; }
  // Every URL this node receives on (one per port it subscribes on), in the order opened.
  std::vector<std::string> receiveUrls() const;

  // Decodes each message of `base` as T and calls handler(msg). A message that fails the size
  // walk or the decode is rejected (kBadSize, kDecode, counted for the channel's stream in the
  // health) and never reaches the handler. Gaps in `seq` count as dropped, and per channel in
  // the HEARTBEAT counters "lost.<base>" (every message this subscriber never handled: lost in
  // the kernel, by LCM's queue or ours) and "queue_drop.<base>" (of those, dropped by our queue). queue_capacity 1: while a message waits to be handled, newer ones are dropped
  // (LCM's semantics), so a control loop never works through a backlog. A handler
  // that runs longer than a non-zero `budget` (wall time) counts as a deadline miss in HEARTBEAT.
  template <class T>
  void subscribe(std::string_view base, std::function<void(const T&)> handler, int queue_capacity = 1,
                 std::chrono::microseconds budget = std::chrono::microseconds::zero());

  // Undecoded messages of every channel whose full name matches the LCM regex `pattern` (no
  // vehicle prefix is added): for recorders. Counted as received; `receive_utime` is LCM's
  // wall-clock receive time [us]. Listens on every URL of the layout, so it hears every channel.
  using RawHandler =
      std::function<void(const std::string& channel, const void* data, uint32_t size, int64_t receive_utime)>;
  void subscribeRaw(const std::string& pattern, RawHandler handler, int queue_capacity);

  // Encodes and publishes on the vehicle-prefixed channel.
  template <class T>
  void publish(std::string_view base, const T& msg);
  // Already encoded bytes on a full channel name (no prefix added), on that channel's URL: for
  // tools that forward or forge messages. Counted as published; a failure counts an error.
  // On a signed bus the bytes are signed with this node's key, as publish() does.
  void publishEncoded(const std::string& channel, const void* data, int size);
  // The same bytes on the channel's URL, never signed: for a bridge between ports, whose messages
  // keep their publisher's signature (or its absence: a bridge with the key must not sign for
  // whoever it hears). Counted as published.
  void forwardEncoded(const std::string& channel, const void* data, int size);

  // From now on the node never publishes: no HEARTBEAT, and a publish is refused (counted as an
  // error). For a listener that must not add traffic to the bus it watches (sdlqr-view).
  void listenOnly() { listen_only_ = true; }
  bool isListenOnly() const { return listen_only_; }

  // Replaces the fault injection read from SDLQR_FAULTS at construction (tests over memq://).
  void setFaultInjection(const FaultInjection& faults);
  const FaultInjection& faultInjection() const { return faults_; }
  // Signs and checks from now on with `key` (replaces SDLQR_BUS_KEY's; tests over memq://).
  void setBusKey(const BusKey& key);
  bool signing() const { return signer_ != nullptr; }

  // Another input of the process (a MAVLink link's socket) handled in the same thread and loop as
  // the bus: spin() and waitReadable() also wait on `fd`, and spin() calls on_readable() when it is
  // readable (or in error: the callback reads and sees). At most a few beside the bus's sockets.
  void watchDescriptor(int fd, std::function<void()> on_readable);

  // Handles messages for up to timeout_ms and publishes HEARTBEAT when one is due.
  // Returns false once SIGINT or SIGTERM has been received.
  bool spin(int timeout_ms);
  // Waits up to `timeout` (finer than spin's milliseconds) until a message is ready on any
  // subscribed URL, handling nothing; true when one is. Without subscriptions it just sleeps.
  bool waitReadable(std::chrono::steady_clock::duration timeout);
  // Handles messages for up to timeout_ms even after a stop signal, publishing nothing: for a
  // recorder taking in the last messages (its own STOPPING heartbeat) before it closes.
  void drain(int timeout_ms);
  bool running() const;
  // For a main that ends itself (e.g. a duration elapsed): publishes a last STOPPING heartbeat.
  void shutdown();

  // Heartbeat contents: the health's.
  ProcessHealth& health() { return *health_; }
  void setState(ProcessState state) { health_->setState(state); }
  ProcessState state() const { return health_->state(); }
  void setSimTime(int64_t utime) { health_->setSimTime(utime); }
  void setLastError(const std::string& text) { health_->setLastError(text); }
  Counters& counters() { return health_->counters(); }
  void countError() { health_->countError(); }
  void countDeadlineMiss() { health_->countDeadlineMiss(); }
  // Messages lost by the process itself (e.g. a recorder's queue overflow), for HEARTBEAT dropped.
  void countDropped(int64_t count) { health_->countDropped(count); }
  int64_t received() const { return received_; }
  int64_t rejected() const { return health_->rejected(); }
  int64_t dropped() const { return health_->dropped(); }
  int64_t deadlineMisses() const { return health_->deadlineMisses(); }
  const std::string& process() const { return process_; }

  void publishHeartbeat();

 private:
  struct SubscriptionBase {
    virtual ~SubscriptionBase() = default;
    virtual void onMessage(const void* data, uint32_t size) = 0;
    // The bytes are one whole encoding of the channel's type (tells kUnsigned from kBadMac).
    virtual bool fitsUnsigned(const void* data, uint32_t size) const = 0;
    Node* node = nullptr;
    std::string channel;  // full name: signed with the payload
    ReplayWindow replay;  // signed bus: the newest timestamp of each link on this channel
    Stream stream = Stream::kOther;
    int64_t last_seq = -1;
    Counters::Id lost = -1;        // "lost.<base>": forward seq gaps
    Counters::Id queue_drop = -1;  // "queue_drop.<base>": over queue capacity on arrival
    std::chrono::steady_clock::duration budget{};  // zero: not timed
    std::chrono::steady_clock::time_point last_due{};  // keeps a channel's delayed messages in order
  };
  template <class T>
  struct TypedSubscription : SubscriptionBase {
    std::function<void(const T&)> handler;
    T message;  // decoded in place: fixed-size types never allocate
    void onMessage(const void* data, uint32_t size) override {
      ++node->received_;
      if (node->health_->reject(stream, decode(data, size, message))) return;
      node->noteSequence(*this, message.seq);
      if (budget == std::chrono::steady_clock::duration::zero()) {
        handler(message);
        return;
      }
      const auto start = std::chrono::steady_clock::now();
      handler(message);
      if (std::chrono::steady_clock::now() - start > budget) node->countDeadlineMiss();
    }
    bool fitsUnsigned(const void* data, uint32_t size) const override {
      return encodingFits<T>(static_cast<const uint8_t*>(data), size);
    }
  };
  struct RawSubscription {
    Node* node = nullptr;
    RawHandler handler;
    std::string pattern;  // LCM regex, anchored
  };
  // C callback: LCM's C++ wrapper would build a std::string of the channel for every message.
  static void dispatch(const lcm_recv_buf_t* rbuf, const char* channel, void* sub);
  static void dispatchRaw(const lcm::ReceiveBuffer* rbuf, const std::string& channel, RawSubscription* sub);
  void noteSequence(SubscriptionBase& sub, int64_t seq);
  void injectFault(SubscriptionBase& sub, const void* data, uint32_t size);
  void deliverDueMessages();
  int millisecondsToNextDue(int timeout_ms) const;
  void addSubscription(std::string_view base, std::unique_ptr<SubscriptionBase> sub, int queue_capacity);
  // Who gets the messages of a udpm endpoint: a typed subscription (exact channel) or a raw one.
  struct Route {
    std::string channel;  // typed: the full name
    SubscriptionBase* typed = nullptr;
    RawSubscription* raw = nullptr;
    int capacity = 0;  // newest messages of a batch delivered; 0: all
  };
  // The routes a channel name goes to, found once per name.
  struct ChannelRoutes {
    std::string channel;
    std::vector<int> routes;
  };
  // One connection per URL, receiving once something subscribed on it.
  struct Endpoint {
    Endpoint();
    ~Endpoint();
    std::string url;
    std::unique_ptr<lcm::LCM> lcm;       // publishing; receiving too on other providers than udpm
    std::unique_ptr<UdpmInbox> inbox;    // udpm receiving
    std::vector<Route> routes;
    std::vector<ChannelRoutes> routes_by_channel;
    std::vector<ChannelRoutes> uncached;  // per message of a batch, once routes_by_channel is full
    std::vector<int> delivered;          // per route, scratch of one batch
    std::vector<WireMessage> batch;
    bool receiving = false;
  };
  Endpoint& endpoint(const std::string& url);
  Endpoint& endpointFor(std::string_view channel) { return endpoint(channelUrl(layout_, base_url_, channel)); }
  void markReceiving(Endpoint& e);
  void publishRaw(lcm::LCM& lcm, const std::string& channel, const void* data, int size);
  lcm::LCM& encodedChannelLcm(const std::string& channel);
  // Publishes `size` bytes of `buffer`, signed first on a signed bus: the buffer has room for the
  // trailer (kSignatureSize more bytes).
  void publishFrame(lcm::LCM& lcm, const std::string& channel, uint8_t* buffer, int size);
  // On a signed bus, the signature check of a typed subscription's message on arrival: false when
  // refused (counted), else *size becomes the payload's. Always true on an unsigned bus.
  bool signatureAdmits(SubscriptionBase& sub, const void* data, uint32_t* size);
  // Full channel name of a base name and its connection, found once: publishing then never allocates.
  struct PublishChannel {
    std::string base;
    std::string full;
    lcm::LCM* lcm = nullptr;
  };
  const PublishChannel& publishChannel(std::string_view base);
  // Polls every receiving connection for up to timeout_ms and handles what is ready on each
  // ready one; returns the number of connections handled, or -1 on an error.
  int handleReady(int timeout_ms);
  bool drainInbox(Endpoint& e);
  const ChannelRoutes* routesOf(Endpoint& e, std::string_view channel, size_t batch_index);
  void addRoute(Endpoint& e, Route route);
  void deliverTyped(SubscriptionBase& sub, const void* data, uint32_t size);

  std::string process_;
  std::string vehicle_;
  BusLayout layout_ = BusLayout::kSplit;
  std::string base_url_;
  std::vector<std::unique_ptr<Endpoint>> endpoints_;  // [0]: the base URL
  std::vector<std::unique_ptr<SubscriptionBase>> subscriptions_;
  std::vector<std::unique_ptr<RawSubscription>> raw_subscriptions_;
  std::vector<uint8_t> encode_buffer_;  // kSignatureSize spare bytes past any encoding
  std::unique_ptr<BusSigner> signer_;   // null: an unsigned bus
  uint32_t link_id_ = 0;
  uint64_t last_signature_time_ = 0;
  std::vector<uint8_t> sign_buffer_;    // publishEncoded's copy, with room for the trailer
  std::vector<PublishChannel> publish_channels_;
  std::vector<std::pair<std::string, lcm::LCM*>> encoded_channels_;  // publishEncoded's, found once
  std::vector<Endpoint*> receiving_;  // the endpoints handleReady polls
  struct Watched {
    int fd;
    std::function<void()> on_readable;
  };
  std::vector<Watched> watched_;  // watchDescriptor's, polled after the endpoints
  ProcessHealth own_health_;
  ProcessHealth* health_ = &own_health_;
  struct DelayedMessage {
    SubscriptionBase* sub = nullptr;
    std::chrono::steady_clock::time_point due;
    std::vector<uint8_t> bytes;
  };
  FaultInjection faults_;
  std::mt19937_64 fault_rng_;
  std::vector<DelayedMessage> delayed_;
  std::vector<std::vector<uint8_t>> spare_buffers_;
  Counters::Id fault_dropped_ = -1;
  Counters::Id fault_delayed_ = -1;
  Counters::Id bus_datagrams_ = -1;
  Counters::Id bus_malformed_ = -1;
  Counters::Id bus_over_capacity_ = -1;
  Counters::Id bus_unrouted_ = -1;
  Counters::Id bus_kernel_dropped_ = -1;
  int64_t received_ = 0;
  int64_t published_ = 0;
  bool listen_only_ = false;
  int64_t heartbeat_seq_ = 0;
  std::chrono::steady_clock::time_point next_heartbeat_;
  std::chrono::steady_clock::time_point cpu_window_start_;
  double cpu_seconds_at_window_start_ = 0.0;
};

template <class T>
void Node::subscribe(std::string_view base, std::function<void(const T&)> handler, int queue_capacity,
                     std::chrono::microseconds budget) {
  auto sub = std::make_unique<TypedSubscription<T>>();
  sub->handler = std::move(handler);
  sub->budget = budget;
  sub->stream = streamOfChannel(base);
  addSubscription(base, std::move(sub), queue_capacity);
}

template <class T>
void Node::publish(std::string_view base, const T& msg) {
  const int size = msg.getEncodedSize();
  const size_t room = static_cast<size_t>(size) + kSignatureSize;
  if (encode_buffer_.size() < room) encode_buffer_.resize(room);
  if (msg.encode(encode_buffer_.data(), 0, size) < 0) {
    countError();
    setLastError("encode failed on " + std::string(base));
    return;
  }
  const PublishChannel& target = publishChannel(base);
  publishFrame(*target.lcm, target.full, encode_buffer_.data(), size);
}

// The stop flag every Node checks, set by SIGINT or SIGTERM once a Node exists or
// installStopSignalHandlers() ran: for a main that runs without a bus (sdlqr-view playing a log).
void installStopSignalHandlers();
bool stopRequested();

}  // namespace sdlqr::bus
