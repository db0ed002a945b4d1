#include "app/compare_columns.h"

#include <algorithm>
#include <charconv>
#include <set>

#include "core/base/errors.h"
#include "core/base/names.h"
#include "core/scene/texture.h"
#include "core/vulkan/depth.h"

namespace shadelab {
namespace {

const char* const kKeys =
    "name, mode, tess, msaa, filter, env, bump, depth, shadows, shadow-size, lod";

// Parses one spec; `fail(what)` throws InputError "--column 'SPEC': WHAT".
class SpecReader {
 public:
  SpecReader(std::string spec, const FrameSettings& defaults) : spec_(std::move(spec)) {
    column_.spec = spec_;
    column_.settings = defaults;
  }

  CompareColumn read() {
    if (spec_.empty())
      fail("empty: expected a model or key=value pairs (" + std::string(kKeys) + ")");
    for (const std::string& item : splitFields(spec_)) {
      size_t equals = item.find('=');
      if (equals == std::string::npos) {
        // A bare word: the shading model (what --modes lists).
        if (!valueOf(kShadingModelNames, item))
          fail("'" + item + "' is neither a shading model (" +
               joinNames(namesOf(kShadingModelNames)) + ") nor key=value with a key of " + kKeys);
        set("mode", item);
      } else {
        set(item.substr(0, equals), item.substr(equals + 1));
      }
    }
    if (column_.name.empty()) column_.name = spec_;
    return column_;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("--column '" + spec_ + "': " + what);
  }
  void badValue(const std::string& key, const std::string& value,
                const std::string& expected) const {
    fail(key + " '" + value + "': expected " + expected);
  }
  template <typename E, size_t N>
  E named(const NameTable<E, N>& table, const std::string& key, const std::string& value) const {
    std::optional<E> parsed = valueOf(table, value);
    if (!parsed) badValue(key, value, "one of " + joinNames(namesOf(table)));
    return *parsed;
  }
  template <typename Number>
  std::optional<Number> number(const std::string& text) const {
    Number value{};
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
  }

  void set(const std::string& key, const std::string& value) {
    if (!seen_.insert(key).second)
      fail("key '" + key + "' given twice (a bare model name is mode=)");
    FrameSettings& settings = column_.settings;
    if (key == "name") {
      if (value.empty()) badValue(key, value, "a name for the sheet and --against");
      if (value == kReferenceColumnName)
        badValue(key, value, "a name other than 'reference' (the name of the reference)");
      column_.name = value;
    } else if (key == "mode") {
      settings.shadingModel = named(kShadingModelNames, key, value);
    } else if (key == "tess") {
      if (value == "auto") {
        column_.autoTessellation = true;
        return;
      }
      std::optional<float> factor = number<float>(value);
      if (!factor || !(*factor >= kMinTessellation && *factor <= kMaxTessellation))
        badValue(key, value, "a factor from 0.125 to 16, or auto");
      column_.tessellation = *factor;
    } else if (key == "msaa") {
      std::optional<uint32_t> samples = number<uint32_t>(value);
      if (!samples || (*samples != 1 && *samples != 4)) badValue(key, value, "1 or 4");
      settings.msaaSamples = *samples;
    } else if (key == "filter") {
      if (value == "material")
        settings.textures.filterOverride.reset();
      else if (!valueOf(kTextureFilterNames, value))
        badValue(key, value, "material or one of " + joinNames(namesOf(kTextureFilterNames)));
      else
        settings.textures.filterOverride = valueOf(kTextureFilterNames, value);
    } else if (key == "env") {
      settings.environment = named(kOnOffNames, key, value);
    } else if (key == "bump") {
      settings.textures.bump = named(kOnOffNames, key, value);
    } else if (key == "depth") {
      settings.depth = named(kDepthModeNames, key, value);
    } else if (key == "shadows") {
      settings.shadows = named(kShadowMethodNames, key, value);
    } else if (key == "shadow-size") {
      std::optional<uint32_t> size = number<uint32_t>(value);
      if (!size || *size < 1 || *size > 16384) badValue(key, value, "a map size from 1 to 16384");
      settings.shadowMapSize = *size;
    } else if (key == "lod") {
      settings.lod = value != "off";
      if (!settings.lod) return;
      std::optional<float> bound = number<float>(value);
      if (!bound || !(*bound >= 0.01f && *bound <= 100.0f))
        badValue(key, value, "off or an error bound in pixels from 0.01 to 100");
      settings.lodErrorPixels = *bound;
    } else {
      fail("unknown key '" + key + "': expected one of " + kKeys);
    }
  }

