// The declaration facility on a small struct of every kind: defaults, loading, the one-line
// errors naming the key, range ends, checks, nested sections, derived lists, the printed YAML.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "sdlqr/config/param_table.hpp"

namespace sdlqr {
namespace {

enum class Mode { kSlow, kFast };

struct Inner {
  double x;
  Inner() { declaration().setDefaults(*this); }
  static const ParamTable<Inner>& declaration() {
    static const ParamTable<Inner> table = [] {
      ParamTable<Inner> t("the inner part");
      t.number("x", &Inner::x, 0.5, "m", Range::closed(0.0, 1.0), "a length");
      return t;
    }();
    return table;
  }
};

struct Demo {
  double gain;
  int count;
  int64_t seed;
  bool enabled;
  Mode mode;
  Eigen::Vector3d weights;
  double low;
  double high;
  Inner inner;
  Eigen::Vector2d twice;  // follows gain unless given

  Demo() { declaration().setDefaults(*this); }
  static const ParamTable<Demo>& declaration() {
    static const ParamTable<Demo> table = [] {
      using P = Demo;
      ParamTable<P> t("a demonstration section");
      t.number("gain", &P::gain, 2.0, "1/s", Range::above(0.0), "how fast");
      t.integer("count", &P::count, 3, "-", Range::closed(1, 10), "how many");
      t.integer("seed", &P::seed, 7, "-", Range::atLeast(0), "noise seed");
      t.flag("enabled", &P::enabled, true, "on or off");
      t.choice("mode", &P::mode, Mode::kSlow, {{"slow", Mode::kSlow}, {"fast", Mode::kFast}}, "slow or fast");
      t.list("weights", &P::weights, {1.0, 2.0, 3.0}, "-", Range::atLeast(0.0), "one per axis");
      t.number("low", &P::low, 1.0, "s", Range::atLeast(0.0), "the lower end");
      t.number("high", &P::high, 2.0, "s", Range::finite(), "the upper end");
      t.section("inner", &P::inner);
      t.derivedList<2>(
          "twice", "1/s", Range::finite(), "twice the gain, twice", "[a, b]",
          [](P& p) { p.twice = Eigen::Vector2d(2 * p.gain, 2 * p.gain); }, [](const P& p) { return p.twice; },
          [](P& p, const Eigen::Vector2d& v) { p.twice = v; });
      t.check("high", [](const P& p) { return p.high > p.low; }, "must be > low");
      return t;
    }();
    return table;
  }
};

Demo load(const std::string& text) { return Demo::declaration().load(ConfigReader(YAML::Load(text), "demo")); }

ConfigError errorOf(const std::string& text) {
  try {
    load(text);
  } catch (const ConfigError& e) {
    return e;
  }
  return ConfigError("<none>", "<accepted>");
}

TEST(ParamTable, DefaultsComeFromTheDeclaration) {
  const Demo d;
  EXPECT_EQ(d.gain, 2.0);
  EXPECT_EQ(d.count, 3);
  EXPECT_EQ(d.seed, 7);
  EXPECT_TRUE(d.enabled);
  EXPECT_EQ(d.mode, Mode::kSlow);
  EXPECT_EQ(d.weights, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(d.inner.x, 0.5);
  EXPECT_EQ(d.twice, Eigen::Vector2d(4, 4));
  EXPECT_EQ(Demo::declaration().invalidReason(d), "");
}

TEST(ParamTable, LoadReadsThePresentKeysAndKeepsTheOthers) {
  const Demo d = load("{gain: 3, seed: 5000000000, enabled: false, mode: fast, weights: [0, 0, 1], inner: {x: 1}}");
  EXPECT_EQ(d.gain, 3.0);
  EXPECT_EQ(d.seed, 5000000000LL);
  EXPECT_FALSE(d.enabled);
  EXPECT_EQ(d.mode, Mode::kFast);
  EXPECT_EQ(d.weights, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(d.inner.x, 1.0);
  EXPECT_EQ(d.count, 3);
  EXPECT_EQ(d.twice, Eigen::Vector2d(6, 6)) << "a derived list follows the loaded gain";
  EXPECT_EQ(load("{twice: [1, 2]}").twice, Eigen::Vector2d(1, 2));
}

TEST(ParamTable, EveryErrorNamesTheFullKey) {
  EXPECT_EQ(errorOf("{gain: 0}").key(), "demo.gain");
  EXPECT_EQ(errorOf("{gain: fast}").key(), "demo.gain");
  EXPECT_EQ(errorOf("{count: 1.5}").key(), "demo.count");
  EXPECT_EQ(errorOf("{weights: [1, -1, 1]}").key(), "demo.weights[1]");
  EXPECT_EQ(errorOf("{weights: [1, 1]}").key(), "demo.weights");
  EXPECT_EQ(errorOf("{mode: medium}").key(), "demo.mode");
  EXPECT_EQ(errorOf("{inner: {x: 2}}").key(), "demo.inner.x");
  EXPECT_EQ(errorOf("{inner: 3}").key(), "demo.inner");
  EXPECT_EQ(errorOf("{low: 5}").key(), "demo.high");  // the check blames the key it names
  EXPECT_EQ(errorOf("{twice: [1, .nan]}").key(), "demo.twice[1]");
  EXPECT_EQ(errorOf("{gain: 1}").key(), "<none>");  // guards the cases above
}

TEST(ParamTable, TheReasonIsTheDeclaredRange) {
  EXPECT_STREQ(errorOf("{gain: -1}").what(), "demo.gain: must be > 0 1/s");
  EXPECT_STREQ(errorOf("{count: 11}").what(), "demo.count: must be in [1, 10]");
  EXPECT_STREQ(errorOf("{mode: medium}").what(), "demo.mode: expected slow or fast");
  EXPECT_STREQ(errorOf("{low: 5}").what(), "demo.high: must be > low");
}

TEST(ParamTable, RangeEndsAreOpenOrClosedAsDeclared) {
  EXPECT_EQ(errorOf("{count: 1}").key(), "<none>");   // closed: the end is in
  EXPECT_EQ(errorOf("{count: 10}").key(), "<none>");
  EXPECT_EQ(errorOf("{count: 0}").key(), "demo.count");
  EXPECT_EQ(errorOf("{gain: 0}").key(), "demo.gain");  // open: the end is out
  EXPECT_EQ(errorOf("{gain: 1e-300}").key(), "<none>");
  EXPECT_EQ(errorOf("{inner: {x: 0}}").key(), "<none>");
}

TEST(ParamTable, RangesAreCheckedBeforeTheChecks) {
  // low is out of its range and high below it: the range is reported, not the rule between the two.
  EXPECT_STREQ(errorOf("{low: -5, high: -10}").what(), "demo.low: must be >= 0 s");
}

TEST(ParamTable, UnknownKeysAreRefusedWithTheNearestKnownOne) {
  EXPECT_STREQ(errorOf("{gian: 1}").what(), "demo.gian: unknown key (did you mean 'gain'?)");
  EXPECT_STREQ(errorOf("{zzzzzz: 1}").what(), "demo.zzzzzz: unknown key");
  EXPECT_STREQ(errorOf("{inner: {y: 1}}").what(), "demo.inner.y: unknown key (did you mean 'x'?)");
}

TEST(ParamTable, ProgrammaticChangesAreCheckedLikeLoadedOnes) {
  Demo d;
  d.weights[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(Demo::declaration().invalidReason(d), "weights[2]: must be >= 0");
  d = Demo();
  d.inner.x = 3.0;
  EXPECT_EQ(Demo::declaration().invalidReason(d), "inner.x: must be in [0, 1] m");
}

TEST(ParamTable, PrintsCommentedYamlThatLoadsBackToTheSameValues) {
  std::ostringstream text;
  YamlWriter out(text);
  Demo::declaration().print(Demo(), out);
  EXPECT_EQ(text.str(),
            "gain: 2.0                             # [1/s] how fast\n"
            "count: 3                              # [-] how many\n"
            "seed: 7                               # [-] noise seed\n"
            "enabled: true                         # [-] on or off\n"
            "mode: slow                            # [-] slow or fast\n"
            "weights: [1.0, 2.0, 3.0]              # [-] one per axis\n"
            "low: 1.0                              # [s] the lower end\n"
            "high: 2.0                             # [s] the upper end\n"
            "inner:                                # the inner part\n"
            "  x: 0.5                              # [m] a length\n"
            "# twice: [a, b]                       # [1/s] twice the gain, twice\n");
  Demo changed = load("{gain: 0.25, mode: fast, twice: [1, 2], inner: {x: 0.125}}");
  std::ostringstream again;
  YamlWriter out_again(again);
  Demo::declaration().print(changed, out_again);
  EXPECT_NE(again.str().find("twice: [1.0, 2.0]"), std::string::npos) << "a given derived list is printed";
  const Demo reread = load(again.str());
  EXPECT_EQ(reread.gain, 0.25);
  EXPECT_EQ(reread.mode, Mode::kFast);
  EXPECT_EQ(reread.twice, Eigen::Vector2d(1, 2));
  EXPECT_EQ(reread.inner.x, 0.125);
}

TEST(ParamTable, DescribesEveryKeyForTheTests) {
  const std::vector<ParamInfo> params = Demo::declaration().params();
  ASSERT_EQ(params.size(), 10u);
  EXPECT_EQ(params[0].key, "gain");
  EXPECT_EQ(params[0].default_text, "2.0");
  EXPECT_EQ(params[5].kind, ParamKind::kList);
  EXPECT_EQ(params[5].size, 3);
  EXPECT_EQ(params[8].key, "inner.x");
  EXPECT_EQ(params[8].unit, "m");
  EXPECT_TRUE(params[9].derived);
  EXPECT_EQ(params[4].choices, (std::vector<std::string>{"slow", "fast"}));
  EXPECT_EQ(Demo::declaration().subsections(), std::vector<std::string>{"inner"});
}

TEST(Range, RulesReadAsTheyCheck) {
  EXPECT_EQ(Range::openClosed(0, 1).rule("s"), "must be in (0, 1] s");
  EXPECT_EQ(Range::closedOpen(0, 0.5).rule("-"), "must be in [0, 0.5)");
  EXPECT_EQ(Range::above(0).rule(""), "must be > 0");
  EXPECT_EQ(Range::atLeast(20).rule("m/s^2"), "must be >= 20 m/s^2");
  EXPECT_EQ(Range::finite().rule("rad"), "must be finite");
  EXPECT_FALSE(Range::finite().contains(std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(Range::atLeast(0).contains(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_TRUE(Range::open(0, 1).contains(0.5));
  EXPECT_FALSE(Range::open(0, 1).contains(1.0));
}

TEST(YamlNumber, ReadsBackExactlyAndAsAFloat) {
  EXPECT_EQ(yamlNumber(2.0), "2.0");
  EXPECT_EQ(yamlNumber(100.0), "100.0");
  EXPECT_EQ(yamlNumber(0.0005), "0.0005");
  EXPECT_EQ(yamlNumber(0.000125), "0.000125");
  EXPECT_EQ(yamlNumber(2e-5), "2.0e-5");
  EXPECT_EQ(yamlNumber(1e-12), "1.0e-12");
  EXPECT_EQ(yamlNumber(-1.0), "-1.0");
  EXPECT_EQ(yamlNumber(1e20), "1.0e+20");
  EXPECT_EQ(yamlNumber(9.81), "9.81");
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> exponent(-20.0, 20.0);
  for (int i = 0; i < 2000; ++i) {
    const double value = std::pow(10.0, exponent(random)) * (i % 2 ? -1.0 : 1.0);
    const std::string text = yamlNumber(value);
    EXPECT_EQ(YAML::Load(text).as<double>(), value) << text;
    EXPECT_NE(text.find('.'), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace sdlqr
