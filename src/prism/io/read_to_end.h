#pragma once
// Whole files into memory in pieces, not byte by byte: std::istreambuf_iterator costs a few
// instructions per byte (at DamagedHelmet's 20 MB of buffers and JPEGs, a tenth of its
// start-up; a 4k float OpenEXR sky is 100 MB), where a read of the file's size is a copy.
#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace prism {

// The rest of `in` (opened in binary mode) into `out`, replacing its contents. `expected_size`
// (the file's size, or 0 when unknown) sizes the first read; a file that is shorter or
// longer by the time it is read, or a stream of unknown size, is read on in pieces until
// its end, so the result is what reading byte by byte would give. Returns false when the
// stream reports a read error (badbit).
bool read_to_end(std::istream& in, std::uintmax_t expected_size, std::string& out);
bool read_to_end(std::istream& in, std::uintmax_t expected_size, std::vector<unsigned char>& out);

// The size of the regular file at `path`, or 0 when it has none (a directory, a pipe, an
// error): the expected_size for read_to_end.
std::uintmax_t regular_file_size_or_zero(const std::filesystem::path& path);

// The whole regular file at `path`, opened, sized and read as above. IoError
// "cannot read <what> '<path>': <reason>" (no such file, not a regular file, cannot open
// it, read error) otherwise; `what` names the file's role ("PLY mesh", "image").
std::string read_file_text(const std::filesystem::path& path, std::string_view what);
std::vector<unsigned char> read_file_bytes(const std::filesystem::path& path, std::string_view what);

}  // namespace prism
