#pragma once
// Per-lane values of a kernel that works on a few lanes at once (camera packets, the plain
// diffuse lanes) that are written lane by lane before any lane is read, held without a
// constructor that clears them first. A std::array of a type with default member
// initialisers (Ray, Hit, SampledSpectrum, BounceSamples, LightSample in a std::optional)
// is cleared whole where it is declared; GCC 12 does that with `rep stosq`, which takes
// tens of cycles to start, once per array per call (perf annotate of
// shade_plain_lanes_avx2, docs/performance-design.md "Plain diffuse lanes").
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>

namespace prism {

template <class T, std::size_t N>
class LaneSlots {
  // Implicit-lifetime types (trivially copyable, trivially destructible): the bytes hold
  // T objects as soon as they are written, whole (set) or through data().
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "slots are written in place and never destroyed");

 public:
  LaneSlots() {}  // leaves every slot unwritten
  // Writes slot k; a slot is read only after it is written.
  void set(std::size_t k, const T& value) { std::construct_at(data() + k, value); }
  const T& operator[](std::size_t k) const { return data()[k]; }
  // The N slots in a row, for a callee that writes them.
  T* data() { return std::launder(reinterpret_cast<T*>(bytes_)); }
  const T* data() const { return std::launder(reinterpret_cast<const T*>(bytes_)); }
  static constexpr std::size_t size() { return N; }

 private:
  alignas(T) std::byte bytes_[sizeof(T) * N];
};

}  // namespace prism
