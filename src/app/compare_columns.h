#pragma once
// compare's columns: each a named setting of the rasteriser, written on the
// command line as comma-separated key=value pairs (the style of
// `docker --mount`), a bare word being the shading model:
//   --column phong                          model only; named "phong"
//   --column "phong,tess=1,msaa=1"          named after its spec as typed
//   --column "name=fine,gouraud,tess=4,msaa=4"
// Keys: name, mode, tess, msaa, filter, env, bump, depth, shadows,
// shadow-size. A key not given keeps the command's own setting (--shadows,
// --shadow-size) or render's default. `--modes a,b` is the simple case: one
// column per model, named after it.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "passes/renderer.h"

namespace shadelab {

struct CompareColumn {
  std::string name;  // the sheet's label, the JSON's, what --against names
  std::string spec;  // as typed ("" for a --modes column)
  // Model, MSAA, filter, env, bump, depth and shadows; width and height are the cell's.
  FrameSettings settings;
  std::optional<float> tessellation;  // none: the scene as loaded (render --tess 1)
  bool autoTessellation = false;      // tess=auto: as render --tess auto
};

// The name --against takes for the traced (or raster) reference.
inline constexpr const char* kReferenceColumnName = "reference";

// One column per model, named after it, with `defaults`' other settings.
std::vector<CompareColumn> modelColumns(const std::vector<ShadingModel>& models,
                                        const FrameSettings& defaults);

// The --column specs in order. Throws InputError naming the option, the spec,
// the key or value at fault and what is expected (unknown key, bad value, a
// key given twice, a name given twice or the reserved "reference").
std::vector<CompareColumn> parseCompareColumns(const std::vector<std::string>& specs,
                                               const FrameSettings& defaults);

// The column --against names, or none for "reference". Throws InputError
// listing the names it could be.
std::optional<size_t> findAgainstColumn(const std::vector<CompareColumn>& columns,
                                        const std::string& name);

// True when the columns differ in shading model alone (and keep the scene's
// tessellation): compare then draws them as one split frame, one camera.
bool drawableAsOneSplitFrame(const std::vector<CompareColumn>& columns);

// The column's settings for the JSON: mode, tess, msaa, depth, filter, env,
// bump, shadows, shadow_map_size.
nlohmann::json columnSettingsJson(const CompareColumn& column);

}  // namespace shadelab
