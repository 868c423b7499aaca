#include "sdlqr/batch/draws.hpp"

#include <cmath>

namespace sdlqr::batch {

namespace {

uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// A stream of its own for (seed, flight, slot).
class Stream {
 public:
  Stream(long long seed, int flight, int slot) {
    state_ = static_cast<uint64_t>(seed);
    state_ = splitmix64(state_) ^ static_cast<uint64_t>(flight);
    state_ = splitmix64(state_) ^ static_cast<uint64_t>(slot);
  }
  uint64_t next() { return splitmix64(state_); }
  // In (0, 1]: 53 random bits.
  double uniform() { return (static_cast<double>(next() >> 11) + 1.0) * 0x1p-53; }
  double normal() {  // Box-Muller
    const double r = std::sqrt(-2.0 * std::log(uniform()));
    return r * std::cos(2.0 * M_PI * uniform());
  }

 private:
  uint64_t state_;
};

double drawOne(const ParameterSpec& p, Stream& stream, int grid_index) {
  const Distribution& d = p.distribution;
  switch (d.kind) {
    case Distribution::Kind::kGrid:
      return d.grid[static_cast<size_t>(grid_index)];
    case Distribution::Kind::kUniform:
      return d.a + (d.b - d.a) * (1.0 - stream.uniform());  // [a, b)
    case Distribution::Kind::kNormal:
      break;
  }
  // Truncated to what the parameter accepts (checked again when the plant is built).
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const double v = d.a + d.b * stream.normal();
    if (d.relative ? v >= 0.0 : p.parameter.info.range.contains(v)) return v;
  }
  return d.a;
}

}  // namespace

FlightDraw drawFlight(const BatchSpec& spec, const closedloop::StackConfig& nominal, const sim::SimStress& stress,
                      int flight) {
  FlightDraw draw;
  draw.flight = flight;
  Stream seeds(spec.seed, flight, -1);
  draw.seed = static_cast<long long>(seeds.next() >> 2);  // >= 0, as sim.seed must be
  // Grids as one product, the last grid varying fastest.
  long long stride = 1;
  std::vector<int> grid_index(spec.parameters.size(), 0);
  for (size_t i = spec.parameters.size(); i-- > 0;) {
    const Distribution& d = spec.parameters[i].distribution;
    if (d.kind != Distribution::Kind::kGrid) continue;
    const long long n = static_cast<long long>(d.grid.size());
    grid_index[i] = static_cast<int>((flight / stride) % n);
    stride = std::min<long long>(stride * n, 1LL << 40);
  }
  for (size_t i = 0; i < spec.parameters.size(); ++i) {
    const ParameterSpec& p = spec.parameters[i];
    Stream stream(spec.seed, flight, static_cast<int>(i));
    double value = drawOne(p, stream, grid_index[i]);
    const bool whole_list = p.parameter.info.kind == ParamKind::kList && p.parameter.element < 0;
    if (p.distribution.relative && !whole_list) value *= nominalValue(p.parameter, nominal, stress);
    if (p.parameter.info.kind == ParamKind::kInteger) value = std::round(value);
    draw.values.push_back(value);
  }
  return draw;
}

bool inShard(int flight, int index, int count) { return flight % count == index - 1; }

}  // namespace sdlqr::batch
