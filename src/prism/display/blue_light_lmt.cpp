#include "prism/display/blue_light_lmt.h"

#include <cmath>
#include <string>

#include "prism/core/error.h"

namespace prism::display {

const Mat3& blue_light_artifact_fix_matrix() {
  // correctionMatrix of LMT.Academy.BlueLightArtifactFix.ctl (published Academy data,
  // aces-dev v1.1–v1.3). The CTL multiplies row vectors by its transpose, i.e. column
  // vectors by the matrix as printed. Each row sums to 1, so neutrals are unchanged.
  static const Mat3 m = [] {
    Mat3 r;
    r.m = {{{0.9404372683, -0.0183068787, 0.0778696104},
            {0.0083786969, 0.8286599939, 0.1629613092},
            {0.0005471261, -0.0008833746, 1.0003362486}}};
    return r;
  }();
  return m;
}

Mat3 blue_correction_matrix(double strength) {
  if (!(strength >= 0.0 && strength <= 1.0))
    throw UsageError("blue correction strength must be in [0, 1], got " + std::to_string(strength));
  const Mat3& fix = blue_light_artifact_fix_matrix();
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = strength * fix.m[i][j] + (1.0 - strength) * (i == j ? 1.0 : 0.0);
  return r;
}

}  // namespace prism::display
