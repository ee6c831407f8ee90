#include "prism/display/aces2_tables.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace prism::display {
namespace {

constexpr int kFirst = 1;                    // first nominal entry
constexpr int kLast = kAces2TableSize;       // last nominal entry
constexpr int kUpperWrap = kAces2TableSize + 1;
constexpr double kSmoothCuspM = 1.0 + 0.27 * 0.12;  // 1 + smooth_m · smooth_cusps
constexpr int kCorners = 6;

bool any_below_zero(const Vec3d& v) { return v.x < 0.0 || v.y < 0.0 || v.z < 0.0; }
bool any_above(const Vec3d& v, double limit) { return v.x > limit || v.y > limit || v.z > limit; }
double lerp(double a, double b, double t) { return a + t * (b - a); }

// Unit-cube corners in the order R, Y, G, C, B, M, so that their hues increase.
Vec3d cube_corner(int corner) {
  return {double(((corner + 1) % kCorners) < 3), double(((corner + 5) % kCorners) < 3),
          double(((corner + 3) % kCorners) < 3)};
}

// Six corners rotated so that the smallest hue is at index 1, with a copy of the last at
// 0 (hue − 360) and of the first at 7 (hue + 360), so that hues increase across the cycle.
struct CornerCycle {
  std::array<Vec3d, kCorners + 2> rgb{}, jmh{};
};

CornerCycle make_cycle(const std::array<Vec3d, kCorners>& rgb, const std::array<Vec3d, kCorners>& jmh) {
  int first = 0;
  for (int i = 1; i < kCorners; ++i)
    if (jmh[i].z < jmh[first].z) first = i;
  CornerCycle c;
  for (int i = 0; i < kCorners; ++i) {
    c.rgb[i + 1] = rgb[(i + first) % kCorners];
    c.jmh[i + 1] = jmh[(i + first) % kCorners];
  }
  c.rgb[0] = c.rgb[kCorners];
  c.jmh[0] = c.jmh[kCorners];
  c.rgb[kCorners + 1] = c.rgb[1];
  c.jmh[kCorners + 1] = c.jmh[1];
  c.jmh[0].z -= 360.0;
  c.jmh[kCorners + 1].z += 360.0;
  return c;
}

// The reach gamut's corners scaled until their J reaches J max (bisection on the scale,
// comparing achromatic responses, to 1e-3).
CornerCycle reach_corners(const HellwigCam& reach, double limit_j_max, double forward_limit) {
  const double limit_a = HellwigCam::j_to_achromatic(limit_j_max);
  std::array<Vec3d, kCorners> rgb, jmh;
  for (int i = 0; i < kCorners; ++i) {
    const Vec3d corner = cube_corner(i);
    double lower = 0.0, upper = forward_limit;
    while (upper - lower > 1e-3) {
      const double test = (lower + upper) / 2.0;
      const double a = reach.rgb_to_aab(corner * test).x;
      if (a < limit_a) lower = test;
      else upper = test;
      if (a == limit_a) break;
    }
    rgb[i] = corner * upper;
    jmh[i] = reach.rgb_to_jmh(rgb[i]);
  }
  return make_cycle(rgb, jmh);
}

CornerCycle limiting_corners(const HellwigCam& limit, double peak_nits) {
  std::array<Vec3d, kCorners> rgb, jmh;
  for (int i = 0; i < kCorners; ++i) {
    rgb[i] = cube_corner(i) * (peak_nits / 100.0);
    jmh[i] = limit.rgb_to_jmh(rgb[i]);
  }
  return make_cycle(rgb, jmh);
}

// The two corner sets' hues merged into one increasing list without repeats.
std::vector<double> merged_corner_hues(const CornerCycle& a, const CornerCycle& b) {
  std::vector<double> hues;
  int ia = 1, ib = 1;
  while (ia < kCorners + 1 || ib < kCorners + 1) {
    const double ha = a.jmh[ia].z, hb = b.jmh[ib].z;
    if (ha == hb) {
      hues.push_back(ha);
      ++ia;
      ++ib;
    } else if (ha < hb) {
      hues.push_back(ha);
      ++ia;
    } else {
      hues.push_back(hb);
      ++ib;
    }
  }
  return hues;
}

void fill_interval(Aces2Table& table, int first_index, int samples, double lower, double upper) {
  const double delta = (upper - lower) / samples;
  for (int i = 0; i < samples; ++i) table[first_index + i] = lower + i * delta;
}

// 360 hues, evenly spaced between consecutive corner hues, each corner hue placed at the
// table position nearest its value (moved by one where two corners would share one).
Aces2Table build_hue_table(const std::vector<double>& corner_hues) {
  const int n = int(corner_hues.size());
  std::vector<int> position(n, 0);
  int last = -1;
  int min_position = corner_hues[0] == 0.0 ? 0 : 1;  // always keep a sample at hue 0
  for (int k = 0; k < n; ++k) {
    int p = std::min(std::max(int(std::round(corner_hues[k])), min_position), kAces2TableSize - 1);
    if (p == last) {
      if (k > 1 && position[k - 2] != position[k - 1] - 1) position[k - 1] -= 1;
      else p += 1;
    }
    position[k] = std::min(p, kAces2TableSize - 1);
    last = min_position = p;
  }
  Aces2Table hues{};
  int total = 0;
  fill_interval(hues, total + kFirst, position[0], 0.0, corner_hues[0]);
  total += position[0];
  for (int k = 1; k < n; ++k) {
    const int samples = position[k] - position[k - 1];
    fill_interval(hues, total + kFirst, samples, corner_hues[k - 1], corner_hues[k]);
    total += samples;
  }
  fill_interval(hues, total + kFirst, kAces2TableSize - total, corner_hues[n - 1], 360.0);
  hues[0] = hues[kLast] - 360.0;
  hues[kUpperWrap] = hues[kFirst] + 360.0;
  return hues;
}

// The limiting gamut's cusp at `hue`: a point on the cube edge between the two corners
// whose hues enclose it (bisection along the edge to 1e-7). `previous` (corner, t) lets
// consecutive hues on one edge start where the last search ended.
Vec2<double> cusp_at_hue(double hue, const CornerCycle& c, const HellwigCam& limit, int& previous_corner,
                         double& previous_t) {
  int upper = 1;
  for (int i = 1; i < kCorners + 2; ++i)
    if (c.jmh[i].z > hue) {
      upper = i;
      break;
    }
  const int lower = upper - 1;
  if (c.jmh[lower].z == hue) return {c.jmh[lower].x, c.jmh[lower].y};
  const Vec3d from = c.rgb[lower], to = c.rgb[upper];
  double lower_t = upper == previous_corner ? previous_t : 0.0;
  double upper_t = 1.0;
  while (upper_t - lower_t > 1e-7) {
    const double t = (lower_t + upper_t) / 2.0;
    const double h = limit.rgb_to_jmh(from + (to - from) * t).z;
    // Near the 0/360 seam an edge's hues wrap: compare against its corners first.
    if (h < c.jmh[lower].z) upper_t = t;
    else if (h >= c.jmh[upper].z) lower_t = t;
    else if (h > hue) upper_t = t;
    else lower_t = t;
  }
  const double t = (lower_t + upper_t) / 2.0;
  const Vec3d jmh = limit.rgb_to_jmh(from + (to - from) * t);
  previous_corner = upper;
  previous_t = t;
  return {jmh.x, jmh.y};
}

// The approximate boundary at five lightnesses between the cusp and J max, for a trial
// upper-hull exponent, must lie outside the limiting gamut (some channel above peak).
struct GammaTest {
  Aces2HueShape shape;
  double hue;
  std::array<double, 5> j_intersect_source, slope, j_intersect_cusp;
};

GammaTest make_gamma_test(const Aces2HueShape& shape, double hue, const Aces2GamutGeometry& g) {
  constexpr std::array<double, 5> kPositions = {0.01, 0.1, 0.5, 0.8, 0.99};
  GammaTest test{shape, hue, {}, {}, {}};
  for (int k = 0; k < 5; ++k) {
    const double j = lerp(shape.cusp_j, g.limit_j_max, kPositions[k]);
    const double gain = aces2_focus_gain(j, shape.analytical_threshold, g);
    test.j_intersect_source[k] = aces2_solve_j_intersect(j, shape.cusp_m, shape.focus_j, g.limit_j_max, gain);
    test.slope[k] = aces2_compression_vector_slope(test.j_intersect_source[k], shape.focus_j, g.limit_j_max, gain);
    test.j_intersect_cusp[k] = aces2_solve_j_intersect(shape.cusp_j, shape.cusp_m, shape.focus_j, g.limit_j_max, gain);
  }
  return test;
}

bool boundary_outside_gamut(const GammaTest& test, double gamma_top_inv, const HellwigCam& limit, double peak_nits,
                            const Aces2GamutGeometry& g) {
  for (int k = 0; k < 5; ++k) {
    const double m = aces2_gamut_boundary_m(test.shape, g.limit_j_max, gamma_top_inv, g.lower_hull_gamma_inv,
                                            test.j_intersect_source[k], test.slope[k], test.j_intersect_cusp[k]);
    const double j = test.j_intersect_source[k] + test.slope[k] * m;
    if (!any_above(limit.jmh_to_rgb({j, m, test.hue}), peak_nits / 100.0)) return false;
  }
  return true;
}

double upper_hull_gamma(const GammaTest& test, const HellwigCam& limit, double peak_nits, const Aces2GamutGeometry& g) {
  constexpr double kStep = 0.4, kMaximum = 5.0, kAccuracy = 1e-5;
  double low = 0.0, high = kStep;
  while (high < kMaximum && !boundary_outside_gamut(test, 1.0 / high, limit, peak_nits, g)) {
    low = high;
    high += kStep;
  }
  while (high - low > kAccuracy) {
    const double mid = (high + low) / 2.0;
    if (boundary_outside_gamut(test, 1.0 / mid, limit, peak_nits, g)) high = mid;
    else low = mid;
  }
  return high;
}

}  // namespace

