#include "sdlqr/batch/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

namespace sdlqr::batch {

namespace {

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * fraction);
  return text;
}

std::string rateLine(long long passed, long long total) {
  const Interval ci = wilson(passed, total);
  std::ostringstream line;
  line << passed << "/" << total << " = " << percent(total ? static_cast<double>(passed) / total : 0.0) << "  [95 % Wilson "
       << percent(ci.low) << " .. " << percent(ci.high) << "]";
  return line.str();
}

double number(const std::string& cell) { return cell.empty() ? std::nan("") : std::strtod(cell.c_str(), nullptr); }

std::string distributionText(const Distribution& d) {
  std::ostringstream t;
  switch (d.kind) {
    case Distribution::Kind::kUniform: t << "uniform [" << d.a << ", " << d.b << "]"; break;
    case Distribution::Kind::kNormal: t << "normal mean " << d.a << " std " << d.b; break;
    case Distribution::Kind::kGrid:
      t << "grid [";
      for (size_t i = 0; i < d.grid.size(); ++i) t << (i ? ", " : "") << d.grid[i];
      t << "]";
      break;
  }
  if (d.relative) t << " x nominal";
  return t.str();
}

}  // namespace

Interval wilson(long long passed, long long total, double z) {
  if (total <= 0) return {0.0, 1.0};
  const double n = static_cast<double>(total);
  const double p = static_cast<double>(passed) / n;
  const double z2 = z * z;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = z / (1.0 + z2 / n) * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

std::vector<size_t> worstRows(const Table& table, size_t count) {
  const int pass = table.column("pass"), failed = table.column("failed_checks"), tilt = table.column("max_tilt_deg");
  std::vector<size_t> failing;
  for (size_t i = 0; i < table.rows.size(); ++i) {
    if (table.rows[i][pass] != "1") failing.push_back(i);
  }
  std::stable_sort(failing.begin(), failing.end(), [&](size_t a, size_t b) {
    const double fa = number(table.rows[a][failed]), fb = number(table.rows[b][failed]);
    if (fa != fb) return fa > fb;
    return number(table.rows[a][tilt]) > number(table.rows[b][tilt]);
  });
  if (failing.size() > count) failing.resize(count);
  return failing;
}

std::string summaryText(const BatchContext& context, const Table& table) {
  const BatchSpec& spec = context.spec;
  std::ostringstream out;
  out << "batch " << spec.path << ": scenario " << context.scenario.name << ", " << spec.flights << " flights x "
      << spec.controllers.size() << " controller(s), seed " << spec.seed << "\n";
  for (const ParameterSpec& p : spec.parameters) {
    out << "  " << p.parameter.key << " [" << p.parameter.info.unit << "]: " << distributionText(p.distribution) << "\n";
  }
  const int controller = table.column("controller"), pass = table.column("pass");
  for (const std::string& name : spec.controllers) {
    long long total = 0, passed = 0;
    for (const auto& r : table.rows) {
      if (r[controller] != name) continue;
      ++total;
      passed += r[pass] == "1" ? 1 : 0;
    }
    out << "\n" << name << ": every check passed in " << rateLine(passed, total) << "\n";
    for (const std::string& key : context.criteria) {
      const int c = table.column(key);
      long long judged = 0, ok = 0;
      for (const auto& r : table.rows) {
        if (r[controller] != name || r[c].empty()) continue;
        ++judged;
        ok += r[c] == "1" ? 1 : 0;
      }
      char label[48];
      std::snprintf(label, sizeof label, "  %-32s", key.c_str());
      out << label << rateLine(ok, judged) << "\n";
    }
  }
  const std::vector<size_t> worst = worstRows(table, 5);
  out << "\nworst flights (" << (worst.empty() ? "none failed" : "most failed checks first") << ")\n";
  for (size_t i : worst) {
    const auto& r = table.rows[i];
    out << "  flight " << r[0] << " (" << r[1] << ", seed " << r[2] << "): " << r[table.column("failed_checks")]
        << " failed checks:";
    for (const std::string& key : context.criteria) {
      if (r[table.column(key)] == "0") out << " " << key << "=" << r[table.column(key + ".value")];
    }
    for (const ParameterSpec& p : spec.parameters) out << "; " << p.parameter.key << "=" << r[table.column(p.parameter.key)];
    out << "\n    alone:        ./sdlqr batch " << spec.path << " --refly " << r[0] << " --controller " << r[1]
        << " --out refly-" << r[0] << "\n    over the bus: ./sdlqr run refly-" << r[0] << "/scenario.yaml --plant-config refly-"
        << r[0] << "/plant.yaml   (after the line above; writes runs/<date>-" << context.scenario.name
        << "/flight.lcmlog)\n";
  }
  return out.str();
}

}  // namespace sdlqr::batch
