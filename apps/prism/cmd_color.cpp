// `prism color convert|matrix|encode|decode|spaces`: thin adapters over prism::color.
// Output is machine-readable: plain numbers printed with %.9g (enough digits to round-trip
// a float exactly), separated by single spaces, one line per row.
#include "cmd_color.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "prism/color/chromatic_adaptation.h"
#include "prism/color/color_space.h"
#include "prism/color/transfer_functions.h"
#include "prism/core/error.h"

namespace prism::cli {

// Strict: the whole text must be one finite number (std::from_chars, locale-independent).
double parse_number(const std::string& text, const std::string& what) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value))
    throw UsageError("malformed number '" + text + "' for " + what);
  return value;
}

namespace {

namespace color = prism::color;

constexpr const char* kNegativeNote = "Negative numbers are written as they are (-0.5), or after `--`.";


void print_numbers(const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) std::printf(i == 0 ? "%.9g" : " %.9g", values[i]);
  std::printf("\n");
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : "|") + n;
  return out;
}

// --from SPACE --to SPACE [--cat CAT]: shared by convert and matrix.
void add_space_pair_options(CLI::App& cmd, std::string& from, std::string& to, std::string& cat) {
  cmd.add_option("--from", from, "Source space (see `prism color spaces`, or xy:rx,ry,gx,gy,bx,by,wx,wy)")
      ->required()
      ->type_name("SPACE");
  cmd.add_option("--to", to, "Destination space")->required()->type_name("SPACE");
  cmd.add_option("--cat", cat, "Chromatic adaptation: " + joined(color::cat_names()))
      ->capture_default_str()
      ->type_name("CAT");
}