double Aces2ReachTable::at(double hue_degrees) const {
  const int base = std::min(int(hue_degrees), kAces2TableSize - 1);
  const double t = hue_degrees - base;
  return lerp(m[base + kFirst], m[base + kFirst + 1], t);
}

Aces2ReachTable make_aces2_reach_table(const HellwigCam& reach, double limit_j_max) {
  Aces2ReachTable table;
  for (int i = 0; i < kAces2TableSize; ++i) {
    const double hue = i * 360.0 / kAces2TableSize;
    constexpr double kStep = 50.0, kMaximum = 1300.0, kTolerance = 1e-2;
    double low = 0.0, high = kStep;
    while (high < kMaximum && !any_below_zero(reach.jmh_to_rgb({limit_j_max, high, hue}))) {
      low = high;
      high += kStep;
    }
    while (high - low > kTolerance) {
      const double mid = (high + low) / 2.0;
      if (any_below_zero(reach.jmh_to_rgb({limit_j_max, mid, hue}))) high = mid;
      else low = mid;
    }
    table.m[i + kFirst] = high;
  }
  table.m[0] = table.m[kLast];
  table.m[kUpperWrap] = table.m[kFirst];
  return table;
}

Aces2HueShape Aces2CuspTable::shape(double hue_degrees, const Aces2GamutGeometry& g) const {
  // Upper index of the interval containing the hue (hue[hi − 1] < h ≤ hue[hi]). The hues
  // are nearly one degree apart, so the search starts at the uniform table's position.
  int hi = std::clamp(int(hue_degrees) + kFirst, 1, kUpperWrap);
  while (hi < kUpperWrap && hue[hi] < hue_degrees) ++hi;
  while (hi > 1 && hue[hi - 1] >= hue_degrees) --hi;
  const double t = (hue_degrees - hue[hi - 1]) / (hue[hi] - hue[hi - 1]);
  return make_hue_shape(lerp(cusp_j[hi - 1], cusp_j[hi], t), lerp(cusp_m[hi - 1], cusp_m[hi], t),
                        lerp(gamma_top_inv[hi - 1], gamma_top_inv[hi], t), g);
}

