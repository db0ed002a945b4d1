#include "app/look_options.h"

#include <charconv>

#include "app/cli_common.h"
#include "core/base/errors.h"

namespace shadelab {

void addLookOptions(CLI::App* command, LookOptions& options) {
  command
      ->add_option("--env", options.environment,
                   namedHelp("Environment mapping (reflections, refraction, skybox) when the "
                             "scene has an environment",
                             kOnOffNames))
      ->capture_default_str();
  command->add_option("--filter", options.filter,
                      "Texture filter for every texture, overriding the materials' samplers: "
                      "nearest (base level, no mipmaps), bilinear (nearest mip level), "
                      "trilinear, aniso (trilinear + anisotropic; slow on llvmpipe)");
  command
      ->add_option("--bump", options.bump,
                   namedHelp("Bump mapping (normal and height maps; Phong and Blinn-Phong only)",
                             kOnOffNames))
      ->capture_default_str();
  command->add_flag("--mip-tint", options.mipTint,
                    "Debug view: tint diffuse textures by the mip level sampled (0 white, 1 red, "
                    "2 orange, 3 yellow, 4 green, 5 cyan, 6 blue, 7+ magenta)");
}

void applyLookOptions(const LookOptions& options, FrameSettings& settings) {
  settings.environment = parseNamed(kOnOffNames, options.environment, "--env");
  if (!options.filter.empty())
    settings.textures.filterOverride = parseNamed(kTextureFilterNames, options.filter, "--filter");
  settings.textures.bump = parseNamed(kOnOffNames, options.bump, "--bump");
  settings.textures.mipTint = options.mipTint;
}

float parseTessellationFactor(const std::string& text) {
  float factor = 0.0f;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), factor);
  if (error != std::errc() || end != text.data() + text.size() || !(factor >= 0.125f) ||
      !(factor <= 16.0f))
    throw InputError("--tess '" + text + "': expected a factor from 0.125 to 16, or auto");
  return factor;
}

}  // namespace shadelab
