#include "command_line.h"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace prism::cli {
namespace {

// Operand i after `--` is shown to CLI11 as this mark followed by i: a word it can only take
// for a positional argument (it begins with neither '-' nor a subcommand's name), so that
// it assigns the operands to positional arguments as it assigns any.
constexpr std::string_view kOperandMark = "\x1f" "prism-operand:";

std::string placeholder(std::size_t index) { return std::string(kOperandMark) + std::to_string(index); }

std::optional<std::size_t> operand_index(const std::string& word) {
  if (!word.starts_with(kOperandMark)) return std::nullopt;
  return std::stoul(word.substr(kOperandMark.size()));
}

// `text` with each placeholder replaced by its operand (for CLI11's messages).
std::string with_operands(std::string text, const std::vector<std::string>& operands) {
  for (std::size_t at = text.find(kOperandMark); at != std::string::npos; at = text.find(kOperandMark, at)) {
    std::size_t end = at + kOperandMark.size();
    while (end < text.size() && text[end] >= '0' && text[end] <= '9') ++end;
    const std::string& operand = operands.at(std::stoul(text.substr(at + kOperandMark.size(), end - at)));
    text.replace(at, end - at, operand);
    at += operand.size();
  }
  return text;
}

void collect_options(CLI::App& app, std::vector<CLI::Option*>& out) {
  for (CLI::Option* option : app.get_options([](CLI::Option*) { return true; })) out.push_back(option);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) collect_options(*sub, out);
}

void set_validators_active(CLI::Option& option, bool active) {
  for (int i = 0;; ++i) {
    CLI::Validator* validator = nullptr;
    try {
      validator = option.get_validator(i);
    } catch (const CLI::OptionNotFound&) {
      return;
    }
    validator->active(active);
  }
}

// After the parse: each positional argument's placeholders replaced by their operands, and
// its values checked and converted again, now with its validators.
void give_operands(const std::vector<CLI::Option*>& options, const std::vector<std::string>& operands) {
  for (CLI::Option* option : options) {
    const std::vector<std::string> results = option->results();
    const bool has_operand = std::any_of(results.begin(), results.end(),
                                         [](const std::string& r) { return operand_index(r).has_value(); });
    if (!option->get_positional()) {
      if (has_operand)  // `-o --`: POSIX would take `--` for -o's value; CLI11 never does
        throw CLI::ArgumentMismatch(option->get_name() + " needs its value before `--`", CLI::ExitCodes::ArgumentMismatch);
      continue;
    }
    set_validators_active(*option, true);
    if (results.empty()) continue;
    option->clear();
    for (const std::string& r : results) option->add_result(operand_index(r) ? operands[*operand_index(r)] : r);
    option->run_callback();
  }
}

}  // namespace

void parse_command_line(CLI::App& app, const std::vector<std::string>& args) {
  const auto marker = std::find(args.begin(), args.end(), std::string("--"));
  if (marker == args.end()) {
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
    return;
  }
  const std::vector<std::string> operands(marker + 1, args.end());
  std::vector<std::string> words(args.begin(), marker);
  for (std::size_t i = 0; i < operands.size(); ++i) words.push_back(placeholder(i));
  std::vector<CLI::Option*> options;
  collect_options(app, options);
  for (CLI::Option* option : options) {
    // A placeholder is no file name: validators (ExistingFile, ...) wait for the operands.
    if (option->get_positional()) set_validators_active(*option, false);
    // An option that takes a list (-o a -o b, or -o a b) takes one value a time here, as
    // POSIX options do, so that it cannot take the placeholders for more of its values.
    else option->allow_extra_args(false);
  }
  try {
    std::vector<std::string> reversed(words.rbegin(), words.rend());
    app.parse(reversed);
    give_operands(options, operands);
  } catch (const CLI::ParseError& e) {
    const std::string message = e.what();
    if (message.find(kOperandMark) == std::string::npos) throw;
    throw CLI::ParseError(with_operands(message, operands), e.get_exit_code());
  }
}

}  // namespace prism::cli
