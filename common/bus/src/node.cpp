#include "sdlqr/bus/node.hpp"

#include <poll.h>
#include <regex.h>
#include <sys/random.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <stdexcept>

#include "sdlqr/heartbeat_t.hpp"
#include "sdlqr/bus/realtime.hpp"
#include "sdlqr/bus/wall_clock.hpp"
#include "udpm_inbox.hpp"

namespace sdlqr::bus {

namespace {

std::atomic<bool> g_stop_requested{false};

void onStopSignal(int) { g_stop_requested.store(true); }

double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double parseNumber(const std::string& field, const std::string& text) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value)) {
    throw std::invalid_argument("SDLQR_FAULTS: " + field + ": expected a number, got '" + text + "'");
  }
  return value;
}

}  // namespace

FaultInjection FaultInjection::parse(const std::string& spec) {
  FaultInjection f;
  size_t start = 0;
  while (start < spec.size()) {
    size_t end = spec.find(',', start);
    if (end == std::string::npos) end = spec.size();
    const std::string item = spec.substr(start, end - start);
    start = end + 1;
    if (item.empty()) continue;
    const size_t eq = item.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("SDLQR_FAULTS: '" + item + "': expected key=value");
    const std::string key = item.substr(0, eq);
    const std::string value = item.substr(eq + 1);
    if (key == "drop") {
      f.drop = parseNumber(key, value);
      if (f.drop < 0.0 || f.drop >= 1.0) throw std::invalid_argument("SDLQR_FAULTS: drop: must be in [0, 1)");
    } else if (key == "delay_ms") {
      const size_t colon = value.find(':');
      f.delay_min_ms = parseNumber(key, value.substr(0, colon));
      f.delay_max_ms = colon == std::string::npos ? f.delay_min_ms : parseNumber(key, value.substr(colon + 1));
      if (f.delay_min_ms < 0.0 || f.delay_max_ms < f.delay_min_ms || f.delay_max_ms > 10000.0) {
        throw std::invalid_argument("SDLQR_FAULTS: delay_ms: expected MIN:MAX with 0 <= MIN <= MAX <= 10000");
      }
    } else if (key == "seed") {
      const double seed = parseNumber(key, value);
      if (seed < 0.0 || seed != std::floor(seed) || seed > 9e15) {
        throw std::invalid_argument("SDLQR_FAULTS: seed: expected a non-negative integer");
      }
      f.seed = static_cast<uint64_t>(seed);
    } else {
      throw std::invalid_argument("SDLQR_FAULTS: unknown key '" + key + "' (drop, delay_ms, seed)");
    }
  }
  return f;
}

Node::Node(std::string process, const ProcessOptions& options) : Node(std::move(process), options, own_health_) {}

Node::Node(std::string process, const ProcessOptions& options, ProcessHealth& health)
    : process_(std::move(process)), vehicle_(options.vehicle), health_(&health) {
  for (char c : vehicle_) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) {
      throw std::invalid_argument("--vehicle: use letters, digits, '_' or '-' only, got '" + vehicle_ + "'");
    }
  }
  base_url_ = resolveLcmUrl(options.lcm_url);
  // Without ports to separate channels every layout is the single one.
  layout_ = isUdpmUrl(base_url_) ? parseBusLayout(options.bus_layout) : BusLayout::kSingle;
  base_url_ = urlWithPortOffset(base_url_, 0);
  endpoint(base_url_);
  if (isUdpmUrl(base_url_)) {
    // Datagrams its sockets read, against `received` (messages handed to handlers).
    bus_datagrams_ = health_->counters().add("bus.datagrams");
    bus_malformed_ = health_->counters().add("bus.malformed");
    bus_over_capacity_ = health_->counters().add("bus.over_capacity");  // queue full: dropped on arrival
    bus_unrouted_ = health_->counters().add("bus.unrouted");      // no subscription of this process wants it
    bus_kernel_dropped_ = health_->counters().add("bus.kernel_dropped");  // socket buffer full: lost unread
  }
  if (const std::string refused = lockMemoryWhenAsked(); !refused.empty()) {
    std::fprintf(stderr, "%s: %s\n", process_.c_str(), refused.c_str());
  }
  if (const char* spec = std::getenv("SDLQR_FAULTS"); spec != nullptr && spec[0] != '\0') {
    setFaultInjection(FaultInjection::parse(spec));
  }
  if (const std::optional<BusKey> key = busKeyFromEnvironment()) setBusKey(*key);
  installStopSignalHandlers();
  encode_buffer_.resize(4096 + kSignatureSize);
  next_heartbeat_ = std::chrono::steady_clock::now();
  cpu_window_start_ = next_heartbeat_;
  cpu_seconds_at_window_start_ = processCpuSeconds();
}

