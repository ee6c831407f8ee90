#include "prism/render/checkpoint.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"

namespace prism {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'I', 'S', 'M', 'C', 'K', 'P'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 8 + 4 + 8 + 4 * 4;
constexpr std::size_t kPixelBytes = 6 * 8 + 4;

std::uint64_t fnv1a(const unsigned char* data, std::size_t size) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 0x100000001b3ull;
  return h;
}

class Writer {
 public:
  template <typename T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof v);
  }
  std::vector<unsigned char>& bytes() { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
};

class Reader {
 public:
  explicit Reader(const std::vector<unsigned char>& bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    T v;
    std::memcpy(&v, bytes_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return v;
  }

 private:
  const std::vector<unsigned char>& bytes_;
  std::size_t pos_ = 0;
};

}  // namespace

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& c) {
  Writer w;
  w.bytes().insert(w.bytes().end(), std::begin(kMagic), std::end(kMagic));
  w.put(kVersion);
  w.put(c.fingerprint);
  w.put(static_cast<std::int32_t>(c.film.width()));
  w.put(static_cast<std::int32_t>(c.film.height()));
  w.put(static_cast<std::int32_t>(c.first_sample));
  w.put(static_cast<std::int32_t>(c.next_sample));
  w.bytes().reserve(kHeaderBytes + c.film.pixel_count() * kPixelBytes + 8);
  for (std::size_t i = 0; i < c.film.pixel_count(); ++i) {
    for (int k = 0; k < 3; ++k) w.put(c.film.sums()[i][k]);
    for (int k = 0; k < 3; ++k) w.put(c.film.sum_squares()[i][k]);
    w.put(c.film.counts()[i]);
  }
  w.put(fnv1a(w.bytes().data(), w.bytes().size()));

  AtomicFile file(path);
  {
    std::ofstream out(file.temporary_path(), std::ios::binary);
    out.write(reinterpret_cast<const char*>(w.bytes().data()), static_cast<std::streamsize>(w.bytes().size()));
    out.flush();
    if (!out) throw IoError(fmt::format("cannot write checkpoint '{}': {}", path.string(), std::strerror(errno)));
  }
  file.commit();
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  const auto fail = [&](const std::string& why) {
    return IoError(fmt::format("cannot read checkpoint '{}': {}", path.string(), why));
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail(std::strerror(errno));
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < kHeaderBytes + 8 || std::memcmp(bytes.data(), kMagic, 8) != 0)
    throw fail("not a Prism checkpoint");
  Reader r(bytes);  // sizes are checked below before the pixel data is read
  r.get<std::uint64_t>();  // magic
  if (r.get<std::uint32_t>() != kVersion) throw fail("unsupported checkpoint version");
  Checkpoint c;
  c.fingerprint = r.get<std::uint64_t>();
  const std::int32_t width = r.get<std::int32_t>(), height = r.get<std::int32_t>();
  c.first_sample = r.get<std::int32_t>();
  c.next_sample = r.get<std::int32_t>();
  // Check the size before trusting the header's dimensions for an allocation.
  if (width < 1 || height < 1 || width > 32768 || height > 32768) throw fail("corrupt header");
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (bytes.size() != kHeaderBytes + pixels * kPixelBytes + 8) throw fail("truncated or corrupt file");
  std::uint64_t stored_hash;
  std::memcpy(&stored_hash, bytes.data() + bytes.size() - 8, 8);
  if (stored_hash != fnv1a(bytes.data(), bytes.size() - 8)) throw fail("checksum mismatch (corrupt file)");
  if (c.first_sample < 0 || c.next_sample < c.first_sample) throw fail("corrupt sample range");

  std::vector<Vec3d> sums(pixels), squares(pixels);
  std::vector<std::uint32_t> counts(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (int k = 0; k < 3; ++k) sums[i][k] = r.get<double>();
    for (int k = 0; k < 3; ++k) squares[i][k] = r.get<double>();
    counts[i] = r.get<std::uint32_t>();
  }
  c.film = Film(width, height, std::move(sums), std::move(squares), std::move(counts));
  return c;
}

}  // namespace prism
