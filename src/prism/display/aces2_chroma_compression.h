#pragma once
// ACES 2.0 in-gamut chroma compression (ACES 2.0 "Output Transform technical details",
// "Chroma compression"; aces-core lib/Lib.Academy.OutputTransform.ctl chroma_compress_fwd):
// after the tonescale has moved J to J_ts, colourfulness M is rescaled by (J_ts/J)^(1/cz)
// to keep the chromaticity, normalised by a hue-dependent estimate of the rendering
// space's cusp M (a third-order Fourier series in h), expanded in the shadows and
// mid-tones by a reversed "toe" and compressed towards the highlights by a forward toe,
// both bounded by the reach gamut's M at J_ts.
namespace prism::display {

class Aces2ChromaCompression {
 public:
  explicit Aces2ChromaCompression(double peak_luminance_nits);

  // The Fourier-series normaliser of M at hue h (given as cos h, sin h).
  double normaliser(double cos_h, double sin_h) const;

  struct Context {
    double limit_j_max;   // J of the display peak
    double reach_max_m;   // reach (AP1) gamut's M at limit_j_max for this hue
    double normaliser;    // normaliser(cos h, sin h)
  };
  // M after the forward compression, for a colour (J, M) whose tonemapped lightness is j_ts.
  double forward(double J, double M, double j_ts, const Context& c) const;
  // The colourfulness before compression, given the compressed M, j_ts and the original J.
  double inverse(double J, double M_compressed, double j_ts, const Context& c) const;

 private:
  double saturation_, saturation_threshold_, compression_, scale_;
};

}  // namespace prism::display