Node::~Node() = default;
Node::Endpoint::Endpoint() = default;
Node::Endpoint::~Endpoint() = default;

namespace {

constexpr size_t kMaxEndpoints = 16;  // the split layout has 8 URLs
constexpr size_t kMaxWatched = 4;     // watchDescriptor's, beside them
using PollSet = std::array<pollfd, kMaxEndpoints + kMaxWatched>;

// The notify descriptor of each receiving connection (LCM makes it readable per message), then
// the watched descriptors of other inputs (Node::watchDescriptor).
template <class Endpoints, class Watched>
size_t fillPollSet(const Endpoints& receiving, const Watched& watched, PollSet& fds) {
  for (size_t i = 0; i < receiving.size(); ++i) {
    const auto& e = *receiving[i];
    fds[i] = {e.inbox ? e.inbox->fd() : e.lcm->getFileno(), POLLIN, 0};
  }
  for (size_t i = 0; i < watched.size(); ++i) fds[receiving.size() + i] = {watched[i].fd, POLLIN, 0};
  return receiving.size() + watched.size();
}

// LCM's channel regex semantics (POSIX extended, the whole name must match).
bool channelMatches(const std::string& pattern, const std::string& channel) {
  regex_t compiled;
  if (regcomp(&compiled, ("^(" + pattern + ")$").c_str(), REG_EXTENDED | REG_NOSUB) != 0) return false;
  const bool match = regexec(&compiled, channel.c_str(), 0, nullptr, 0) == 0;
  regfree(&compiled);
  return match;
}

void checkChannelPattern(const std::string& pattern) {
  regex_t compiled;
  if (regcomp(&compiled, ("^(" + pattern + ")$").c_str(), REG_EXTENDED | REG_NOSUB) != 0) {
    throw std::invalid_argument("channel pattern '" + pattern + "' is not a valid regex");
  }
  regfree(&compiled);
}

constexpr size_t kMaxCachedChannels = 256;  // distinct names remembered per connection

}  // namespace

Node::Endpoint& Node::endpoint(const std::string& url) {
  for (const auto& e : endpoints_) {
    if (e->url == url) return *e;
  }
  if (endpoints_.size() == kMaxEndpoints) throw std::runtime_error("more than 16 LCM URLs in one process");
  auto e = std::make_unique<Endpoint>();
  e->url = url;
  e->lcm = std::make_unique<lcm::LCM>(url);
  if (!e->lcm->good()) {
    throw std::runtime_error("cannot open LCM bus '" + url + "' (is multicast routed? see README, Troubleshooting)");
  }
  endpoints_.push_back(std::move(e));
  return *endpoints_.back();
}

void Node::markReceiving(Endpoint& e) {
  if (e.receiving) return;
  if (isUdpmUrl(e.url)) {
    e.inbox = std::make_unique<UdpmInbox>(e.url);
    e.batch.reserve(UdpmInbox::kMaxBatch);
    e.routes_by_channel.reserve(kMaxCachedChannels);
    e.uncached.resize(UdpmInbox::kMaxBatch);
  }
  e.receiving = true;
  receiving_.push_back(&e);
}

void Node::addRoute(Endpoint& e, Route route) {
  e.routes.push_back(std::move(route));
  e.delivered.assign(e.routes.size(), 0);
  e.routes_by_channel.clear();  // recomputed with the new route
}

