#include "prism/io/read_to_end.h"

#include <algorithm>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "prism/core/error.h"

namespace prism {
namespace {

// Pieces of at most this size: a file's size is a hint, not a promise, and a huge one
// should grow the buffer as it is read (as byte-by-byte reading did), not all at once.
constexpr std::size_t kMaxPieceBytes = std::size_t{256} << 20;
constexpr std::size_t kMinPieceBytes = std::size_t{64} << 10;  // after the expected size, or without one

template <class Bytes>
bool read_pieces(std::istream& in, std::uintmax_t expected_size, Bytes& out) {
  out.clear();
  while (in) {
    const std::size_t have = out.size();
    const std::size_t expected_rest = expected_size > have ? static_cast<std::size_t>(std::min<std::uintmax_t>(
                                                                 expected_size - have, kMaxPieceBytes))
                                                           : 0;
    // One byte more than expected, so that a file of exactly the expected size ends in this
    // read (the stream sees its end) instead of another.
    const std::size_t piece = expected_rest > 0 ? expected_rest + 1 : kMinPieceBytes;
    out.resize(have + piece);
    in.read(reinterpret_cast<char*>(out.data() + have), static_cast<std::streamsize>(piece));
    out.resize(have + static_cast<std::size_t>(in.gcount()));
  }
  return !in.bad();
}

}  // namespace

bool read_to_end(std::istream& in, std::uintmax_t expected_size, std::string& out) {
  return read_pieces(in, expected_size, out);
}

bool read_to_end(std::istream& in, std::uintmax_t expected_size, std::vector<unsigned char>& out) {
  return read_pieces(in, expected_size, out);
}

std::uintmax_t regular_file_size_or_zero(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || ec) return 0;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return ec ? 0 : size;
}

namespace {

template <class Bytes>
Bytes read_whole_file(const std::filesystem::path& path, std::string_view what) {
  const auto fail = [&](std::string_view reason) {
    return IoError(fmt::format("cannot read {} '{}': {}", what, path.string(), reason));
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw fail(std::filesystem::exists(path, ec) ? "not a regular file" : "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail("cannot open it");
  Bytes bytes;
  if (!read_to_end(in, regular_file_size_or_zero(path), bytes)) throw fail("read error");
  return bytes;
}

}  // namespace

std::string read_file_text(const std::filesystem::path& path, std::string_view what) {
  return read_whole_file<std::string>(path, what);
}

std::vector<unsigned char> read_file_bytes(const std::filesystem::path& path, std::string_view what) {
  return read_whole_file<std::vector<unsigned char>>(path, what);
}

}  // namespace prism
