#include "prism/render/checkpoint.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

#include <fmt/format.h>

#include "prism/core/error.h"
#include "prism/io/atomic_file.h"
#include "prism/io/read_to_end.h"

namespace prism {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'I', 'S', 'M', 'C', 'K', 'P'};
constexpr std::uint32_t kVersion = 2;
constexpr std::size_t kHeaderBytes = 8 + 4 + 8 + 4 * 4 + 4;
constexpr std::size_t kPixelBytes = 6 * 8 + 4;

std::size_t aov_pixel_bytes(const AovSet& a) {
  return (a.albedo ? 3 * 8 : 0) + (a.normal ? 3 * 8 : 0) + (a.depth ? 8 + 4 : 0) + (a.variance ? 3 * 8 : 0);
}

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
  const FilmAovSums& aov = c.film.aov_sums();
  w.put(static_cast<std::uint32_t>(aov.set.bits()));
  w.bytes().reserve(kHeaderBytes + c.film.pixel_count() * (kPixelBytes + aov_pixel_bytes(aov.set)) + 8);
  for (std::size_t i = 0; i < c.film.pixel_count(); ++i) {
    for (int k = 0; k < 3; ++k) w.put(c.film.sums()[i][k]);
    for (int k = 0; k < 3; ++k) w.put(c.film.sum_squares()[i][k]);
    w.put(c.film.counts()[i]);
    if (aov.set.albedo)
      for (int k = 0; k < 3; ++k) w.put(aov.albedo[i][k]);
    if (aov.set.normal)
      for (int k = 0; k < 3; ++k) w.put(aov.normal[i][k]);
    if (aov.set.depth) {
      w.put(aov.depth[i]);
      w.put(aov.depth_hits[i]);
    }
    if (aov.set.variance)
      for (int k = 0; k < 3; ++k) w.put(aov.cross[i][k]);
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
  std::vector<unsigned char> bytes;
  if (!read_to_end(in, regular_file_size_or_zero(path), bytes)) throw fail("read error");
  if (bytes.size() < 12 || std::memcmp(bytes.data(), kMagic, 8) != 0) throw fail("not a Prism checkpoint");
  Reader r(bytes);  // sizes are checked below before the pixel data is read
  r.get<std::uint64_t>();  // magic
  const auto version = r.get<std::uint32_t>();
  if (version != kVersion)
    throw fail(fmt::format("checkpoint format version {} is not supported (this Prism reads version {}); finish "
                           "it with the Prism that wrote it, or render again",
                           version, kVersion));
  if (bytes.size() < kHeaderBytes + 8) throw fail("truncated or corrupt file");
  Checkpoint c;
  c.fingerprint = r.get<std::uint64_t>();
  const std::int32_t width = r.get<std::int32_t>(), height = r.get<std::int32_t>();
  c.first_sample = r.get<std::int32_t>();
  c.next_sample = r.get<std::int32_t>();
  const auto aov_bits = r.get<std::uint32_t>();
  if (aov_bits > AovSet::kAllBits) throw fail("corrupt header (unknown AOVs)");
  FilmAovSums aov;
  aov.set = AovSet::from_bits(aov_bits);
  // Check the size before trusting the header's dimensions for an allocation.
  if (width < 1 || height < 1 || width > 32768 || height > 32768) throw fail("corrupt header");
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (bytes.size() != kHeaderBytes + pixels * (kPixelBytes + aov_pixel_bytes(aov.set)) + 8)
    throw fail("truncated or corrupt file");
  std::uint64_t stored_hash;
  std::memcpy(&stored_hash, bytes.data() + bytes.size() - 8, 8);
  if (stored_hash != fnv1a(bytes.data(), bytes.size() - 8)) throw fail("checksum mismatch (corrupt file)");
  if (c.first_sample < 0 || c.next_sample < c.first_sample) throw fail("corrupt sample range");

  std::vector<Vec3d> sums(pixels), squares(pixels);
  std::vector<std::uint32_t> counts(pixels);
  if (aov.set.albedo) aov.albedo.resize(pixels);
  if (aov.set.normal) aov.normal.resize(pixels);
  if (aov.set.depth) {
    aov.depth.resize(pixels);
    aov.depth_hits.resize(pixels);
  }
  if (aov.set.variance) aov.cross.resize(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (int k = 0; k < 3; ++k) sums[i][k] = r.get<double>();
    for (int k = 0; k < 3; ++k) squares[i][k] = r.get<double>();
    counts[i] = r.get<std::uint32_t>();
    if (aov.set.albedo)
      for (int k = 0; k < 3; ++k) aov.albedo[i][k] = r.get<double>();
    if (aov.set.normal)
      for (int k = 0; k < 3; ++k) aov.normal[i][k] = r.get<double>();
    if (aov.set.depth) {
      aov.depth[i] = r.get<double>();
      aov.depth_hits[i] = r.get<std::uint32_t>();
      if (aov.depth_hits[i] > counts[i]) throw fail("corrupt depth AOV (more hits than samples)");
    }
    if (aov.set.variance)
      for (int k = 0; k < 3; ++k) aov.cross[i][k] = r.get<double>();
  }
  c.film = Film(width, height, std::move(sums), std::move(squares), std::move(counts), std::move(aov));
  return c;
}

}  // namespace prism