const Node::ChannelRoutes* Node::routesOf(Endpoint& e, std::string_view channel, size_t batch_index) {
  for (const ChannelRoutes& known : e.routes_by_channel) {
    if (known.channel == channel) return &known;
  }
  // Remembered while there is room (reserved: pointers of the batch stay valid); past that, a
  // flood of names is matched message by message.
  const bool cached = e.routes_by_channel.size() < kMaxCachedChannels;
  ChannelRoutes& entry = cached ? e.routes_by_channel.emplace_back() : e.uncached[batch_index];
  entry.channel = std::string(channel);
  entry.routes.clear();
  for (size_t i = 0; i < e.routes.size(); ++i) {
    const Route& r = e.routes[i];
    if (r.typed != nullptr ? r.channel == channel : channelMatches(r.raw->pattern, entry.channel)) {
      entry.routes.push_back(static_cast<int>(i));
    }
  }
  return &entry;
}

bool Node::drainInbox(Endpoint& e) {
  if (!e.inbox->drain(&e.batch)) return false;
  // Queue capacity as LCM's: of the messages waiting (the batch) a route gets its first
  // `capacity`, later ones are dropped. A controller predicting forward from the estimate before
  // its tick needs the older one (the newer may lie past the tick).
  std::fill(e.delivered.begin(), e.delivered.end(), 0);
  for (const WireMessage& m : e.batch) {
    const ChannelRoutes& routes = *routesOf(e, m.channel, static_cast<size_t>(&m - e.batch.data()));
    if (routes.routes.empty()) health_->counters().increment(bus_unrouted_);
    for (int r : routes.routes) {
      const Route& route = e.routes[static_cast<size_t>(r)];
      if (route.capacity > 0 && e.delivered[static_cast<size_t>(r)] >= route.capacity) {
        health_->counters().increment(bus_over_capacity_);
        if (route.typed != nullptr) health_->counters().increment(route.typed->queue_drop);
        continue;
      }
      // A message refused for its signature takes no place in the queue: a flood of unsigned ones
      // cannot crowd out the signed message of the same batch.
      uint32_t size = m.size;
      if (route.typed != nullptr && !signatureAdmits(*route.typed, m.data, &size)) continue;
      ++e.delivered[static_cast<size_t>(r)];
      if (route.typed != nullptr) {
        deliverTyped(*route.typed, m.data, size);
      } else {
        ++received_;
        route.raw->handler(routes.channel, m.data, m.size, m.receive_utime);
      }
    }
  }
  return true;
}

std::vector<std::string> Node::receiveUrls() const {
  std::vector<std::string> urls;
  for (const Endpoint* e : receiving_) urls.push_back(e->url);
  return urls;
}

void Node::dispatch(const lcm_recv_buf_t* rbuf, const char*, void* sub) {
  auto* subscription = static_cast<SubscriptionBase*>(sub);
  uint32_t size = rbuf->data_size;
  if (!subscription->node->signatureAdmits(*subscription, rbuf->data, &size)) return;
  subscription->node->deliverTyped(*subscription, rbuf->data, size);
}

void Node::setBusKey(const BusKey& key) {
  signer_ = std::make_unique<BusSigner>(key);
  // A new link per node: a restarted process starts a fresh timestamp sequence.
  if (getrandom(&link_id_, sizeof link_id_, 0) != static_cast<ssize_t>(sizeof link_id_)) {
    throw std::runtime_error("cannot draw a signing link id (getrandom)");
  }
  if (sign_buffer_.size() < 4096) sign_buffer_.resize(4096);
}

namespace {

uint64_t signatureNow() {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  return signatureTime(std::chrono::duration_cast<std::chrono::microseconds>(since_epoch).count());
}

}  // namespace

bool Node::signatureAdmits(SubscriptionBase& sub, const void* data, uint32_t* size) {
  if (signer_ == nullptr) return true;
  const auto* bytes = static_cast<const uint8_t*>(data);
  const RejectReason reason =
      admitSigned(*signer_, sub.replay, sub.channel, bytes, *size, sub.fitsUnsigned(data, *size), signatureNow());
  if (reason != RejectReason::kNone) {
    ++received_;
    health_->reject(sub.stream, reason);
    return false;
  }
  *size -= kSignatureSize;  // the handlers get the payload
  return true;
}

void Node::deliverTyped(SubscriptionBase& sub, const void* data, uint32_t size) {
  if (faults_.enabled()) {
    injectFault(sub, data, size);
    return;
  }
  sub.onMessage(data, size);
}

