// Every message type of lcmtypes/ (the list is the generated one): a plain struct with a distinct
// non-default value in every number and text, converted to the lcm-gen class, encoded, decoded
// and converted back, is the same bit for bit. A field a conversion dropped would come back at
// its default, one it swapped with another would come back with the other's value: both fail,
// and the negative test shows that for every field of every type. The same holds through the
// logger's decodeMessage, which decodes and converts in one function (where LCM's type punning
// of doubles once lost fields to the optimizer: see lcmtypes/CMakeLists.txt). Types without
// strings or variable-length arrays convert without allocating.

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "allocation_counter.hpp"
#include "leaf_support.hpp"
#include "sdlqr/lcmtypes/generated/convert.hpp"
#include "sdlqr/lcmtypes/generated/plain_fields.hpp"
#include "sdlqr/lcmtypes/generated/lcm_fields.hpp"
#include "sdlqr/logger/decode.hpp"

namespace sdlqr::lcmtypes {
namespace {

using test::Differences;
using test::differences;

template <class Lcm>
using PlainOf = decltype(fromLcm(std::declval<const Lcm&>()));

// A struct with no std::vector and no std::string member.
struct FixedSize {
  bool fixed = true;
  template <class T>
  void leaf(const LeafName&, const T&) {
    if constexpr (std::is_same_v<T, std::string>) fixed = false;
  }
  template <class Vector>
  std::size_t rows(const LeafName&, const Vector&) {
    fixed = false;
    return 0;
  }
};

template <class Plain>
Plain filled() {
  Plain s;
  test::Filler filler;
  visitLeaves(filler, s);
  return s;
}

template <class Lcm>
void roundTrip(int* types, int* leaves) {
  using Plain = PlainOf<Lcm>;
  const Plain original = filled<Plain>();
  Plain defaults;
  test::Sizer sizer;
  visitLeaves(sizer, defaults);
  const Differences filled_leaves = differences(original, defaults);
  ASSERT_GT(filled_leaves.leaves, 0) << Lcm::getTypeName();
  EXPECT_EQ(filled_leaves.names.size(), static_cast<std::size_t>(filled_leaves.leaves))
      << Lcm::getTypeName() << ": a leaf kept its default value, a dropped field would go unseen";

  const std::vector<uint8_t> bytes = test::encode(toLcm(original));
  const Plain back = fromLcm(test::decode<Lcm>(bytes));
  const Differences after = differences(original, back);
  EXPECT_TRUE(after.names.empty()) << Lcm::getTypeName() << ": " << (after.names.empty() ? "" : after.names.front());
  EXPECT_EQ(after.leaves, filled_leaves.leaves) << Lcm::getTypeName();

  logger::LogEvent event;
  event.channel = "X";
  event.data = bytes.data();
  event.size = static_cast<int64_t>(bytes.size());
  Plain logged;
  ASSERT_TRUE(logger::decodeMessage(event, &logged)) << Lcm::getTypeName();
  const Differences through_log = differences(original, logged);
  EXPECT_TRUE(through_log.names.empty()) << Lcm::getTypeName() << " via decodeMessage: "
                                         << (through_log.names.empty() ? "" : through_log.names.front());
  ++*types;
  *leaves += after.leaves;
}

TEST(RoundTrip, EveryFieldOfEveryTypeSurvivesPlainToLcmToPlain) {
  int types = 0;
  int leaves = 0;
#define SDLQR_ROUND_TRIP(LCM) roundTrip<LCM>(&types, &leaves);
  SDLQR_LCMTYPES_SDLQR_EACH(SDLQR_ROUND_TRIP)
#undef SDLQR_ROUND_TRIP
  EXPECT_EQ(types, static_cast<int>(std::size(kAllTypes)));
  std::cout << "[ figures  ] " << types << " types, " << leaves << " numbers and texts round-tripped bit for bit\n";
}

// Negative: the comparison above sees each field on its own. Each top-level member of a filled
// struct is put back to its default in turn (what a conversion that forgot it would return).
template <class Lcm>
void eachDroppedFieldIsSeen(int* fields) {
  using Plain = PlainOf<Lcm>;
  const Plain original = filled<Plain>();
  int count = 0;
  visitFields([&](const PlainField&, const auto&) { ++count; }, original);
  for (int dropped = 0; dropped < count; ++dropped) {
    Plain back = original;
    const Plain defaults;
    std::string name;
    int index = 0;
    visitFields(
        [&](const PlainField& f, auto& member, const auto& initial) {
          if (index++ != dropped) return;
          member = initial;
          name = std::string(f.name);
        },
        back, defaults);
    const Differences d = differences(original, back);
    ASSERT_FALSE(d.names.empty()) << Lcm::getTypeName() << "." << name << " dropped and not seen";
    EXPECT_EQ(d.names.front().rfind(name, 0), 0u) << d.names.front() << " for " << name;
    ++*fields;
  }
}

TEST(RoundTrip, ADroppedFieldOfAnyTypeIsADifference) {
  int fields = 0;
#define SDLQR_DROPPED(LCM) eachDroppedFieldIsSeen<LCM>(&fields);
  SDLQR_LCMTYPES_SDLQR_EACH(SDLQR_DROPPED)
#undef SDLQR_DROPPED
  std::cout << "[ figures  ] " << fields << " fields, each seen when dropped\n";
  EXPECT_GT(fields, 100);
}

template <class Lcm>
void fixedSizeDoesNotAllocate(int* fixed_types) {
  using Plain = PlainOf<Lcm>;
  const Plain original = filled<Plain>();
  FixedSize probe;
  visitLeaves(probe, original);
  if (!probe.fixed) return;
  ++*fixed_types;
  const ::sdlqr::testing::AllocationCounter counter;
  const Lcm m = toLcm(original);
  const Plain back = fromLcm(m);
  EXPECT_EQ(counter.count(), 0) << Lcm::getTypeName();
  EXPECT_TRUE(differences(original, back).names.empty());
}

TEST(RoundTrip, FixedSizeTypesConvertWithoutAllocating) {
  int fixed_types = 0;
#define SDLQR_NO_ALLOCATION(LCM) fixedSizeDoesNotAllocate<LCM>(&fixed_types);
  SDLQR_LCMTYPES_SDLQR_EACH(SDLQR_NO_ALLOCATION)
#undef SDLQR_NO_ALLOCATION
  EXPECT_EQ(fixed_types, static_cast<int>(std::size(kAllTypes)) - 2);  // all but trajectory_t and heartbeat_t
  const Trajectory with_samples = filled<Trajectory>();
  const ::sdlqr::testing::AllocationCounter counter;
  const trajectory_t m = toLcm(with_samples);
  EXPECT_GT(counter.count(), 0) << "the counter sees the allocations of a variable-length type";
}

}  // namespace
}  // namespace sdlqr::lcmtypes
