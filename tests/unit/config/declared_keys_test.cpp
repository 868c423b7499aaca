// Every declared key of the vehicle file against its section's loader, in process: each invalid
// value derived from the declarations (declared_cases.hpp) is refused with a ConfigError naming
// exactly that key. A parameter added to a declaration is covered without editing this test.

#include <gtest/gtest.h>

#include <iostream>
#include <map>

#include "declared_cases.hpp"
#include "sdlqr/params/vehicle_file.hpp"

namespace sdlqr {
namespace {

TEST(DeclaredKeys, EveryInvalidValueOfEveryDeclaredKeyIsRefusedNamingIt) {
  const YAML::Node defaults = YAML::Load(params::defaultVehicleFileText());
  std::map<std::string, int> per_section;
  int refused = 0, total = 0;
  for (const auto& [section, declaration] : params::declarations()) {
    for (const testing::DeclaredCase& c : testing::declaredCases(section, *declaration)) {
      ++total;
      ++per_section[section];
      const ConfigReader root(withCase(defaults, c), "");
      try {
        declaration->checkLoads(root.child(section));
        ADD_FAILURE() << c.name << ": accepted";
      } catch (const ConfigError& e) {
        EXPECT_EQ(e.key(), c.key) << c.name << ": " << e.what();
        if (e.key() == c.key) ++refused;
      }
    }
  }
  std::cout << refused << " of " << total << " invalid values refused naming their key:";
  for (const auto& [section, count] : per_section) std::cout << " " << section << " " << count;
  std::cout << "\n";
  EXPECT_GT(total, 800);  // every section contributes; an empty declaration list would pass silently
}

TEST(DeclaredKeys, TheUnchangedDefaultsLoadInEverySection) {
  const ConfigReader root(YAML::Load(params::defaultVehicleFileText()), "");
  for (const auto& [section, declaration] : params::declarations()) {
    EXPECT_NO_THROW(declaration->checkLoads(root.child(section))) << section;
  }
}

TEST(DeclaredKeys, EveryKeyHasAUnitAHelpTextAndARangeItsDefaultMeets) {
  for (const auto& [section, declaration] : params::declarations()) {
    EXPECT_FALSE(declaration->help().empty()) << section;
    for (const ParamInfo& info : declaration->params()) {
      const std::string key = section + "." + info.key;
      EXPECT_FALSE(info.unit.empty()) << key;
      EXPECT_GE(info.help.size(), 4u) << key;
      if (info.kind == ParamKind::kNumber || info.kind == ParamKind::kInteger) {
        EXPECT_TRUE(info.range.contains(YAML::Load(info.default_text).as<double>())) << key << " = " << info.default_text;
      }
    }
  }
}

TEST(DeclaredKeys, TheDeclaredSectionsAreTheVehicleFileSectionsInOrder) {
  std::vector<std::string> declared;
  for (const auto& [section, declaration] : params::declarations()) declared.push_back(section);
  EXPECT_EQ(declared, vehicleFileSections());
}

// Guards the case generator: a loader that accepted everything would be caught.
TEST(DeclaredKeys, TheCasesBreakTheFile) {
  const YAML::Node defaults = YAML::Load(params::defaultVehicleFileText());
  const auto sections = params::declarations();
  const auto& [section, declaration] = sections.front();
  const std::vector<testing::DeclaredCase> cases = testing::declaredCases(section, *declaration);
  ASSERT_FALSE(cases.empty());
  for (const testing::DeclaredCase& c : cases) {
    EXPECT_NE(YAML::Dump(withCase(defaults, c)), YAML::Dump(defaults)) << c.name;
  }
  double value = 0.0;
  EXPECT_FALSE(testing::outsideValue(Range::atLeast(0), false, &value));
  ASSERT_TRUE(testing::outsideValue(Range::atLeast(0), true, &value));
  EXPECT_FALSE(Range::atLeast(0).contains(value));
  ASSERT_TRUE(testing::outsideValue(Range::open(0, 1), false, &value));
  EXPECT_FALSE(Range::open(0, 1).contains(value));
}

}  // namespace
}  // namespace sdlqr
