// SPDX-License-Identifier: Apache-2.0
#pragma once
// The hidden effects the truth can put into a flight, by the ids of the
// diagnosis's vocabulary (docs/science.md, docs/diagnose/heading.md), each
// with what it means physically here and the range a value must lie in.
// The diagnosis's code is not used: these are the truth's own definitions.
#include <map>
#include <string>
#include <vector>

namespace glider::truth {

struct EffectSpec {
  const char* id;
  const char* unit;
  double min, max;
  bool heading;  // heading plane (else the vertical plane)
  const char* meaning;
};

const std::vector<EffectSpec>& effect_specs();
const EffectSpec* find_effect(const std::string& id);

// "id=value" -> (id, value); throws std::invalid_argument naming the text,
// the id's allowed range, or the known ids.
std::pair<std::string, double> parse_effect(const std::string& text);

using Effects = std::map<std::string, double>;

}  // namespace glider::truth
