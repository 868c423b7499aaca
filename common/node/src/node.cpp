#include "sdlqr/node/node.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <csignal>
#include <stdexcept>

#include "sdlqr/heartbeat_t.hpp"

namespace sdlqr::node {

namespace {

std::atomic<bool> g_stop_requested{false};

void onStopSignal(int) { g_stop_requested.store(true); }

double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace

Counters::Id Counters::add(const std::string& name) {
  for (size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return static_cast<Id>(i);
  }
  names_.push_back(name);
  values_.push_back(0);
  return static_cast<Id>(names_.size() - 1);
}

Node::Node(std::string process, const ProcessOptions& options)
    : process_(std::move(process)), vehicle_(options.vehicle) {
  for (char c : vehicle_) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) {
      throw std::invalid_argument("--vehicle: use letters, digits, '_' or '-' only, got '" + vehicle_ + "'");
    }
  }
  lcm_ = std::make_unique<lcm::LCM>(options.lcm_url);
  if (!lcm_->good()) {
    throw std::runtime_error("cannot open LCM bus '" + (options.lcm_url.empty() ? std::string("default") : options.lcm_url) +
                             "' (is multicast routed? see README, Troubleshooting)");
  }
  reject_decode_ = counters_.add("reject.decode");
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  encode_buffer_.resize(4096);
  next_heartbeat_ = std::chrono::steady_clock::now();
  cpu_window_start_ = next_heartbeat_;
  cpu_seconds_at_window_start_ = processCpuSeconds();
}

Node::~Node() = default;

void Node::dispatch(const lcm_recv_buf_t* rbuf, const char*, void* sub) {
  static_cast<SubscriptionBase*>(sub)->onMessage(rbuf->data, rbuf->data_size);
}

const std::string& Node::publishChannel(std::string_view base) {
  for (const auto& [known_base, full] : publish_channels_) {
    if (known_base == base) return full;
  }
  publish_channels_.emplace_back(std::string(base), channel(base));
  return publish_channels_.back().second;
}

void Node::dispatchRaw(const lcm::ReceiveBuffer* rbuf, const std::string& channel, RawSubscription* sub) {
  ++sub->node->received_;
  sub->handler(channel, rbuf->data, rbuf->data_size, rbuf->recv_utime);
}

void Node::subscribeRaw(const std::string& pattern, RawHandler handler, int queue_capacity) {
  auto sub = std::make_unique<RawSubscription>();
  sub->node = this;
  sub->handler = std::move(handler);
  lcm::Subscription* handle = lcm_->subscribeFunction(pattern, &Node::dispatchRaw, sub.get());
  if (queue_capacity > 0) handle->setQueueCapacity(queue_capacity);
  raw_subscriptions_.push_back(std::move(sub));
}

void Node::addSubscription(const std::string& channel, std::unique_ptr<SubscriptionBase> sub, int queue_capacity) {
  sub->node = this;
  // The channel is used as an exact name: escape regex characters LCM would interpret.
  std::string pattern;
  for (char c : channel) {
    if (std::string_view(".[]()*+?^$|\\{}").find(c) != std::string_view::npos) pattern.push_back('\\');
    pattern.push_back(c);
  }
  lcm_subscription_t* handle = lcm_subscribe(lcm_->getUnderlyingLCM(), pattern.c_str(), &Node::dispatch, sub.get());
  if (!handle) throw std::runtime_error("cannot subscribe to " + channel);
  if (queue_capacity > 0) lcm_subscription_set_queue_capacity(handle, queue_capacity);
  subscriptions_.push_back(std::move(sub));
}

void Node::noteSequence(SubscriptionBase& sub, int64_t seq) {
  // A forward jump is a loss; a backward jump is a publisher restart and starts a new count.
  if (sub.last_seq >= 0 && seq > sub.last_seq + 1) dropped_ += seq - sub.last_seq - 1;
  sub.last_seq = seq;
}

void Node::publishRaw(const std::string& channel, const void* data, int size) {
  if (lcm_->publish(channel, data, static_cast<unsigned int>(size)) != 0) {
    countError();
    setLastError("publish failed on " + channel);
    return;
  }
  ++published_;
}

bool Node::running() const { return !g_stop_requested.load(); }

bool Node::spin(int timeout_ms) {
  if (!running()) return false;
  const int status = lcm_->handleTimeout(timeout_ms);
  if (status < 0 && running()) {
    countError();
    setLastError("LCM handle failed");
  }
  if (std::chrono::steady_clock::now() >= next_heartbeat_) publishHeartbeat();
  return running();
}

void Node::shutdown() {
  state_ = ProcessState::kStopping;
  publishHeartbeat();
}

void Node::publishHeartbeat() {
  const auto now = std::chrono::steady_clock::now();
  next_heartbeat_ = now + std::chrono::seconds(1);
  const double window = std::chrono::duration<double>(now - cpu_window_start_).count();
  const double cpu_now = processCpuSeconds();
  const double cpu_percent = window > 0.05 ? 100.0 * (cpu_now - cpu_seconds_at_window_start_) / window : 0.0;
  if (window > 0.05) {
    cpu_window_start_ = now;
    cpu_seconds_at_window_start_ = cpu_now;
  }

  heartbeat_t hb;
  hb.utime = sim_utime_;
  hb.seq = heartbeat_seq_++;
  hb.process = process_;
  hb.pid = static_cast<int32_t>(getpid());
  hb.state = static_cast<int8_t>(running() ? state_ : ProcessState::kStopping);
  hb.received = received_;
  hb.published = published_;
  hb.dropped = dropped_;
  hb.rejected = rejected_;
  hb.deadline_misses = deadline_misses_;
  hb.errors = errors_;
  hb.cpu_percent = cpu_percent;
  hb.num_counters = static_cast<int32_t>(counters_.names().size());
  hb.counter_names = counters_.names();
  hb.counter_values = counters_.values();
  hb.last_error = last_error_;
  publish(channel::kHeartbeat, hb);
}

}  // namespace sdlqr::node