void add_convert(CLI::App& color, Action& action) {
  struct Options {
    std::string from, to, cat = "bradford";
    std::vector<std::string> rgb;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = color.add_subcommand(
      "convert", "Convert one linear RGB triple between colour spaces (adapting whites)");
  add_space_pair_options(*cmd, opt->from, opt->to, opt->cat);
  // Read as text and parsed strictly below (parse_number), as every number of `prism color`.
  cmd->add_option("rgb", opt->rgb, "Linear R G B in the source space")->expected(3)->required();
  cmd->footer(std::string("Output: one line, the three converted values printed with %.9g.\n") + kNegativeNote);
  cmd->callback([opt, &action] {
    action = [opt] {
      const Vec3d rgb{parse_number(opt->rgb[0], "R"), parse_number(opt->rgb[1], "G"), parse_number(opt->rgb[2], "B")};
      const Mat3 m = color::conversion_matrix(color::parse_color_space(opt->from),
                                              color::parse_color_space(opt->to), color::parse_cat(opt->cat));
      const Vec3d out = m * rgb;
      print_numbers({out.x, out.y, out.z});
      return 0;
    };
  });
}

void add_matrix(CLI::App& color, Action& action) {
  struct Options {
    std::string from, to, cat = "bradford";
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = color.add_subcommand(
      "matrix", "Print the 3x3 matrix taking linear RGB in one space to another (adapting whites)");
  add_space_pair_options(*cmd, opt->from, opt->to, opt->cat);
  cmd->footer("Output: three lines of three numbers (%.9g), row-major; dst = M * src.\n"
              "Use --from SPACE --to xyz for the space's RGB-to-XYZ matrix.");
  cmd->callback([opt, &action] {
    action = [opt] {
      const Mat3 m = color::conversion_matrix(color::parse_color_space(opt->from),
                                              color::parse_color_space(opt->to), color::parse_cat(opt->cat));
      for (int row = 0; row < 3; ++row) print_numbers({m(row, 0), m(row, 1), m(row, 2)});
      return 0;
    };
  });
}

struct TransferOptions {
  std::string transfer;
  std::string value_text, nits_text;
  bool has_value = false, has_nits = false;
  bool output_nits = false;
  std::string white_nits_text, black_nits_text = "0";
};

// Reference white luminance for --nits: IEC 61966-2-1's 80 cd/m² sRGB display, the
// common 100 cd/m² BT.1886 studio display; overridable with --white-nits.
double white_nits(const TransferOptions& o, color::TransferFunction tf) {
  if (!o.white_nits_text.empty()) {
    const double w = parse_number(o.white_nits_text, "--white-nits");
    if (!(w > 0.0)) throw UsageError("--white-nits must be positive");
    return w;
  }
  return tf == color::TransferFunction::bt1886 ? 100.0 : color::kScrgbWhiteNits;
}

[[noreturn]] void no_nits(color::TransferFunction tf) {
  throw UsageError(std::string(color::transfer_function_name(tf)) +
                   " is scene-referred and has no absolute luminance: use --value");
}

double encode_from_nits(const TransferOptions& o, color::TransferFunction tf, double nits) {
  using TF = color::TransferFunction;
  switch (tf) {
    case TF::srgb: return color::srgb_encode(nits / white_nits(o, tf));
    case TF::bt1886:
      return color::bt1886_encode_nits(nits, white_nits(o, tf), parse_number(o.black_nits_text, "--black-nits"));
    case TF::pq: return color::pq_encode_nits(nits);
    case TF::scrgb: return color::scrgb_from_nits(nits);
    default: no_nits(tf);
  }
}

double decode_to_nits(const TransferOptions& o, color::TransferFunction tf, double code) {
  using TF = color::TransferFunction;
  switch (tf) {
    case TF::srgb: return color::srgb_decode(code) * white_nits(o, tf);
    case TF::bt1886:
      return color::bt1886_decode_nits(code, white_nits(o, tf), parse_number(o.black_nits_text, "--black-nits"));
    case TF::pq: return color::pq_decode_nits(code);
    case TF::scrgb: return color::scrgb_to_nits(code);
    default: no_nits(tf);
  }
}

const char* kLinearScales =
    "Linear scales: srgb, bt1886: relative, 1 = display white; pq: 1 = 10000 nits;\n"
    "hlg: scene-linear E in [0, 1]; scrgb: 1 = 80 nits; acescc, acescct: ACES linear (AP1).\n"
    "--nits is defined for srgb (white 80 nits), bt1886 (white 100, black 0 nits; change\n"
    "with --white-nits/--black-nits), pq (absolute) and scrgb (1.0 = 80 nits).\n";

void add_encode(CLI::App& color, Action& action) {
  auto opt = std::make_shared<TransferOptions>();
  CLI::App* cmd = color.add_subcommand("encode", "Encode a linear value or a luminance with a transfer function");
  cmd->add_option("--transfer", opt->transfer, "Transfer function: " + joined(color::transfer_function_names()))
      ->required()
      ->type_name("NAME");
  auto* value = cmd->add_option("--value", opt->value_text, "Linear input on the function's own scale")->type_name("NUMBER");
  auto* nits = cmd->add_option("--nits", opt->nits_text, "Input luminance in cd/m^2 (nits)")->type_name("NUMBER");
  value->excludes(nits);
  cmd->add_option("--white-nits", opt->white_nits_text, "Display white luminance for srgb/bt1886 --nits")
      ->type_name("NUMBER");
  cmd->add_option("--black-nits", opt->black_nits_text, "Display black luminance for bt1886 --nits")
      ->capture_default_str()
      ->type_name("NUMBER");
  cmd->footer(std::string("Output: one line, the code value printed with %.9g.\n") + kLinearScales + kNegativeNote);
  cmd->callback([opt, value, nits, &action] {
    opt->has_value = value->count() > 0;
    opt->has_nits = nits->count() > 0;
    action = [opt] {
      const color::TransferFunction tf = color::parse_transfer_function(opt->transfer);
      if (!opt->has_value && !opt->has_nits) throw UsageError("encode needs --value V or --nits L");
      const double code = opt->has_nits ? encode_from_nits(*opt, tf, parse_number(opt->nits_text, "--nits"))
                                        : color::transfer_encode(tf, parse_number(opt->value_text, "--value"));
      print_numbers({code});
      return 0;
    };
  });
}

void add_decode(CLI::App& color, Action& action) {
  auto opt = std::make_shared<TransferOptions>();
  CLI::App* cmd = color.add_subcommand("decode", "Decode a code value to linear light or to a luminance");
  cmd->add_option("--transfer", opt->transfer, "Transfer function: " + joined(color::transfer_function_names()))
      ->required()
      ->type_name("NAME");
  cmd->add_option("--value", opt->value_text, "Code value to decode")->required()->type_name("NUMBER");
  cmd->add_flag("--nits", opt->output_nits, "Print luminance in cd/m^2 instead of the linear value");
  cmd->add_option("--white-nits", opt->white_nits_text, "Display white luminance for srgb/bt1886 --nits")
      ->type_name("NUMBER");
  cmd->add_option("--black-nits", opt->black_nits_text, "Display black luminance for bt1886 --nits")
      ->capture_default_str()
      ->type_name("NUMBER");
  cmd->footer(std::string("Output: one line, the linear value (or, with --nits, the luminance) printed\n"
                          "with %.9g.\n") +
              kLinearScales + kNegativeNote);
  cmd->callback([opt, &action] {
    action = [opt] {
      const color::TransferFunction tf = color::parse_transfer_function(opt->transfer);
      const double code = parse_number(opt->value_text, "--value");
      print_numbers({opt->output_nits ? decode_to_nits(*opt, tf, code) : color::transfer_decode(tf, code)});
      return 0;
    };
  });
}

void add_spaces(CLI::App& color, Action& action) {
  CLI::App* cmd = color.add_subcommand("spaces", "List the named colour spaces with their primaries and white");
  cmd->footer("Output: one line per space: name rx ry gx gy bx by wx wy (%.9g).");
  cmd->callback([&action] {
    action = [] {
      for (const std::string& name : color::color_space_names()) {
        const color::ColorSpace& s = color::color_space(name);
        std::printf("%s ", name.c_str());
        print_numbers({s.red.x, s.red.y, s.green.x, s.green.y, s.blue.x, s.blue.y, s.white.x, s.white.y});
      }
      return 0;
    };
  });
}

}  // namespace

CLI::App* color_command(CLI::App& root) {
  for (CLI::App* sub : root.get_subcommands([](CLI::App* s) { return s->get_name() == "color"; })) return sub;
  CLI::App* color = root.add_subcommand("color", "Query colour spaces, adaptation and transfer functions");
  color->require_subcommand(1);
  color->footer("All output is plain numbers (%.9g), space separated; see each subcommand's --help.");
  return color;
}

void add_color_command(CLI::App& root, Action& action) {
  CLI::App& color = *color_command(root);
  add_convert(color, action);
  add_matrix(color, action);
  add_encode(color, action);
  add_decode(color, action);
  add_spaces(color, action);
  add_color_spectrum_commands(color, action);  // spectrum, wavelengths: cmd_color_spectrum.cpp
}

}  // namespace prism::cli
