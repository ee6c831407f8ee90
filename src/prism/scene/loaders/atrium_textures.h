#pragma once
// Procedural textures of the generated atrium (`prism generate atrium`): floor tiles with
// grout, ashlar wall blocks with mortar and a leaf cut-out for the foliage cards. Every
// texel comes from integer hashes of its coordinates, so the same build gives the same
// texels. Texels are made as 8-bit sRGB codes and decoded exactly as a loaded PNG would be
// (colour through the sRGB EOTF, alpha linear; texture_file.h), so writing them back as
// 8-bit PNG and loading the file again gives the same floats.
#include "prism/scene/texture.h"

namespace prism::loaders {

// Metres of floor or wall one repeat of the texture covers (uv = position / this).
inline constexpr float kFloorTextureMeters = 4.0f;  // 4 × 4 tiles of 1 m
inline constexpr float kWallTextureMeters = 4.0f;   // 4 × 8 blocks of 1 m × 0.5 m

// 512 × 512 RGB: a checkerboard of cream and terracotta tiles (128 px = 1 m), each with
// its own tint and mottling, separated by 4 px grout lines.
TextureImage make_floor_tile_texture();

// 512 × 512 RGB: sandstone blocks 128 × 64 px in running bond with 3 px mortar joints.
TextureImage make_wall_block_texture();

// 256 × 256 RGBA: a sprig of pointed leaves on a stem, alpha exactly 0 or 1 (a binary
// mask, so MASK at any cutoff in (0, 1) and pbrt-v4's stochastic alpha agree). The border
// rows and columns are transparent. The v axis points down the image: the stem's foot is
// at v = 1.
TextureImage make_leaf_texture();

}  // namespace prism::loaders
