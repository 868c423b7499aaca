#pragma once
// A folder of this test process under the build tree, gone when the process ends, and the text of
// the files written into it; a header, so the files of one test binary (one translation unit) share it.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace sdlqr::test {

// Of this process: ctest runs each test case in a process of its own, several at once.
inline std::string processWorkFolder(const std::string& test_name) {
  return SDLQR_BINARY_DIR "/" + test_name + "/" + std::to_string(::getpid());
}

class RemoveWorkFolder : public ::testing::Environment {
 public:
  explicit RemoveWorkFolder(std::string folder) : folder_(std::move(folder)) {}
  void TearDown() override { EXPECT_EQ(std::system(("rm -rf '" + folder_ + "'").c_str()), 0); }

 private:
  std::string folder_;
};

// `folder` goes when this process's tests are over.
inline const ::testing::Environment* removeAtExit(const std::string& folder) {
  return ::testing::AddGlobalTestEnvironment(new RemoveWorkFolder(folder));
}

// The whole of a file the test expects to be there.
inline std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.good()) << path;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace sdlqr::test
