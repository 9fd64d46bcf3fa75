#include "driver/glx_config.h"

#include <X11/Xutil.h>

#include <algorithm>
#include <map>

#include "raster/multisample.h"
#include "state/accum.h"

namespace pineda::glx {
namespace {

struct Variant {
  bool double_buffered;
  int depth, stencil;
  int alpha;
  int samples;
};

// The single-sampled configs with 24-bit depth and 8-bit stencil or neither, the 4x
// multisampled ones (double-buffered only), then single-sampled depth without stencil (which
// programs that score configs, like glmark2, ask for), so that the first ids stay what they were.
std::vector<Variant> variants_for_depth(int depth) {
  std::vector<Variant> out;
  const auto add = [&](bool db, int depth_bits, int stencil_bits, int samples) {
    if (depth == 24) out.push_back({db, depth_bits, stencil_bits, 0, samples});
    out.push_back({db, depth_bits, stencil_bits, 8, samples});
  };
  for (int samples : {0, raster::kMaxSamples})
    for (bool db : {true, false})
      for (bool ds : {true, false}) {
        if (samples && !db) continue;
        add(db, ds ? 24 : 0, ds ? 8 : 0, samples);
      }
  for (bool db : {true, false}) add(db, 24, 0, 0);
  return out;
}

}  // namespace

// X's native 32-bit pixel layout is Pineda's BGRA8 in memory on a little-endian client.
std::vector<XVisualInfo> usable_visuals(Display* dpy, int screen, int depth) {
  XVisualInfo tmpl{};
  tmpl.screen = screen;
  tmpl.depth = depth;
  tmpl.c_class = TrueColor;
  int count = 0;
  XVisualInfo* infos =
      XGetVisualInfo(dpy, VisualScreenMask | VisualDepthMask | VisualClassMask, &tmpl, &count);
  std::vector<XVisualInfo> result;
  const VisualID default_id = XVisualIDFromVisual(DefaultVisual(dpy, screen));
  for (int i = 0; i < count; ++i) {
    const XVisualInfo& v = infos[i];
    if (v.red_mask != 0xff0000 || v.green_mask != 0xff00 || v.blue_mask != 0xff) continue;
    if (v.bits_per_rgb != 8) continue;
    result.push_back(v);
  }
  if (infos) XFree(infos);
  // The default visual first, so that it carries the best config.
  std::stable_sort(result.begin(), result.end(), [&](const XVisualInfo& a, const XVisualInfo& b) {
    if ((a.visualid == default_id) != (b.visualid == default_id)) return a.visualid == default_id;
    return a.visualid < b.visualid;
  });
  return result;
}

std::vector<std::unique_ptr<Config>> build_configs(Display* dpy) {
  std::vector<std::unique_ptr<Config>> configs;
  int next_id = 1;
  for (int screen = 0; screen < ScreenCount(dpy); ++screen) {
    std::unordered_set<VisualID> seen;
    for (int depth : {24, 32}) {
      std::vector<XVisualInfo> visuals = usable_visuals(dpy, screen, depth);
      if (visuals.empty()) continue;
      std::vector<Variant> variants = variants_for_depth(depth);
      // With enough visuals every config has its own; otherwise they share, and the first
      // config of a visual is the one the visual stands for.
      for (size_t i = 0; i < variants.size(); ++i) {
        const XVisualInfo& v = visuals[i % visuals.size()];
        auto c = std::make_unique<Config>();
        c->id = next_id++;
        c->screen = screen;
        c->visual_id = v.visualid;
        c->visual_depth = depth;
        c->alpha = variants[i].alpha;
        c->depth = variants[i].depth;
        c->stencil = variants[i].stencil;
        c->double_buffered = variants[i].double_buffered;
        c->samples = variants[i].samples;
        c->visual_canonical = seen.insert(v.visualid).second;
        configs.push_back(std::move(c));
      }
    }
  }
  return configs;
}

int config_attribute(const Config& c, int attribute, int* value) {
  switch (attribute) {
    case GLX_USE_GL: *value = True; break;
    case GLX_RGBA: *value = True; break;
    case GLX_FBCONFIG_ID: *value = c.id; break;
    case GLX_BUFFER_SIZE: *value = c.buffer_size(); break;
    case GLX_LEVEL: *value = 0; break;
    case GLX_DOUBLEBUFFER: *value = c.double_buffered; break;
    case GLX_STEREO: *value = False; break;
    case GLX_AUX_BUFFERS: *value = 0; break;
    case GLX_RED_SIZE: *value = c.red; break;
    case GLX_GREEN_SIZE: *value = c.green; break;
    case GLX_BLUE_SIZE: *value = c.blue; break;
    case GLX_ALPHA_SIZE: *value = c.alpha; break;
    case GLX_DEPTH_SIZE: *value = c.depth; break;
    case GLX_STENCIL_SIZE: *value = c.stencil; break;
    case GLX_ACCUM_RED_SIZE: case GLX_ACCUM_GREEN_SIZE: case GLX_ACCUM_BLUE_SIZE:
    case GLX_ACCUM_ALPHA_SIZE: *value = kAccumBits; break;  // every context has one (state/accum.h)
    case GLX_RENDER_TYPE: *value = GLX_RGBA_BIT; break;
    case GLX_DRAWABLE_TYPE: *value = GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT; break;
    case GLX_X_RENDERABLE: *value = True; break;
    case GLX_VISUAL_ID: *value = static_cast<int>(c.visual_id); break;
    case GLX_X_VISUAL_TYPE: *value = GLX_TRUE_COLOR; break;
    case GLX_CONFIG_CAVEAT: *value = GLX_NONE; break;
    case GLX_TRANSPARENT_TYPE: *value = GLX_NONE; break;
    case GLX_TRANSPARENT_INDEX_VALUE: case GLX_TRANSPARENT_RED_VALUE:
    case GLX_TRANSPARENT_GREEN_VALUE: case GLX_TRANSPARENT_BLUE_VALUE:
    case GLX_TRANSPARENT_ALPHA_VALUE: *value = 0; break;
    case GLX_MAX_PBUFFER_WIDTH: case GLX_MAX_PBUFFER_HEIGHT: *value = kMaxDrawableSize; break;
    case GLX_MAX_PBUFFER_PIXELS: *value = kMaxDrawableSize * kMaxDrawableSize; break;
    case GLX_SAMPLE_BUFFERS: *value = c.samples > 0; break;
    case GLX_SAMPLES: *value = c.samples; break;
    case GLX_SCREEN: *value = c.screen; break;
    default: return GLX_BAD_ATTRIBUTE;
  }
  return Success;
}

namespace {

enum class Rule { Exact, Minimum, Mask, Ignore };

constexpr int kDontCare = static_cast<int>(GLX_DONT_CARE);

struct Criterion {
  int attribute;
  int default_value;
  Rule rule;
};

// GLX 1.4 table 3.4: defaults and matching rules of glXChooseFBConfig.
constexpr Criterion kFBConfigCriteria[] = {
    {GLX_FBCONFIG_ID, kDontCare, Rule::Exact},
    {GLX_BUFFER_SIZE, 0, Rule::Minimum},
    {GLX_LEVEL, 0, Rule::Exact},
    {GLX_DOUBLEBUFFER, kDontCare, Rule::Exact},
    {GLX_STEREO, False, Rule::Exact},
    {GLX_AUX_BUFFERS, 0, Rule::Minimum},
    {GLX_RED_SIZE, 0, Rule::Minimum},
    {GLX_GREEN_SIZE, 0, Rule::Minimum},
    {GLX_BLUE_SIZE, 0, Rule::Minimum},
    {GLX_ALPHA_SIZE, 0, Rule::Minimum},
    {GLX_DEPTH_SIZE, 0, Rule::Minimum},
    {GLX_STENCIL_SIZE, 0, Rule::Minimum},
    {GLX_ACCUM_RED_SIZE, 0, Rule::Minimum},
    {GLX_ACCUM_GREEN_SIZE, 0, Rule::Minimum},
    {GLX_ACCUM_BLUE_SIZE, 0, Rule::Minimum},
    {GLX_ACCUM_ALPHA_SIZE, 0, Rule::Minimum},
    {GLX_SAMPLE_BUFFERS, 0, Rule::Minimum},
    {GLX_SAMPLES, 0, Rule::Minimum},
    {GLX_RENDER_TYPE, GLX_RGBA_BIT, Rule::Mask},
    {GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, Rule::Mask},
    {GLX_X_RENDERABLE, kDontCare, Rule::Exact},
    {GLX_X_VISUAL_TYPE, kDontCare, Rule::Exact},
    {GLX_CONFIG_CAVEAT, kDontCare, Rule::Exact},
    {GLX_TRANSPARENT_TYPE, GLX_NONE, Rule::Exact},
    {GLX_TRANSPARENT_INDEX_VALUE, kDontCare, Rule::Exact},
    {GLX_TRANSPARENT_RED_VALUE, kDontCare, Rule::Exact},
    {GLX_TRANSPARENT_GREEN_VALUE, kDontCare, Rule::Exact},
    {GLX_TRANSPARENT_BLUE_VALUE, kDontCare, Rule::Exact},
    {GLX_TRANSPARENT_ALPHA_VALUE, kDontCare, Rule::Exact},
    {GLX_VISUAL_ID, kDontCare, Rule::Exact},
    {GLX_MAX_PBUFFER_WIDTH, 0, Rule::Ignore},
    {GLX_MAX_PBUFFER_HEIGHT, 0, Rule::Ignore},
    {GLX_MAX_PBUFFER_PIXELS, 0, Rule::Ignore},
};

const Criterion* find_criterion(int attribute) {
  for (const Criterion& c : kFBConfigCriteria)
    if (c.attribute == attribute) return &c;
  return nullptr;
}

using Request = std::map<int, int>;

bool matches(const Config& c, const Request& request) {
  for (const Criterion& criterion : kFBConfigCriteria) {
    const int wanted = request.at(criterion.attribute);
    if (wanted == kDontCare || criterion.rule == Rule::Ignore) continue;
    int have = 0;
    config_attribute(c, criterion.attribute, &have);
    switch (criterion.rule) {
      case Rule::Exact: if (have != wanted) return false; break;
      case Rule::Minimum: if (have < wanted) return false; break;
      case Rule::Mask: if ((have & wanted) != wanted) return false; break;
      case Rule::Ignore: break;
    }
  }
  return true;
}

// The colour bits the sort counts: only of the components the request asks for.
int requested_color_bits(const Config& c, const Request& r) {
  auto counts = [&](int attribute) {
    const int wanted = r.at(attribute);
    return wanted != 0 && wanted != kDontCare;
  };
  return (counts(GLX_RED_SIZE) ? c.red : 0) + (counts(GLX_GREEN_SIZE) ? c.green : 0) +
         (counts(GLX_BLUE_SIZE) ? c.blue : 0) + (counts(GLX_ALPHA_SIZE) ? c.alpha : 0);
}

// GLX 1.4 section 3.3.3's sort (caveats, accumulation and visual type are the same for every
// Pineda config): true when `a` comes before `b`. Fewer samples first.
bool fbconfig_before(const Config& a, const Config& b, const Request& r) {
  const int color_a = requested_color_bits(a, r), color_b = requested_color_bits(b, r);
  if (color_a != color_b) return color_a > color_b;
  if (a.buffer_size() != b.buffer_size()) return a.buffer_size() < b.buffer_size();
  if (a.double_buffered != b.double_buffered) return !a.double_buffered;
  if (a.samples != b.samples) return a.samples < b.samples;
  if (a.depth != b.depth) return a.depth > b.depth;
  if (a.stencil != b.stencil) return a.stencil < b.stencil;
  return a.id < b.id;
}

}  // namespace

bool choose_fbconfigs(const DisplayState& d, int screen, const int* attribs,
                      std::vector<const Config*>* out) {
  out->clear();
  Request request;
  for (const Criterion& c : kFBConfigCriteria) request[c.attribute] = c.default_value;
  for (const int* a = attribs; a && a[0] != None; a += 2) {
    if (!find_criterion(a[0])) return false;
    request[a[0]] = a[1];
  }
  const int wanted_id = request[GLX_FBCONFIG_ID];
  for (const auto& c : d.configs) {
    if (c->screen != screen) continue;
    // A config id, when given, decides alone.
    if (wanted_id != kDontCare ? c->id == wanted_id : matches(*c, request))
      out->push_back(c.get());
  }
  std::stable_sort(out->begin(), out->end(), [&](const Config* a, const Config* b) {
    return fbconfig_before(*a, *b, request);
  });
  return true;
}

const Config* choose_visual_config(const DisplayState& d, int screen, const int* attribs) {
  bool rgba = false, double_buffered = false, stereo = false;
  int level = 0, buffer_size = 0, aux = 0, red = 0, green = 0, blue = 0, alpha = 0;
  int depth = 0, stencil = 0, accum = 0, sample_buffers = 0, samples = 0;
  for (const int* a = attribs; a && a[0] != None; ++a) {
    switch (a[0]) {
      case GLX_USE_GL: break;
      case GLX_RGBA: rgba = true; break;
      case GLX_DOUBLEBUFFER: double_buffered = true; break;
      case GLX_STEREO: stereo = true; break;
      case GLX_BUFFER_SIZE: buffer_size = *++a; break;
      case GLX_LEVEL: level = *++a; break;
      case GLX_AUX_BUFFERS: aux = *++a; break;
      case GLX_RED_SIZE: red = *++a; break;
      case GLX_GREEN_SIZE: green = *++a; break;
      case GLX_BLUE_SIZE: blue = *++a; break;
      case GLX_ALPHA_SIZE: alpha = *++a; break;
      case GLX_DEPTH_SIZE: depth = *++a; break;
      case GLX_STENCIL_SIZE: stencil = *++a; break;
      case GLX_ACCUM_RED_SIZE: case GLX_ACCUM_GREEN_SIZE: case GLX_ACCUM_BLUE_SIZE:
      case GLX_ACCUM_ALPHA_SIZE: accum = std::max(accum, *++a); break;
      // GLX 1.3 attributes that take a value are accepted and matched where meaningful.
      case GLX_SAMPLE_BUFFERS: sample_buffers = *++a; break;
      case GLX_SAMPLES: samples = *++a; break;
      case GLX_X_VISUAL_TYPE:
        if (*++a != GLX_TRUE_COLOR && *a != kDontCare) return nullptr;
        break;
      case GLX_CONFIG_CAVEAT: case GLX_TRANSPARENT_TYPE: case GLX_VISUAL_ID: ++a; break;
      default: return nullptr;
    }
  }
  // There are no colour-index, stereo, overlay or auxiliary buffers; accumulation buffers
  // have 16 bits per channel.
  if (!rgba || stereo || level != 0 || aux > 0 || accum > kAccumBits) return nullptr;
  std::vector<const Config*> candidates;
  for (const auto& c : d.configs) {
    if (c->screen != screen || !c->visual_canonical) continue;
    // Without GLX_DOUBLEBUFFER only single-buffered visuals are considered.
    if (c->double_buffered != double_buffered) continue;
    if (c->buffer_size() < buffer_size || c->red < red || c->green < green || c->blue < blue ||
        c->alpha < alpha || c->depth < depth || c->stencil < stencil ||
        (c->samples > 0 ? 1 : 0) < sample_buffers || c->samples < samples)
      continue;
    candidates.push_back(c.get());
  }
  // Fewer samples first (GLX_SAMPLES is a minimum). A size of zero prefers the smallest buffer;
  // a positive size the largest (colour, depth); stencil always prefers the smallest.
  auto before = [&](const Config* a, const Config* b) {
    auto prefer = [](int wanted, int x, int y) { return wanted > 0 ? x > y : x < y; };
    if (a->samples != b->samples) return a->samples < b->samples;
    if (a->alpha != b->alpha) return prefer(alpha, a->alpha, b->alpha);
    if (a->depth != b->depth) return prefer(depth, a->depth, b->depth);
    if (a->stencil != b->stencil) return a->stencil < b->stencil;
    return a->id < b->id;
  };
  auto best = std::min_element(candidates.begin(), candidates.end(), before);
  return best == candidates.end() ? nullptr : *best;
}

const Config* config_of_visual(const DisplayState& d, VisualID id) {
  for (const auto& c : d.configs)
    if (c->visual_id == id && c->visual_canonical) return c.get();
  return nullptr;
}

}  // namespace pineda::glx
