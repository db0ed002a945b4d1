#include "app/look_options.h"

#include <charconv>
#include <sstream>

#include "app/cli_common.h"
#include "core/base/errors.h"

namespace shadelab {

void ShadowOptions::add(CLI::App* command) {
  command
      ->add_option("--shadows", method,
                   namedHelp("Shadow maps and their filter (off: no shadows)", kShadowMethodNames))
      ->capture_default_str();
  command->add_option("--shadow-size", size, "Shadow map size in texels (square)")
      ->capture_default_str();
  command
      ->add_option("--shadow-bias", bias,
                   "Constant shadow bias towards the light, in shadow-map texels (0..64)")
      ->capture_default_str();
  command
      ->add_option("--shadow-slope-bias", slopeBias,
                   "Slope-scaled shadow bias: texels times tan(angle of N and L) (0..64)")
      ->capture_default_str();
  command
      ->add_option("--shadow-normal-offset", normalOffset,
                   "Normal-offset shadow bias: texels along the normal times sin(angle) (0..64)")
      ->capture_default_str();
  command
      ->add_option("--shadow-cache", keep,
                   namedHelp("Keep a shadow map while its light, its view and the casters are "
                             "unchanged (off: redraw every map every frame, to time them)",
                             kOnOffNames))
      ->capture_default_str();
}

void ShadowOptions::apply(FrameSettings& settings) const {
  settings.shadows = parseNamed(kShadowMethodNames, method, "--shadows");
  if (size < 1 || size > int64_t(kMaxShadowMapSize))
    throw InputError("--shadow-size " + std::to_string(size) +
                     ": expected a map size from 1 to the device's largest 2D image (16384 "
                     "on lavapipe)");
  settings.shadowMapSize = uint32_t(size);
  for (auto [option, value] :
       {std::pair{"--shadow-bias", bias}, std::pair{"--shadow-slope-bias", slopeBias},
        std::pair{"--shadow-normal-offset", normalOffset}})
    if (!(value >= 0.0f && value <= kMaxShadowBias)) {
      std::ostringstream text;
      text << option << " " << value << ": expected 0 to " << kMaxShadowBias << " texels";
      throw InputError(text.str());
    }
  settings.shadowBias = {bias, slopeBias, normalOffset};
  settings.keepShadowMaps = parseNamed(kOnOffNames, keep, "--shadow-cache");
}

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
  command
      ->add_option("--constants,--material-constants", options.materialConstants,
                   "Compile each material into its own pipelines when the scene has at most 16, "
                   "and for `render` with a fixed camera the lights too: faster frames, ~9 ms "
                   "more start-up per material (off: read from memory; auto: on unless the "
                   "command draws a single frame)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "on", "off"}));
  options.shadows.add(command);
  command
      ->add_option("--lod", options.lod,
                   "Levels of detail chosen every frame: each loaded mesh drawn at the coarsest "
                   "of its simplified levels whose error stays within --lod-error (auto), or in "
                   "full (off)")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "off"}));
  command
      ->add_option("--lod-error", options.lodError,
                   "Screen-space error bound of --lod auto, in pixels")
      ->capture_default_str()
      ->check(finiteRange(0.01, 100.0));
  command
      ->add_option("--instancing", options.instancing,
                   "The visible copies of an \"instances\" block drawn as one instanced draw per "
                   "level of detail (on), or one draw each (off: the same image)")
      ->capture_default_str()
      ->check(CLI::IsMember({"on", "off"}));
  command
      ->add_option("--billboard-outline", options.billboardOutline,
                   "Cut-out and blended billboards drawn as one triangle around what their "
                   "texture can show at the mip levels they sample (trimmed; single-sampled, "
                   "not anisotropic), or as whole quads (quad: the same image)")
      ->capture_default_str()
      ->check(CLI::IsMember({"trimmed", "quad"}));
  command
      ->add_option("--draw-order", options.drawOrder,
                   "Opaque objects drawn nearest first, so the depth test spares the fragments "
                   "they hide (sorted), or in the scene's order (scene: where two surfaces' "
                   "depths tie, the one drawn first wins, the last with --depth reversed; "
                   "`render zfight --depth d16 --draw-order scene` shows z-fighting)")
      ->capture_default_str()
      ->check(CLI::IsMember({"sorted", "scene"}));
  command
      ->add_option("--impostors", options.impostors,
                   "With --lod auto, each opaque untextured mesh's chain ends in an impostor: a "
                   "quad showing the mesh as captured from the nearest of 16x16 directions "
                   "(on), from the three around the view direction blended (blend: no seams "
                   "between cells, three times the texture lookups), or in its coarsest mesh "
                   "(off)")
      ->capture_default_str()
      ->check(CLI::IsMember({"on", "blend", "off"}));
}

void applyLookOptions(const LookOptions& options, FrameSettings& settings) {
  settings.environment = parseNamed(kOnOffNames, options.environment, "--env");
  if (!options.filter.empty())
    settings.textures.filterOverride = parseNamed(kTextureFilterNames, options.filter, "--filter");
  settings.textures.bump = parseNamed(kOnOffNames, options.bump, "--bump");
  settings.textures.mipTint = options.mipTint;
  settings.materialConstants = options.materialConstants != "off";  // auto: see the header
  options.shadows.apply(settings);
  settings.lod = options.lod == "auto";
  settings.lodErrorPixels = options.lodError;
  settings.instancing = options.instancing == "on";
  settings.impostorCells = options.impostors != "off" ? kImpostorCells : 0;
  settings.impostorBlend = options.impostors == "blend";
  settings.trimBillboards = options.billboardOutline == "trimmed";
  settings.frontToBack = options.drawOrder == "sorted";
}

float parseTessellationFactor(const std::string& text) {
  float factor = 0.0f;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), factor);
  if (error != std::errc() || end != text.data() + text.size() || !(factor >= kMinTessellation) ||
      !(factor <= kMaxTessellation))
    throw InputError("--tess '" + text + "': expected a factor from 0.125 to 16, or auto");
  return factor;
}

}  // namespace shadelab
