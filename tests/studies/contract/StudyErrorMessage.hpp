#pragma once
// What the study-file tests ask of a refused file: the message of the StudyError it throws.
#include <gtest/gtest.h>

#include <string>

#include "studies/contract/StudyFile.hpp"

namespace granwave::testing {

// The message of the StudyError `f` throws (fails the test if it throws nothing).
template <typename F>
std::string studyError(F&& f) {
  try {
    f();
  } catch (const granwave::StudyError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no StudyError thrown";
  return "";
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace granwave::testing