void Node::setFaultInjection(const FaultInjection& faults) {
  faults_ = faults;
  // Each process draws its own sequence from the common seed.
  fault_rng_.seed(faults.seed ^ std::hash<std::string>{}(process_));
  if (faults.enabled() && fault_dropped_ < 0) {
    fault_dropped_ = health_->counters().add("fault.dropped");
    fault_delayed_ = health_->counters().add("fault.delayed");
  }
}

void Node::injectFault(SubscriptionBase& sub, const void* data, uint32_t size) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  if (faults_.drop > 0.0 && uniform(fault_rng_) < faults_.drop) {
    ++received_;
    health_->counters().increment(fault_dropped_);
    return;
  }
  const double delay_ms = faults_.delay_min_ms + (faults_.delay_max_ms - faults_.delay_min_ms) * uniform(fault_rng_);
  const auto now = std::chrono::steady_clock::now();
  auto due = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                       std::chrono::duration<double, std::milli>(delay_ms));
  due = std::max(due, sub.last_due);
  if (due <= now) {
    sub.onMessage(data, size);
    return;
  }
  sub.last_due = due;
  health_->counters().increment(fault_delayed_);
  DelayedMessage message;
  message.sub = &sub;
  message.due = due;
  if (!spare_buffers_.empty()) {
    message.bytes = std::move(spare_buffers_.back());
    spare_buffers_.pop_back();
  }
  const auto* bytes = static_cast<const uint8_t*>(data);
  message.bytes.assign(bytes, bytes + size);
  delayed_.push_back(std::move(message));
}

void Node::deliverDueMessages() {
  if (delayed_.empty()) return;
  const auto now = std::chrono::steady_clock::now();
  // Insertion order is due order within each channel; channels do not wait for each other.
  size_t kept = 0;
  for (size_t i = 0; i < delayed_.size(); ++i) {
    DelayedMessage& message = delayed_[i];
    if (message.due <= now) {
      message.sub->onMessage(message.bytes.data(), static_cast<uint32_t>(message.bytes.size()));
      spare_buffers_.push_back(std::move(message.bytes));
    } else {
      if (kept != i) delayed_[kept] = std::move(message);
      ++kept;
    }
  }
  delayed_.resize(kept);
}

int Node::millisecondsToNextDue(int timeout_ms) const {
  if (delayed_.empty()) return timeout_ms;
  auto earliest = delayed_.front().due;
  for (const DelayedMessage& message : delayed_) earliest = std::min(earliest, message.due);
  const double wait_ms = std::chrono::duration<double, std::milli>(earliest - std::chrono::steady_clock::now()).count();
  const int wait = std::max(0, static_cast<int>(std::ceil(wait_ms)));
  return timeout_ms < 0 ? wait : std::min(timeout_ms, wait);
}

const Node::PublishChannel& Node::publishChannel(std::string_view base) {
  for (const PublishChannel& known : publish_channels_) {
    if (known.base == base) return known;
  }
  PublishChannel entry;
  entry.base = std::string(base);
  entry.full = channel(base);
  entry.lcm = endpointFor(base).lcm.get();
  publish_channels_.push_back(std::move(entry));
  return publish_channels_.back();
}

lcm::LCM& Node::encodedChannelLcm(const std::string& channel) {
  for (const auto& [known, lcm] : encoded_channels_) {
    if (known == channel) return *lcm;
  }
  lcm::LCM& lcm = *endpointFor(channel).lcm;
  if (encoded_channels_.size() < 256) encoded_channels_.emplace_back(channel, &lcm);  // a flood of names is not kept
  return lcm;
}

void Node::publishEncoded(const std::string& channel, const void* data, int size) {
  lcm::LCM& lcm = encodedChannelLcm(channel);
  if (signer_ == nullptr || size < 0) {
    publishRaw(lcm, channel, data, size);
    return;
  }
  const size_t room = static_cast<size_t>(size) + kSignatureSize;
  if (sign_buffer_.size() < room) sign_buffer_.resize(room);
  std::memcpy(sign_buffer_.data(), data, static_cast<size_t>(size));
  publishFrame(lcm, channel, sign_buffer_.data(), size);
}

void Node::forwardEncoded(const std::string& channel, const void* data, int size) {
  publishRaw(encodedChannelLcm(channel), channel, data, size);
}

