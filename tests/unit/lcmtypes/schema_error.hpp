#pragma once
// Checks that reading a definition fails with one LcmSchemaError naming the file first
// ("bad.lcm:<line>: ...") and holding `fragment`.

#include <gtest/gtest.h>

#include <string>

#include "sdlqr/lcmgen/schema.hpp"

namespace sdlqr::lcmgen::test {

template <class Read>
void expectSchemaError(Read&& read, const std::string& fragment, const std::string& input) {
  try {
    read();
    ADD_FAILURE() << "no error for:\n" << input;
  } catch (const LcmSchemaError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("bad.lcm:", 0), 0u) << e.what();
  }
}

}  // namespace sdlqr::lcmgen::test
