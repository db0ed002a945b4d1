#pragma once
// Options that change how a frame looks beyond the shading model, shared by
// every command that draws with the rasteriser (render, view): --env,
// --filter, --bump, --mip-tint. The viewer's E, F, B and M keys change the
// same FrameSettings fields afterwards.
#include <CLI/CLI.hpp>
#include <string>

#include "passes/renderer.h"

namespace shadelab {

struct LookOptions {
  std::string environment = "on";
  std::string filter;  // empty: each material's own sampler
  std::string bump = "on";
  bool mipTint = false;
};

void addLookOptions(CLI::App* command, LookOptions& options);
// Throws InputError naming the option and the values it accepts.
void applyLookOptions(const LookOptions& options, FrameSettings& settings);

// --tess: "0.125".."16"; throws InputError naming the option otherwise.
float parseTessellationFactor(const std::string& text);

}  // namespace shadelab
