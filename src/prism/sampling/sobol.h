#pragma once
// The first two dimensions of Sobol's sequence (Sobol' 1967) as base-2 digital
// sequences: point i of dimension d is C_d · bits(i) over GF(2), where column j of the
// generator matrix C_d holds the direction number v_j = m_j / 2^(j+1) as a 32-bit
// fraction. Together the two dimensions form a (0,2)-sequence: every aligned block of
// 2^m consecutive points is a (0,m,2)-net. Only these two dimensions are needed because
// the samplers pad 1D and 2D requests (pbrt-v4's "padded" samplers; Burley 2020).
#include <array>
#include <cstdint>

namespace prism {

// The generator matrix of dimension 0 or 1, derived rather than tabulated.
//   dim 0: m_j = 1, so v_j = 2^-(j+1): the bit reversal of i (van der Corput).
//   dim 1: the primitive polynomial x + 1 (degree s = 1, no inner coefficients) gives
//          Sobol's recurrence m_j = 2·m_{j-1} ⊕ m_{j-1} with m_1 = 1, i.e. 1, 3, 5, 15,
//          17, 51, ... (rows of Pascal's triangle mod 2).
constexpr std::array<std::uint32_t, 32> sobol_generator_matrix(int dimension) {
  std::array<std::uint32_t, 32> columns{};
  std::uint32_t m = 1;  // m_j: an odd integer below 2^j
  for (int j = 0; j < 32; ++j) {
    if (dimension == 1 && j > 0) m = (m << 1) ^ m;
    columns[static_cast<std::size_t>(j)] = m << (31 - j);  // m_j / 2^(j+1) as a 32-bit fraction
  }
  return columns;
}

inline constexpr std::array<std::array<std::uint32_t, 32>, 2> kSobolMatrices{sobol_generator_matrix(0),
                                                                             sobol_generator_matrix(1)};

// C·i by bytes: table[b][v] is the XOR of the columns 8b..8b+7 selected by the bits of v,
// so a product costs four lookups instead of one step per set bit.
constexpr std::array<std::array<std::uint32_t, 256>, 4> sobol_byte_tables(int dimension) {
  const auto columns = sobol_generator_matrix(dimension);
  std::array<std::array<std::uint32_t, 256>, 4> tables{};
  for (std::size_t b = 0; b < 4; ++b)
    for (std::uint32_t v = 0; v < 256; ++v)
      for (std::size_t j = 0; j < 8; ++j)
        if ((v >> j) & 1u) tables[b][v] ^= columns[8 * b + j];
  return tables;
}

inline constexpr auto kSobolDimension1ByteTables = sobol_byte_tables(1);

constexpr std::uint32_t reverse_bits_32(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// The same product with every column bit-reversed, i.e. reverse_bits_32(C_1 · i): Owen
// scrambling works on reversed bits, so the samplers take the point in this form and save
// a reversal per request (x ↦ reverse(x) is linear over GF(2), so it commutes with the XOR).
constexpr std::array<std::array<std::uint32_t, 256>, 4> sobol_reversed_byte_tables(int dimension) {
  auto tables = sobol_byte_tables(dimension);
  for (auto& table : tables)
    for (std::uint32_t& entry : table) entry = reverse_bits_32(entry);
  return tables;
}

inline constexpr auto kSobolDimension1ReversedByteTables = sobol_reversed_byte_tables(1);

// Point `index` of Sobol' dimension 0 or 1 as a 32-bit fraction (value · 2^-32): the XOR
// of the columns of the index's set bits. Dimension 0's matrix is the bit reversal, done
// in closed form; dimension 1 by byte tables (tests check both against the matrices).
constexpr std::uint32_t sobol_sample_bits(std::uint32_t index, int dimension) {
  if (dimension == 0) return reverse_bits_32(index);
  const auto& t = kSobolDimension1ByteTables;
  return t[0][index & 0xffu] ^ t[1][(index >> 8) & 0xffu] ^ t[2][(index >> 16) & 0xffu] ^ t[3][index >> 24];
}

// reverse_bits_32(sobol_sample_bits(index, 1)) without the reversal.
constexpr std::uint32_t sobol_dimension1_reversed_bits(std::uint32_t index) {
  const auto& t = kSobolDimension1ReversedByteTables;
  return t[0][index & 0xffu] ^ t[1][(index >> 8) & 0xffu] ^ t[2][(index >> 16) & 0xffu] ^ t[3][index >> 24];
}

// A 32-bit fraction as a float in [0, 1): the top 24 bits, so 1 is never returned.
constexpr float bits_to_unit_float(std::uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

}  // namespace prism
