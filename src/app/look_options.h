#pragma once
// Options that change how a frame looks beyond the shading model, shared by
// every command that draws with the rasteriser (render, view): --env,
// --filter, --bump, --mip-tint, the shadow options. The viewer's E, F, B and M keys change the
// same FrameSettings fields afterwards.
#include <CLI/CLI.hpp>
#include <string>

#include "core/scene/shadows.h"
#include "passes/renderer.h"

namespace shadelab {

// --shadows, --shadow-size and the bias options, as render, compare and view
// take them; apply() validates what the device does not (the device's
// limits are checked by Renderer::applyFrameSettings).
struct ShadowOptions {
  std::string method{nameOf(kShadowMethodNames, kDefaultShadowMethod)};
  int64_t size = kDefaultShadowMapSize;
  float bias = ShadowBias{}.constant;
  float slopeBias = ShadowBias{}.slope;
  float normalOffset = ShadowBias{}.normalOffset;
  std::string keep = "on";  // --shadow-cache
  void add(CLI::App* command);
  void apply(FrameSettings& settings) const;  // throws InputError naming the option
};

struct LookOptions {
  std::string environment = "on";
  std::string filter;  // empty: each material's own sampler
  std::string bump = "on";
  bool mipTint = false;
  // --constants (alias --material-constants): on, off or auto, which applyLookOptions takes as on
  // and a command that draws one frame only as off (`render`: its 8-bit
  // images are the same either way, linear ones within a half-float step,
  // and a pipeline per material costs more start-up than one frame saves).
  std::string materialConstants = "auto";
  ShadowOptions shadows;                     // --shadows, --shadow-size, the bias options
  std::string lod = "off";                   // --lod auto|off (view sets "auto" before adding)
  float lodError = 0.5f;                     // --lod-error, pixels
  std::string instancing = "on";             // --instancing on|off
  std::string impostors = "on";              // --impostors on|blend|off
  std::string billboardOutline = "trimmed";  // --billboard-outline trimmed|quad
  std::string drawOrder = "sorted";          // --draw-order sorted|scene
};

void addLookOptions(CLI::App* command, LookOptions& options);
// Throws InputError naming the option and the values it accepts.
void applyLookOptions(const LookOptions& options, FrameSettings& settings);

// --tess: "0.125".."16"; throws InputError naming the option otherwise.
float parseTessellationFactor(const std::string& text);

}  // namespace shadelab