  std::string spec_;
  CompareColumn column_;
  std::set<std::string> seen_;
};

}  // namespace

std::vector<CompareColumn> modelColumns(const std::vector<ShadingModel>& models,
                                        const FrameSettings& defaults) {
  std::vector<CompareColumn> columns;
  for (ShadingModel model : models) {
    CompareColumn column{std::string(shadingModelName(model)), "", defaults};
    column.settings.shadingModel = model;
    columns.push_back(column);
  }
  return columns;
}

std::vector<CompareColumn> parseCompareColumns(const std::vector<std::string>& specs,
                                               const FrameSettings& defaults) {
  std::vector<CompareColumn> columns;
  for (const std::string& spec : specs) {
    CompareColumn column = SpecReader(spec, defaults).read();
    for (const CompareColumn& earlier : columns)
      if (earlier.name == column.name)
        throw InputError("--column '" + spec + "': the name '" + column.name +
                         "' is already a column's (of '" + earlier.spec +
                         "'): expected a name of its own (name=...)");
    columns.push_back(column);
  }
  return columns;
}

std::optional<size_t> findAgainstColumn(const std::vector<CompareColumn>& columns,
                                        const std::string& name) {
  if (name == kReferenceColumnName) return std::nullopt;
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i].name == name) return i;
  std::string names;
  for (const CompareColumn& column : columns)
    names += (names.empty() ? "'" : ", '") + column.name + "'";
  throw InputError("--against '" + name + "': expected reference or a column's name (" + names +
                   ")");
}

bool drawableAsOneSplitFrame(const std::vector<CompareColumn>& columns) {
  auto sameButModel = [&](const CompareColumn& column) {
    FrameSettings a = column.settings, b = columns.front().settings;
    a.shadingModel = b.shadingModel;
    return !column.tessellation && !column.autoTessellation && a.msaaSamples == b.msaaSamples &&
           a.textures.filterOverride == b.textures.filterOverride &&
           a.textures.bump == b.textures.bump && a.environment == b.environment &&
           a.depth == b.depth && a.shadows == b.shadows && a.shadowMapSize == b.shadowMapSize &&
           a.lod == b.lod && a.lodErrorPixels == b.lodErrorPixels;
  };
  return std::all_of(columns.begin(), columns.end(), sameButModel);
}

nlohmann::json columnSettingsJson(const CompareColumn& column) {
  const FrameSettings& settings = column.settings;
  nlohmann::json tess = column.autoTessellation
                            ? nlohmann::json("auto")
                            : nlohmann::json(column.tessellation.value_or(1.0f));
  return {{"mode", std::string(shadingModelName(settings.shadingModel))},
          {"tess", tess},
          {"msaa", settings.msaaSamples},
          {"depth", std::string(depthModeName(settings.depth))},
          {"filter", settings.textures.filterOverride
                         ? nlohmann::json(textureFilterName(*settings.textures.filterOverride))
                         : nlohmann::json("material")},
          {"environment", settings.environment},
          {"bump", settings.textures.bump},
          {"shadows", std::string(nameOf(kShadowMethodNames, settings.shadows))},
          {"shadow_map_size", settings.shadowMapSize},
          {"lod", settings.lod ? nlohmann::json(settings.lodErrorPixels) : nlohmann::json("off")}};
}

}  // namespace shadelab
