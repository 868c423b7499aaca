// Signing and checking one message (common/bus signature.hpp): a signed message verifies, and
// every change to its bytes, its channel or its key makes it fail; the subscriber's admission
// tells an unsigned message from a forged one; LCM's own decoder (the one lcm-spy's Java twin
// mirrors) still reads a signed message, and so does the bus's decode (a signed log).

#include <gtest/gtest.h>

#include <vector>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/decode.hpp"
#include "sdlqr/bus/signature.hpp"
#include "sdlqr/rate_cmd_t.hpp"
#include "bus_test_helpers.hpp"

namespace sdlqr::bus {
namespace {

using test::keyOf;
using test::memq;

std::vector<uint8_t> encodedRateCommand() {
  RateCommand command;
  command.utime = 123456;
  command.seq = 7;
  command.body_rate = Vec3(0.1, -0.2, 0.3);
  command.thrust = 9.0;
  const rate_cmd_t message = toLcm(command);
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()) + kSignatureSize);
  message.encode(bytes.data(), 0, message.getEncodedSize());
  return bytes;
}

std::vector<uint8_t> signedRateCommand(const BusSigner& signer, SignatureTrailer trailer = {0xa1b2c3d4, 5000}) {
  std::vector<uint8_t> bytes = encodedRateCommand();
  signer.sign("QUAD/RATE_CMD", bytes.data(), bytes.size() - kSignatureSize, trailer);
  return bytes;
}

TEST(Signature, ASignedMessageVerifiesAndCarriesItsLinkAndTimestamp) {
  const BusSigner signer(keyOf(1));
  const std::vector<uint8_t> bytes = signedRateCommand(signer, {0xa1b2c3d4, 0x123456789abcULL});
  EXPECT_TRUE(signer.verify("QUAD/RATE_CMD", bytes.data(), bytes.size()));
  const SignatureTrailer trailer = trailerOf(bytes.data(), bytes.size());
  EXPECT_EQ(trailer.link, 0xa1b2c3d4u);
  EXPECT_EQ(trailer.timestamp, 0x123456789abcULL);
}

TEST(Signature, EveryFlippedBitOfPayloadOrTrailerFailsVerification) {
  const BusSigner signer(keyOf(1));
  const std::vector<uint8_t> good = signedRateCommand(signer);
  for (size_t byte = 0; byte < good.size(); ++byte) {
    std::vector<uint8_t> bad = good;
    bad[byte] ^= 0x04;
    EXPECT_FALSE(signer.verify("QUAD/RATE_CMD", bad.data(), bad.size())) << "byte " << byte;
  }
}

TEST(Signature, AnotherKeyOrAnotherChannelFailsVerification) {
  const BusSigner signer(keyOf(1));
  const std::vector<uint8_t> bytes = signedRateCommand(signer);
  EXPECT_FALSE(BusSigner(keyOf(2)).verify("QUAD/RATE_CMD", bytes.data(), bytes.size()));
  EXPECT_FALSE(signer.verify("OTHER/RATE_CMD", bytes.data(), bytes.size()));
  EXPECT_FALSE(signer.verify("QUAD/RATE_CMD", bytes.data(), bytes.size() - 1));  // truncated
  EXPECT_FALSE(signer.verify("QUAD/RATE_CMD", bytes.data(), kSignatureSize - 1));
}

TEST(Signature, AdmissionTellsUnsignedFromForgedFromReplayed) {
  const BusSigner signer(keyOf(1));
  ReplayWindow window;
  const uint64_t now = 5000;
  const std::vector<uint8_t> plain = encodedRateCommand();
  const size_t plain_size = plain.size() - kSignatureSize;
  EXPECT_EQ(admitSigned(signer, window, "QUAD/RATE_CMD", plain.data(), plain_size, true, now), RejectReason::kUnsigned);
  EXPECT_EQ(admitSigned(signer, window, "QUAD/RATE_CMD", plain.data(), 4, false, now), RejectReason::kUnsigned);

  const std::vector<uint8_t> forged = signedRateCommand(BusSigner(keyOf(9)));
  EXPECT_EQ(admitSigned(signer, window, "QUAD/RATE_CMD", forged.data(), forged.size(), false, now), RejectReason::kBadMac);

  const std::vector<uint8_t> good = signedRateCommand(signer);
  EXPECT_EQ(admitSigned(signer, window, "QUAD/RATE_CMD", good.data(), good.size(), false, now), RejectReason::kNone);
  EXPECT_EQ(admitSigned(signer, window, "QUAD/RATE_CMD", good.data(), good.size(), false, now), RejectReason::kReplayed);
}

TEST(Signature, TimestampsAreMavlinkTenMicrosecondUnitsSince2015) {
  EXPECT_EQ(signatureTime(1'420'070'400'000'000), 0u);
  EXPECT_EQ(signatureTime(1'420'070'400'000'000 + 1'000'000), 100'000u);
  EXPECT_EQ(signatureTime(0), 0u);  // before 2015
}

TEST(Signature, LcmsOwnDecoderReadsASignedMessage) {
  // LCM's generated decode stops at the encoding's end: the trailer is ignored, as by lcm-spy.
  const std::vector<uint8_t> bytes = signedRateCommand(BusSigner(keyOf(1)));
  rate_cmd_t decoded;
  EXPECT_EQ(decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size() - kSignatureSize));
  EXPECT_EQ(decoded.seq, 7);
}

TEST(Signature, TheBusDecodeReadsSignedAndUnsignedButNoOtherLength) {
  const std::vector<uint8_t> bytes = signedRateCommand(BusSigner(keyOf(1)));
  rate_cmd_t decoded;
  EXPECT_EQ(decode(bytes.data(), static_cast<uint32_t>(bytes.size()), decoded), RejectReason::kNone);
  EXPECT_EQ(decoded.seq, 7);
  EXPECT_EQ(decode(bytes.data(), static_cast<uint32_t>(bytes.size() - kSignatureSize), decoded), RejectReason::kNone);
  // Any other number of trailing bytes is no message.
  EXPECT_EQ(decode(bytes.data(), static_cast<uint32_t>(bytes.size() - 1), decoded), RejectReason::kBadSize);
  EXPECT_EQ(decode(bytes.data(), static_cast<uint32_t>(bytes.size() - kSignatureSize + 1), decoded), RejectReason::kBadSize);
}

}  // namespace
}  // namespace sdlqr::bus
