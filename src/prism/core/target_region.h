#pragma once
// A region of code compiled for more of the processor than the build targets (the build is
// plain x86-64): every function defined between PRISM_TARGET_REGION_BEGIN("avx2") and
// PRISM_TARGET_REGION_END gets that target, so its intrinsics and wide vectors compile,
// and code outside it calls them only after checking the processor (__builtin_cpu_supports).
// GCC takes a target pragma; Clang (the sanitizer builds) a target attribute applied to
// every function of the region.
#define PRISM_PRAGMA(text) _Pragma(#text)
#if defined(__clang__)
#define PRISM_TARGET_REGION_BEGIN(features) \
  PRISM_PRAGMA(clang attribute push(__attribute__((target(features))), apply_to = function))
#define PRISM_TARGET_REGION_END PRISM_PRAGMA(clang attribute pop)
#else
#define PRISM_TARGET_REGION_BEGIN(features) PRISM_PRAGMA(GCC push_options) PRISM_PRAGMA(GCC target(features))
#define PRISM_TARGET_REGION_END PRISM_PRAGMA(GCC pop_options)
#endif
