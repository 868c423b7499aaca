// The key file of a signed bus (common/bus bus_key.hpp): mode 0600 or refused with a one-line
// error naming the file and its mode, 64 hex digits or refused, and the key never in any text.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "sdlqr/bus/bus_key.hpp"

namespace sdlqr::bus {
namespace {

constexpr const char* kKeyHex = "00112233445566778899aabbccddeeff0123456789ABCDEFfedcba9876543210";

class BusKeyFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("sdlqr_bus_key_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / "bus-QUAD.key").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void write(const std::string& text, mode_t mode) {
    { std::ofstream(path_) << text; }
    chmod(path_.c_str(), mode);
  }
  // The error text of loading the file (empty when it loads).
  std::string errorOf() {
    try {
      loadBusKey(path_);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_;
  std::string path_;
};

TEST_F(BusKeyFile, AKeyOfMode0600Loads) {
  write(std::string(kKeyHex) + "\n", 0600);
  const BusKey key = loadBusKey(path_);
  EXPECT_EQ(key.bytes[0], 0x00);
  EXPECT_EQ(key.bytes[1], 0x11);
  EXPECT_EQ(key.bytes[22], 0xCD);
  EXPECT_EQ(key.bytes[31], 0x10);
}

TEST_F(BusKeyFile, AnyOtherModeIsRefusedNamingTheFileAndItsMode) {
  for (mode_t mode : {0644, 0640, 0604, 0400, 0700, 0666}) {
    write(kKeyHex, mode);
    const std::string error = errorOf();
    char octal[8];
    std::snprintf(octal, sizeof octal, "%04o", static_cast<unsigned>(mode));
    EXPECT_NE(error.find(path_), std::string::npos) << error;
    EXPECT_NE(error.find(std::string("mode ") + octal), std::string::npos) << error;
    EXPECT_NE(error.find("0600"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(error.find("00112233"), std::string::npos) << "the key leaked into: " << error;
  }
}

TEST_F(BusKeyFile, AMissingFileADirectoryOrBadContentsAreRefused) {
  EXPECT_NE(errorOf().find(path_), std::string::npos);  // missing
  for (const std::string& text : {std::string(kKeyHex).substr(0, 62), std::string(kKeyHex) + "00",
                                  std::string(kKeyHex).replace(10, 1, "g"), std::string()}) {
    write(text, 0600);
    const std::string error = errorOf();
    EXPECT_NE(error.find("64 hexadecimal digits"), std::string::npos) << error;
    EXPECT_EQ(error.find("00112233"), std::string::npos) << "the key leaked into: " << error;
  }
  std::filesystem::remove(path_);
  std::filesystem::create_directory(path_);
  chmod(path_.c_str(), 0600);
  EXPECT_NE(errorOf().find("not a regular file"), std::string::npos);
}

TEST_F(BusKeyFile, TheEnvironmentNamesTheFileAndNoneMeansUnsigned) {
  unsetenv(kBusKeyVariable);
  EXPECT_FALSE(busKeyFromEnvironment().has_value());
  write(kKeyHex, 0600);
  setenv(kBusKeyVariable, path_.c_str(), 1);
  EXPECT_TRUE(busKeyFromEnvironment().has_value());
  chmod(path_.c_str(), 0644);
  EXPECT_THROW(busKeyFromEnvironment(), std::invalid_argument);
  unsetenv(kBusKeyVariable);
}

}  // namespace
}  // namespace sdlqr::bus