Aces2CuspTable make_aces2_cusp_table(const HellwigCam& reach, const HellwigCam& limit, double peak_nits,
                                     double forward_limit, const Aces2GamutGeometry& g) {
  const CornerCycle reach_cycle = reach_corners(reach, g.limit_j_max, forward_limit);
  const CornerCycle limit_cycle = limiting_corners(limit, peak_nits);
  Aces2CuspTable table;
  table.hue = build_hue_table(merged_corner_hues(reach_cycle, limit_cycle));
  int previous_corner = 0;
  double previous_t = 0.0;
  for (int i = kFirst; i <= kLast; ++i) {
    const Vec2<double> jm = cusp_at_hue(table.hue[i], limit_cycle, limit, previous_corner, previous_t);
    table.cusp_j[i] = jm.x;
    table.cusp_m[i] = jm.y * kSmoothCuspM;
  }
  for (int i = kFirst; i <= kLast; ++i) {
    const Aces2HueShape shape = make_hue_shape(table.cusp_j[i], table.cusp_m[i], 1.0, g);
    table.gamma_top_inv[i] = 1.0 / upper_hull_gamma(make_gamma_test(shape, table.hue[i], g), limit, peak_nits, g);
  }
  for (Aces2Table* column : {&table.cusp_j, &table.cusp_m, &table.gamma_top_inv}) {
    (*column)[0] = (*column)[kLast];
    (*column)[kUpperWrap] = (*column)[kFirst];
  }
  return table;
}

}  // namespace prism::display
