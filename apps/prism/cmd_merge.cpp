// `prism merge`: combine EXRs rendered over disjoint --sample-range parts into one image,
// with their AOV layers (aov_exr.h).
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "aov_exr.h"
#include "command.h"
#include "prism/core/error.h"
#include "prism/core/version.h"
#include "prism/io/atomic_file.h"
#include "prism/io/exr.h"
#include "prism/render/merge_partial_renders.h"

namespace prism::cli {
namespace {

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string output;
};

int run_merge(const MergeOptions& o) {
  if (std::filesystem::path(o.output).extension() != ".exr")
    throw UsageError(fmt::format("merge writes EXR: '{}' does not end in .exr", o.output));
  check_writable_output(o.output);
  std::vector<PartialRender> parts;
  ExrFile first_file;
  for (const auto& name : o.inputs) {
    ExrFile f = read_exr(name);
    const auto& ints = f.metadata.ints;
    const auto& strings = f.metadata.strings;
    if (!ints.contains("prism:sampleBegin") || !ints.contains("prism:sampleEnd") || !strings.contains("prism:fingerprint"))
      throw UsageError(fmt::format("'{}' is not a Prism render with sample-range metadata", name));
    AovImages aovs = read_aov_exr_channels(name, f.image.width, f.image.height);
    parts.push_back({name, std::move(f.image), ints.at("prism:sampleBegin"), ints.at("prism:sampleEnd"),
                     strings.at("prism:fingerprint"), std::move(aovs)});
    if (parts.size() == 1) first_file = std::move(f);
  }
  const MergedRender merged = merge_partial_renders(parts);

  ExrMetadata meta;
  meta.strings["prism:version"] = kVersion;
  meta.strings["prism:fingerprint"] = parts.front().fingerprint;
  if (first_file.metadata.strings.contains("prism:scene"))
    meta.strings["prism:scene"] = first_file.metadata.strings.at("prism:scene");
  if (first_file.metadata.strings.contains("prism:sampler"))
    meta.strings["prism:sampler"] = first_file.metadata.strings.at("prism:sampler");  // the fingerprint covers it
  meta.ints["prism:spp"] = merged.samples;
  if (merged.aovs.set.any()) meta.strings["prism:aovs"] = format_aov_list(merged.aovs.set);
  // A contiguous union can be merged again with further parts; otherwise list the ranges.
  if (merged.ranges.size() == 1) {
    meta.ints["prism:sampleBegin"] = merged.ranges.front().first;
    meta.ints["prism:sampleEnd"] = merged.ranges.front().second;
  } else {
    std::string list;
    for (const auto& [a, b] : merged.ranges) list += fmt::format("{}{}:{}", list.empty() ? "" : ",", a, b);
    meta.strings["prism:sampleRanges"] = list;
  }
  const ExrChromaticities chroma = first_file.has_chromaticities
                                       ? first_file.chromaticities
                                       : throw UsageError(fmt::format("'{}' has no chromaticities", o.inputs.front()));
  write_exr(o.output, merged.image, chroma, meta, {}, aov_exr_channels(merged.aovs));
  fmt::print("prism: merged {} parts, {} spp -> {}\n", parts.size(), merged.samples, o.output);
  return 0;
}

}  // namespace

void add_merge_command(CLI::App& root, Action& action) {
  auto options = std::make_shared<MergeOptions>();
  CLI::App* cmd = root.add_subcommand(
      "merge", "Combine EXRs rendered with disjoint --sample-range parts into the image of one render of their union");
  cmd->add_option("inputs", options->inputs, "Partial renders (EXR written by prism render)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output, "Merged EXR")->required();
  cmd->callback([options, &action] { action = [options] { return run_merge(*options); }; });
}

}  // namespace prism::cli
