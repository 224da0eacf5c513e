// SPDX-License-Identifier: Apache-2.0
#pragma once
// Helpers for the tests of configuration readers: the error a reader gives
// (empty when the text reads), and a text with one part replaced.
#include <string>

#include "glider/config/toml_document.hpp"

namespace glider::test {

template <typename Read>
std::string config_error_of(Read&& read) {
  try {
    read();
  } catch (const config::ConfigError& error) {
    return error.what();
  }
  return "";
}

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

}  // namespace glider::test
