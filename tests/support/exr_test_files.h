#pragma once
// OpenEXR files of a kind Prism never writes, for the readers' tests.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <Imath/half.h>

#include <filesystem>
#include <vector>

namespace prism::test {

// A 3 × 2 file whose only channel is `channel` (e.g. "Y", luminance-only), stored as
// `type` (HALF or FLOAT), holding the six `values`.
inline void write_single_channel_exr(const std::filesystem::path& path, const char* channel, Imf::PixelType type,
                                     const std::vector<float>& values) {
  Imf::Header header(3, 2);
  header.channels().insert(channel, Imf::Channel(type));
  Imf::OutputFile out(path.c_str(), header);
  Imf::FrameBuffer fb;
  std::vector<float> floats = values;
  std::vector<half> halves(values.begin(), values.end());
  if (type == Imf::HALF)
    fb.insert(channel, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves.data()), sizeof(half), 3 * sizeof(half)));
  else
    fb.insert(channel,
              Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(floats.data()), sizeof(float), 3 * sizeof(float)));
  out.setFrameBuffer(fb);
  out.writePixels(2);
}

}  // namespace prism::test