void Node::publishFrame(lcm::LCM& lcm, const std::string& channel, uint8_t* buffer, int size) {
  if (signer_ == nullptr) {
    publishRaw(lcm, channel, buffer, size);
    return;
  }
  // Strictly increasing per link, even for messages sent within one 10 us tick.
  last_signature_time_ = std::max(signatureNow(), last_signature_time_ + 1);
  signer_->sign(channel, buffer, static_cast<size_t>(size), SignatureTrailer{link_id_, last_signature_time_});
  publishRaw(lcm, channel, buffer, size + static_cast<int>(kSignatureSize));
}

void Node::dispatchRaw(const lcm::ReceiveBuffer* rbuf, const std::string& channel, RawSubscription* sub) {
  ++sub->node->received_;
  sub->handler(channel, rbuf->data, rbuf->data_size, rbuf->recv_utime);
}

void Node::subscribeRaw(const std::string& pattern, RawHandler handler, int queue_capacity) {
  auto sub = std::make_unique<RawSubscription>();
  sub->node = this;
  sub->handler = std::move(handler);
  sub->pattern = pattern;
  for (const std::string& url : layoutUrls(layout_, base_url_)) {
    Endpoint& e = endpoint(url);
    if (isUdpmUrl(url)) {
      checkChannelPattern(pattern);
      markReceiving(e);
      Route route;
      route.raw = sub.get();
      route.capacity = std::max(0, queue_capacity);
      addRoute(e, std::move(route));
      continue;
    }
    lcm::Subscription* handle = e.lcm->subscribeFunction(pattern, &Node::dispatchRaw, sub.get());
    if (handle == nullptr) throw std::runtime_error("cannot subscribe to '" + pattern + "' on " + url);
    if (queue_capacity > 0) handle->setQueueCapacity(queue_capacity);
    markReceiving(e);
  }
  raw_subscriptions_.push_back(std::move(sub));
}

void Node::addSubscription(std::string_view base, std::unique_ptr<SubscriptionBase> sub, int queue_capacity) {
  sub->node = this;
  sub->channel = this->channel(base);
  sub->lost = health_->counters().add("lost." + std::string(base));
  sub->queue_drop = health_->counters().add("queue_drop." + std::string(base));
  const std::string channel = this->channel(base);
  Endpoint& e = endpointFor(channel);
  if (isUdpmUrl(e.url)) {
    markReceiving(e);
    Route route;
    route.channel = channel;
    route.typed = sub.get();
    route.capacity = std::max(0, queue_capacity);
    addRoute(e, std::move(route));
    subscriptions_.push_back(std::move(sub));
    return;
  }
  // The channel is used as an exact name: escape regex characters LCM would interpret.
  std::string pattern;
  for (char c : channel) {
    if (std::string_view(".[]()*+?^$|\\{}").find(c) != std::string_view::npos) pattern.push_back('\\');
    pattern.push_back(c);
  }
  lcm_subscription_t* handle = lcm_subscribe(e.lcm->getUnderlyingLCM(), pattern.c_str(), &Node::dispatch, sub.get());
  if (!handle) throw std::runtime_error("cannot subscribe to " + channel);
  if (queue_capacity > 0) lcm_subscription_set_queue_capacity(handle, queue_capacity);
  markReceiving(e);
  subscriptions_.push_back(std::move(sub));
}

void Node::noteSequence(SubscriptionBase& sub, int64_t seq) {
  // A forward jump is a loss; a backward jump is a publisher restart and starts a new count.
  if (sub.last_seq >= 0 && seq > sub.last_seq + 1) {
    health_->countDropped(seq - sub.last_seq - 1);
    health_->counters().increment(sub.lost, seq - sub.last_seq - 1);
  }
  sub.last_seq = seq;
}

void Node::publishRaw(lcm::LCM& lcm, const std::string& channel, const void* data, int size) {
  if (listen_only_) {
    countError();
    setLastError("listen-only: refused to publish on " + channel);
    return;
  }
  if (lcm.publish(channel, data, static_cast<unsigned int>(size)) != 0) {
    countError();
    setLastError("publish failed on " + channel);
    return;
  }
  ++published_;
}

bool Node::running() const { return !stopRequested(); }

void installStopSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool stopRequested() { return g_stop_requested.load(); }

