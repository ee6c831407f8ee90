// The display thread of the viewer (display_worker.h). Every colour decision is made by
// prism::display; this file only picks which of its functions to call and packs bytes.
#include "prism/viewer/display_worker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "prism/core/error.h"
#include "prism/display/chromaticity_diagram.h"
#include "prism/display/exposure_metering.h"
#include "prism/display/luminance_view.h"
#include "prism/display/raster.h"
#include "prism/display/sdr_preview.h"

namespace prism::viewer {
namespace {

void to_rgba8(const EncodedImage& image, DisplayFrame& out) {
  out.width = image.width;
  out.height = image.height;
  out.rgba.assign(static_cast<std::size_t>(image.width) * image.height * 4, 255);
  const int shift = image.bit_depth - 8;
  for (std::size_t i = 0; i < static_cast<std::size_t>(image.width) * image.height; ++i)
    for (int c = 0; c < 3; ++c)
      out.rgba[4 * i + c] = static_cast<std::uint8_t>(image.samples[image.channels * i + c] >> shift);
}

// scRGB code values are linear and unbounded: the window shows them clipped to [0, 1], as
// an SDR monitor would show the signal (HDR presentation is not part of this viewer).
void float_codes_to_rgba8(const display::DisplayImage& image, DisplayFrame& out) {
  out.width = image.width;
  out.height = image.height;
  out.rgba.assign(static_cast<std::size_t>(image.width) * image.height * 4, 255);
  for (std::size_t i = 0; i < static_cast<std::size_t>(image.width) * image.height; ++i)
    for (int c = 0; c < 3; ++c)
      out.rgba[4 * i + c] = static_cast<std::uint8_t>(std::clamp(image.code[3 * i + c], 0.0f, 1.0f) * 255.0f + 0.5f);
}

void show(const display::DisplayImage& image, std::uint64_t seed, DisplayFrame& out) {
  if (display::is_float_encoding(image.encoding)) float_codes_to_rgba8(image, out);
  else to_rgba8(display::quantise_display_image(image, 8, seed), out);
}

// Below this the shown EV counts as having reached the metered one (0.7 % in light).
constexpr double kSettledEv = 0.01;

// Auto exposure: meter the film (the rule `prism render` uses, with the film's coverage) and
// adapt the shown EV toward it; the pipeline then gets that EV.
void resolve_exposure(const DisplayJob& job, display::DisplaySettings& s, DisplayFrame& out) {
  const DisplayControls& c = job.controls;
  if (c.auto_exposure) {
    display::MeteringSettings m = c.metering;
    m.key = c.auto_exposure_key;
    const ImageRgbF& film = job.film->film;
    const double metered =
        display::meter_exposure(film, job.film->film_space.rgb_to_xyz.row(1), job.film->coverage, m).ev100;
    const double ev = display::adapt_ev100(job.shown_ev100, metered, job.seconds_since_shown, c.adaptation_speed);
    out.metered_ev100 = metered;
    out.exposure_adapting = std::abs(ev - metered) > kSettledEv;
    s.auto_exposure = false;
    s.exposure_ev100 = out.exposure_adapting ? ev : metered;
  }
  out.ev100 = s.exposure_ev100.value_or(0.0);
}

// What an SDR window shows of an HDR target: the same settings on the SDR 100-nit target in
// Rec.709 with the sRGB curve (the rendering's own SDR picture), never PQ code values.
display::DisplaySettings sdr_preview_settings(display::DisplaySettings s) {
  s.odt = display::OdtId::srgb_100nit;
  s.encoding.reset();
  s.display_primaries.reset();
  s.overlay.reset();
  return s;
}

void fill_frame(const DisplayJob& job, DisplayFrame& out) {
  const ImageRgbF& film = job.film->film;
  const color::ColorSpace& space = job.film->film_space;
  display::DisplaySettings s = resolved_display_settings(job.controls);
  resolve_exposure(job, s, out);
  const bool hdr = hdr_output(job.controls);
  auto image = std::make_shared<display::DisplayImage>(display::apply_display_pipeline(film, space, s));
  out.content_light = content_light_level(image->nits);
  out.image = image;
  // An HDR target in this SDR window: show the SDR preview, say so, save the HDR image.
  std::shared_ptr<const display::DisplayImage> shown = image;
  if (hdr) {
    shown = std::make_shared<display::DisplayImage>(
        display::apply_display_pipeline(film, space, sdr_preview_settings(s)));
    out.preview_note = "SDR preview (srgb-100nit) of the HDR output " +
                       std::string(display::odt_description(s.odt).name) + "; saved images are HDR";
  }
  using display::DebugView;
  switch (job.controls.view) {
    case DebugView::none:
      show(*shown, s.dither_seed, out);
      return;
    case DebugView::gamut_clip: {
      display::DisplayImage marked = *image;
      display::mark_gamut_clip(marked);
      if (hdr) marked = display::transfer_marks(*image, marked, *shown);
      show(marked, s.dither_seed, out);
      return;
    }
    case DebugView::sdr_hdr_split:
      if (!hdr) throw UsageError("the SDR/HDR split view needs an HDR ODT");
      show(display::sdr_preview_of_display_light(
               display::sdr_hdr_split_view(film, space, s, job.controls.sdr_white_nits), job.controls.sdr_white_nits),
           s.dither_seed, out);
      return;
    case DebugView::bloom:
      show(display::bloom_only_view(film, space, s), s.dither_seed, out);
      return;
    case DebugView::luminance: {
      const std::vector<float> y = display::luminance_nits(film.rgb, space);
      to_rgba8(display::canvas_to_srgb8(display::luminance_false_colour_view(y, film.width, film.height,
                                                                             display::luminance_scale_for(y))), out);
      return;
    }
    case DebugView::luminance_display: {
      const std::vector<float> y = display::luminance_nits(image->nits, color::parse_color_space(image->primaries));
      to_rgba8(display::canvas_to_srgb8(display::luminance_false_colour_view(y, image->width, image->height,
                                                                             display::luminance_scale_for(y))), out);
      return;
    }
    case DebugView::chromaticity: {
      const color::ColorSpace shown =
          s.display_primaries ? *s.display_primaries : color::color_space(display::odt_description(s.odt).display_space);
      to_rgba8(display::canvas_to_srgb8(display::chromaticity_diagram(film, space, shown)), out);
      return;
    }
    case DebugView::normal: {
      if (!job.film->normals) throw UsageError("the normal view needs the film's shading-normal AOV");
      display::Canvas canvas(job.film->normals->width, job.film->normals->height, {0, 0, 0});
      canvas.image = display::normal_view(*job.film->normals);
      to_rgba8(display::canvas_to_srgb8(canvas), out);
      return;
    }
  }
}

}  // namespace

DisplayFrame compute_display_frame(const DisplayJob& job) {
  const auto start = std::chrono::steady_clock::now();
  DisplayFrame out;
  out.film_serial = job.film->serial;
  out.controls_version = job.controls_version;
  try {
    fill_frame(job, out);
  } catch (const std::exception& e) {
    out.error = e.what();
    if (out.rgba.empty() && out.image) show(*out.image, job.controls.settings.dither_seed, out);
  }
  out.display_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

DisplayWorker::DisplayWorker() : worker_([this] { run(); }) {}

DisplayWorker::~DisplayWorker() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

void DisplayWorker::submit(DisplayJob job) {
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(job);
  }
  wake_.notify_all();
}

std::shared_ptr<const DisplayFrame> DisplayWorker::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

bool DisplayWorker::busy() const {
  std::lock_guard lock(mutex_);
  return working_ || pending_.has_value();
}

void DisplayWorker::run() {
  for (;;) {
    DisplayJob job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || pending_.has_value(); });
      if (quit_) return;
      job = std::move(*pending_);
      pending_.reset();
      working_ = true;
    }
    // Eye adaptation continues from what the window last showed, over the time since.
    const auto now = std::chrono::steady_clock::now();
    if (latest_ && latest_->metered_ev100 && latest_time_) {
      job.shown_ev100 = latest_->ev100;
      job.seconds_since_shown = std::chrono::duration<double>(now - *latest_time_).count();
    }
    auto frame = std::make_shared<const DisplayFrame>(compute_display_frame(job));
    std::lock_guard lock(mutex_);
    latest_ = std::move(frame);
    latest_time_ = now;
    working_ = false;
  }
}

}  // namespace prism::viewer
