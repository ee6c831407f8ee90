#include "prism/render/aov.h"

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {

AovSet parse_aov_list(const std::string& text) {
  AovSet set;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    bool* flag = name == "albedo" ? &set.albedo : name == "normal" ? &set.normal : name == "depth" ? &set.depth
                  : name == "variance" ? &set.variance : name == "sample-count" ? &set.sample_count : nullptr;
    if (flag == nullptr)
      throw UsageError(fmt::format(
          "unknown --aov '{}' in '{}' (albedo, normal, depth, variance, sample-count, comma-separated)", name, text));
    if (*flag) throw UsageError(fmt::format("--aov '{}' lists '{}' twice", text, name));
    *flag = true;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return set;
}

std::string format_aov_list(const AovSet& aovs) {
  std::string s;
  for (const auto& [on, name] : {std::pair{aovs.albedo, "albedo"}, {aovs.normal, "normal"}, {aovs.depth, "depth"}, {aovs.variance, "variance"},
                              {aovs.sample_count, "sample-count"}})
    if (on) {
      if (!s.empty()) s += ',';
      s += name;
    }
  return s;
}

}  // namespace prism