bool Node::spin(int timeout_ms) {
  if (!running()) return false;
  const int status = handleReady(millisecondsToNextDue(timeout_ms));
  if (status < 0 && running()) {
    countError();
    setLastError("LCM handle failed");
  }
  deliverDueMessages();
  if (!listen_only_ && std::chrono::steady_clock::now() >= next_heartbeat_) publishHeartbeat();
  return running();
}

int Node::handleReady(int timeout_ms) {
  PollSet fds{};
  const size_t count = fillPollSet(receiving_, watched_, fds);
  const int ready = poll(fds.data(), count, timeout_ms);
  if (ready <= 0) return ready < 0 && errno != EINTR ? -1 : 0;
  int handled = 0;
  for (size_t i = 0; i < count; ++i) {
    if ((fds[i].revents & (POLLIN | POLLERR | POLLHUP)) == 0) continue;
    if (i >= receiving_.size()) {
      watched_[i - receiving_.size()].on_readable();
      ++handled;
      continue;
    }
    if ((fds[i].revents & POLLIN) == 0) continue;
    Endpoint& e = *receiving_[i];
    if (e.inbox ? !drainInbox(e) : lcm_handle(e.lcm->getUnderlyingLCM()) != 0) return -1;
    ++handled;
  }
  return handled;
}

void Node::drain(int timeout_ms) {
  if (handleReady(millisecondsToNextDue(timeout_ms)) < 0) countError();
  deliverDueMessages();
}

bool Node::waitReadable(std::chrono::steady_clock::duration timeout) {
  PollSet fds{};
  const size_t count = fillPollSet(receiving_, watched_, fds);
  const auto ns = std::max<int64_t>(0, std::chrono::duration_cast<std::chrono::nanoseconds>(timeout).count());
  const timespec wait{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
  return ppoll(fds.data(), count, &wait, nullptr) > 0;
}

void Node::watchDescriptor(int fd, std::function<void()> on_readable) {
  if (watched_.size() == kMaxWatched) {
    throw std::invalid_argument("more than 4 descriptors to watch beside the bus");
  }
  watched_.push_back({fd, std::move(on_readable)});
}

void Node::shutdown() {
  health_->setState(ProcessState::kStopping);
  publishHeartbeat();
}

void Node::publishHeartbeat() {
  if (listen_only_) return;
  const auto now = std::chrono::steady_clock::now();
  next_heartbeat_ = now + std::chrono::seconds(1);
  const double window = std::chrono::duration<double>(now - cpu_window_start_).count();
  const double cpu_now = processCpuSeconds();
  const double cpu_percent = window > 0.05 ? 100.0 * (cpu_now - cpu_seconds_at_window_start_) / window : 0.0;
  if (window > 0.05) {
    cpu_window_start_ = now;
    cpu_seconds_at_window_start_ = cpu_now;
  }

  if (bus_datagrams_ >= 0) {
    int64_t datagrams = 0, malformed = 0, kernel_dropped = 0;
    for (const Endpoint* e : receiving_) {
      if (!e->inbox) continue;
      datagrams += e->inbox->datagrams();
      malformed += e->inbox->malformed();
      kernel_dropped += e->inbox->kernelDropped();
    }
    health_->counters().set(bus_datagrams_, datagrams);
    health_->counters().set(bus_malformed_, malformed);
    health_->counters().set(bus_kernel_dropped_, kernel_dropped);
  }

  heartbeat_t hb;
  const ProcessHealth& health = *health_;
  hb.utime = health.simTime();
  hb.seq = heartbeat_seq_++;
  hb.process = process_;
  hb.pid = static_cast<int32_t>(getpid());
  hb.state = static_cast<int8_t>(running() ? health.state() : ProcessState::kStopping);
  hb.received = received_;
  hb.published = published_;
  hb.dropped = health.dropped();
  hb.rejected = health.rejected();
  hb.deadline_misses = health.deadlineMisses();
  hb.errors = health.errors();
  hb.cpu_percent = cpu_percent;
  health.exportCounters(hb.counter_names, hb.counter_values);
  hb.num_counters = static_cast<int32_t>(hb.counter_names.size());
  hb.last_error = health.lastError();
  publish(channel::kHeartbeat, hb);
}

}  // namespace sdlqr::bus

namespace sdlqr::bus {

double monotonicSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace sdlqr::bus
