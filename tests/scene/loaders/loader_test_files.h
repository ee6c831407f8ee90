#pragma once
// Scratch folders and files for the loader tests.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include "support/scratch_folder.h"

namespace prism::test {

inline std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Appends the bytes of `values` (little-endian on the machines we build for).
template <typename T>
void append(std::string& s, std::initializer_list<T> values) {
  for (T v : values) s.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

// A binary glTF (GLB 2.0 container): the JSON chunk padded with spaces and the BIN chunk
// with zeros to 4 bytes, as the container requires.
inline std::string glb(const std::string& json, const std::string& bin) {
  std::string j = json, b = bin;
  while (j.size() % 4) j += ' ';
  while (b.size() % 4) b += '\0';
  std::string out = "glTF";
  append<std::uint32_t>(out, {2, static_cast<std::uint32_t>(12 + 8 + j.size() + 8 + b.size())});
  append<std::uint32_t>(out, {static_cast<std::uint32_t>(j.size()), 0x4E4F534Au});  // "JSON"
  out += j;
  append<std::uint32_t>(out, {static_cast<std::uint32_t>(b.size()), 0x004E4942u});  // "BIN\0"
  out += b;
  return out;
}

// The message of the exception `f` throws as E ("" and a test failure when it throws nothing).
template <typename E, typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an exception";
  return {};
}

}  // namespace prism::test
