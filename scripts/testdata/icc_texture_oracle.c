/* Test data for scene/image_color_tags.h, made once with Little CMS 2 (Debian 12's
 * liblcms2-dev 2.14), an implementation independent of Prism's:
 *   ICC profiles of the kinds images embed, written by lcms2, and
 *   the linear Rec.709 (and ACEScg) values lcms2's relative-colorimetric transform gives
 *   for a row of 8-bit codes through each of them (the oracle the tests compare with).
 * The PNG and JPEG files around the profiles are written by scripts/testdata/icc_texture_images.py.
 *
 *   gcc -O1 -o /tmp/icc_oracle scripts/testdata/icc_texture_oracle.c -llcms2 -lm
 *   /tmp/icc_oracle tests/scene/loaders/data/   # writes the .icc files, prints the oracle
 */
#include <lcms2.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double codes[8][3] = {{255, 0, 0}, {0, 255, 0},     {0, 0, 255},  {200, 100, 50},
                                   {128, 128, 128}, {10, 20, 30}, {255, 255, 255}, {0, 0, 0}};

static double srgb_eotf(double v) { return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4); }

static cmsToneCurve* srgb_table(int entries) {
  cmsUInt16Number t[16384];
  for (int i = 0; i < entries; ++i) t[i] = (cmsUInt16Number)floor(srgb_eotf(i / (double)(entries - 1)) * 65535.0 + 0.5);
  return cmsBuildTabulatedToneCurve16(NULL, entries, t);
}

static cmsHPROFILE rgb_profile(cmsCIExyY white, cmsCIExyYTRIPLE primaries, cmsToneCurve* r, cmsToneCurve* g,
                               cmsToneCurve* b, double version, const char* description) {
  cmsToneCurve* curves[3] = {r, g, b};
  cmsHPROFILE p = cmsCreateRGBProfile(&white, &primaries, curves);
  cmsSetProfileVersion(p, version);
  cmsMLU* mlu = cmsMLUalloc(NULL, 1);
  cmsMLUsetASCII(mlu, "en", "US", description);
  cmsWriteTag(p, cmsSigProfileDescriptionTag, mlu);
  cmsMLUfree(mlu);
  return p;
}

static void save(cmsHPROFILE p, const char* folder, const char* name) {
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", folder, name);
  if (!cmsSaveProfileToFile(p, path)) fprintf(stderr, "cannot write %s\n", path);
}

static void oracle(const char* label, cmsHPROFILE in, cmsHPROFILE out) {
  cmsHTRANSFORM t = cmsCreateTransform(in, TYPE_RGB_DBL, out, TYPE_RGB_DBL, INTENT_RELATIVE_COLORIMETRIC,
                                       cmsFLAGS_NOOPTIMIZE | cmsFLAGS_NOCACHE);
  printf("%s\n", label);
  for (int i = 0; i < 8; ++i) {
    double rgb[3] = {codes[i][0] / 255.0, codes[i][1] / 255.0, codes[i][2] / 255.0}, o[3];
    cmsDoTransform(t, rgb, o, 1);
    printf("  {%.0f, %.0f, %.0f} -> {%.7f, %.7f, %.7f}\n", codes[i][0], codes[i][1], codes[i][2], o[0], o[1], o[2]);
  }
  cmsDeleteTransform(t);
}

int main(int argc, char** argv) {
  const char* folder = argc > 1 ? argv[1] : ".";
  cmsCIExyY d65 = {0.3127, 0.3290, 1.0}, aces_white = {0.32168, 0.33767, 1.0};
  cmsCIExyYTRIPLE rec709 = {{0.64, 0.33, 1.0}, {0.30, 0.60, 1.0}, {0.15, 0.06, 1.0}};
  cmsCIExyYTRIPLE p3 = {{0.680, 0.320, 1.0}, {0.265, 0.690, 1.0}, {0.150, 0.060, 1.0}};
  cmsCIExyYTRIPLE rec2020 = {{0.708, 0.292, 1.0}, {0.170, 0.797, 1.0}, {0.131, 0.046, 1.0}};
  cmsCIExyYTRIPLE ap1 = {{0.713, 0.293, 1.0}, {0.165, 0.830, 1.0}, {0.128, 0.044, 1.0}};
  cmsToneCurve* linear = cmsBuildGamma(NULL, 1.0);
  cmsToneCurve* gamma22 = cmsBuildGamma(NULL, 2.2);
  cmsToneCurve* gamma18 = cmsBuildGamma(NULL, 1.8);

  /* Display P3 with the sRGB curve as 1024-entry tables (curveType), a version 2 profile
   * (textDescriptionType 'desc'). */
  cmsToneCurve* table = srgb_table(1024);
  cmsHPROFILE p3_table = rgb_profile(d65, p3, table, table, table, 2.1, "Display P3 (lcms2, tables)");
  save(p3_table, folder, "display-p3-table-v2.icc");
  /* Rec.2020 primaries with a pure 2.2 power (curveType of one entry), version 4. */
  cmsHPROFILE rec2020_g22 = rgb_profile(d65, rec2020, gamma22, gamma22, gamma22, 4.3, "Rec.2020 gamma 2.2 (lcms2)");
  save(rec2020_g22, folder, "rec2020-gamma22-v4.icc");
  /* lcms2's own sRGB profile: Prism keeps such an image's codes. */
  cmsHPROFILE srgb = cmsCreate_sRGBProfile();
  save(srgb, folder, "srgb-lcms2.icc");
  /* A large P3 profile (three distinct 16384-entry tables, ~98 kB): a JPEG splits it over
   * two APP2 segments. */
  cmsToneCurve* big[3] = {srgb_table(16384), srgb_table(16384), srgb_table(16384)};
  cmsHPROFILE p3_big = rgb_profile(d65, p3, big[0], big[1], big[2], 4.3, "Display P3 (lcms2, large tables)");
  save(p3_big, folder, "display-p3-large.icc");
  /* Grey with a 1.8 power. */
  cmsHPROFILE gray = cmsCreateGrayProfile(cmsD50_xyY(), gamma18);
  save(gray, folder, "gray-gamma18.icc");

  cmsHPROFILE linear709 = rgb_profile(d65, rec709, linear, linear, linear, 4.3, "linear Rec.709");
  cmsHPROFILE linear_ap1 = rgb_profile(aces_white, ap1, linear, linear, linear, 4.3, "linear ACEScg");
  oracle("display-p3-table-v2.icc -> linear Rec.709", p3_table, linear709);
  oracle("display-p3-table-v2.icc -> linear ACEScg", p3_table, linear_ap1);
  oracle("rec2020-gamma22-v4.icc -> linear Rec.709", rec2020_g22, linear709);
  oracle("display-p3-large.icc -> linear Rec.709", p3_big, linear709);
  /* What a PNG's cHRM (Rec.2020) and gAMA (1/1.8) say, as a profile. */
  cmsHPROFILE rec2020_g18 = rgb_profile(d65, rec2020, gamma18, gamma18, gamma18, 4.3, "Rec.2020 gamma 1.8");
  oracle("Rec.2020 primaries, gamma 1.8 -> linear Rec.709", rec2020_g18, linear709);
  return 0;
}
