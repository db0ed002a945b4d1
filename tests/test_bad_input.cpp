// The bad-input battery: one table of what a user (or an attacker) can hand
// the shadelab binary, across options, scene JSON, images, panoramas, glTF
// and output paths. Each row states the exit code and how the first line of
// the output begins; every row also checks that no file was left behind (no
// output, no temporary, no folder). Rows run in one suite per group, so ctest
// spreads them over the cores; most fail before a Vulkan device is opened.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "run_command.h"

namespace {
namespace fs = std::filesystem;
using shadelab::test::CommandResult;
using shadelab::test::run;

enum class Group { Options, Json, Images, Gltf, Outputs };

// A file the case needs in its folder. `text` starting with "@" is special:
// "@fifo" a FIFO with no writer, "@folder" a folder, "@link:TARGET" a
// symbolic link, "@copy:PATH" a copy of PATH (relative to tests/data).
struct Setup {
  const char* name;
  std::string text;
};

struct BadCase {
  Group group;
  const char* name;
  std::vector<Setup> files;
  std::string arguments;  // {dir}: the case's folder, {data}: tests/data
  int exitCode;
  std::string firstLine;         // how the output's first line begins ({dir}, {data} as above)
  std::string environment = "";  // prefixed to the command (e.g. a file size limit)
};

const std::string kError = "shadelab: error: ";
// 16 blocks of 512 (dash) or 1024 (bash) bytes: an 8 KiB (16 KiB) file
// size limit, 0: none at all; SIGXFSZ ignored so that write() fails with EFBIG instead of
// the process being killed, as on a full disk.
const std::string kSmallDisk = "ulimit -f 16; trap '' XFSZ;";
const std::string kNoDisk = "ulimit -f 0; trap '' XFSZ;";
// Enough ".." to climb from any test folder to the root.
const std::string kClimb = "../../../../../../../../../../../../../../";

// A scene JSON with one textured plane whose diffuse map is `file`.
std::string texturedScene(const std::string& file) {
  return R"({"materials": {"m": {"diffuse_map": ")" + file +
         R"("}}, "objects": [{"shape": "plane", "material": "m"}]})";
}
std::string panoramaScene(const std::string& file) {
  return R"({"environment": {"type": "equirect", "file": ")" + file + R"("}, "objects": []})";
}
// A glTF whose only buffer is `uri` (a triangle's worth of bytes expected).
std::string gltfWithBuffer(const std::string& uri) {
  return R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" + uri +
         R"(", "byteLength": 36}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
}
// A PNG header (signature, IHDR, IEND; no pixels) that declares 16384x16384
// RGBA texels: 45 bytes that would decode to 1 GiB.
const std::string kHugePngBase64 = "iVBORw0KGgoAAAANSUhEUgAAQAAAAEAACAYAAACpyBCEAAAAAElFTkSuQmCC";
// A triangle whose buffer is a data URI: the 36 bytes of its positions,
// then the 45 of kHugePngBase64 (views 0 and 1), plus `images`.
std::string gltfWithImages(const std::string& images) {
  return R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 81, "uri":
  "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA)" +
         kHugePngBase64 + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 45},
                  {"buffer": 0, "byteOffset": 40, "byteLength": 4000000}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "images": )" +
         images + R"(,
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})";
}
// A valid triangle (positions in a data URI) but for its node, its
// material, its asset version and `extra` members at the top (each ending in a comma).
std::string triangleGltf(const std::string& node, const std::string& material = "{}",
                         const std::string& version = "2.0", const std::string& extra = "") {
  return R"({)" + extra + R"("asset": {"version": ")" + version +
         R"("}, "buffers": [{"byteLength": 36, "uri":
  "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
  "materials": [)" +
         material + R"(], "nodes": [)" + node + R"(], "scenes": [{"nodes": [0]}]})";
}
// `text` with its first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}
std::string nested(const std::string& open, const std::string& close, int depth) {
  std::string text;
  for (int i = 0; i < depth; ++i) text += open;
  for (int i = 0; i < depth; ++i) text += close;
  return text;
}

const std::vector<BadCase>& badCases() {
  const std::string render = "render -o {dir}/out.png ";
  const std::string plane1024 = R"({"objects": [{"shape": "plane", "tessellation": 1024}]})";
  static const std::vector<BadCase> cases = {
      // Options: values out of range or of the wrong kind.
      {Group::Options, "size zero", {}, render + "--size 0x10", 2, kError + "--size '0x10'"},
      {Group::Options, "size not WxH", {}, render + "--size big", 2, kError + "--size 'big'"},
      {Group::Options,
       "size too large",
       {},
       render + "--size 65536x65536",
       2,
       kError + "--size '65536x65536': width and height must be 1..16384"},
      {Group::Options, "unknown mode", {}, render + "--mode toon", 2, kError + "--mode 'toon'"},
      {Group::Options, "tess zero", {}, render + "--tess 0", 2, kError + "--tess '0'"},
      {Group::Options, "tess above 16", {}, render + "--tess 17", 2, kError + "--tess '17'"},
      {Group::Options,
       "tess not a number",
       {},
       render + "--tess lots",
       2,
       kError + "--tess 'lots'"},
      {Group::Options,
       "tess 16 on a plane of 1024",
       {{"plane.json", plane1024}},
       render + "{dir}/plane.json --tess 16",
       2,
       kError + "scene 'plane' at --tess 16: an estimated"},
      {Group::Options,
       "40 large spheres",
       {{"spheres.json",
         [] {
           std::string objects;
           for (int i = 0; i < 40; ++i)  // one mesh of 1 M triangles, drawn 40 times
             objects += std::string(i ? "," : "") + R"({"shape": "sphere", "tessellation": 1024})";
           return R"({"objects": [)" + objects + "]}";
         }()}},
       render + "{dir}/spheres.json",
       2,
       kError + "scene 'spheres' at its own tessellation (before building): an estimated "
                "41861120 triangles"},
      {Group::Options,
       "64 distinct planes of tessellation 1024",
       {{"planes.json",
         [] {
           // 64 different meshes of 2 M triangles each: 134 M triangles,
           // gigabytes and minutes if built before the budget is checked.
           std::string objects;
           for (int i = 0; i < 64; ++i)
             objects += std::string(i ? "," : "") + R"({"shape": "plane", "tessellation": 1024, )" +
                        R"("size": )" + std::to_string(i + 1) + "}";
           return R"({"objects": [)" + objects + "]}";
         }()}},
       render + "{dir}/planes.json",
       2,
       kError + "scene 'planes' at its own tessellation (before building): an estimated "
                "134217728 triangles drawn ("},
      {Group::Options,
       "compare tess=auto column over the budget",
       {{"ball.json", R"({"objects": [{"shape": "sphere", "tessellation": 4}]})"}},
       "compare {dir}/ball.json -o {dir}/s.png --size 320x180 --column phong,tess=auto "
       "--column flat --max-triangles 200",
       2,
       kError + "scene 'ball' at compare (a tess=auto column, for its view): an estimated 440 "
                "triangles"},
      {Group::Options,
       "max-triangles zero",
       {},
       render + "--max-triangles 0",
       2,
       "shadelab: error: --max-triangles: Value 0 not in range"},
      {Group::Options,
       "budget below the default scene",
       {},
       render + "--max-triangles 10",
       2,
       kError + "scene 'default' at --tess 1: an estimated"},
      {Group::Options,
       "quality negative",
       {},
       render + "--quality -1",
       2,
       kError + "--quality -1: no image can meet it, expected a mean FLIP"},
      {Group::Options,
       "quality ssim above 1",
       {},
       render + "--quality 2 --metric ssim",
       2,
       kError + "--quality 2: no image can meet it, expected a SSIM"},
      {Group::Options,
       "quality unknown metric",
       {},
       render + "--quality 0.1 --metric l1",
       2,
       kError + "--metric 'l1'"},
      {Group::Options, "unknown depth", {}, render + "--depth d12", 2, kError + "--depth 'd12'"},
      {Group::Options, "msaa 3", {}, render + "--msaa 3", 2, "shadelab: error: --msaa: "},
      {Group::Options,
       "lod neither auto nor off",
       {},
       render + "--lod sometimes",
       2,
       "shadelab: error: --lod: sometimes not in {auto,off}"},
      {Group::Options,
       "lod error of zero pixels",
       {},
       render + "--lod-error 0",
       2,
       "shadelab: error: --lod-error: Value 0 not in range"},
      // NaN compares false with both ends of a range: CLI::Range lets it through.
      {Group::Options,
       "lod error not a number",
       {},
       render + "--lod-error nan",
       2,
       "shadelab: error: --lod-error: Value nan not in range"},
      {Group::Options,
       "tessellation error not a number",
       {},
       render + "--tess auto --tess-error nan",
       2,
       "shadelab: error: --tess-error: Value nan not in range"},
      {Group::Options,
       "simplify infinite",
       {},
       render + "--simplify inf",
       2,
       "shadelab: error: --simplify: Value inf not in range"},
      {Group::Options,
       "bench tessellation not a number",
       {},
       "bench -o {dir}/b --tess nan",
       2,
       kError + "--tess 'nan': expected tessellation factors from 0.125 to 16"},
      {Group::Options,
       "bench tessellation list with an empty entry",
       {},
       "bench -o {dir}/b --tess ,1",
       2,
       kError + "--tess ',1': entry 1 is empty"},
      {Group::Options,
       "bench sample count list with an empty entry",
       {},
       "bench -o {dir}/b --msaa 1,,4",
       2,
       kError + "--msaa '1,,4': entry 2 is empty"},
      {Group::Options,
       "bench sample count 2",
       {},
       "bench -o {dir}/b --msaa 1,2",
       2,
       kError + "--msaa '1,2': 2 samples; expected 1 or 4"},
      {Group::Options,
       "bench shadow size not whole",
       {},
       "bench -o {dir}/b --shadow-sizes 512.5",
       2,
       kError + "--shadow-sizes '512.5': expected map sizes from 1 to 65536 texels"},
      // --quality --bench DIR reads DIR/results.csv, which anyone can edit.
      {Group::Options,
       "bench table tessellation beyond --tess",
       {{"results.csv",
         "scene,mode,tessellation,msaa,triangles,device_median_ms,flip\n"
         "default,phong,99,1,1000,1.5,0.01\n"}},
       render + "--quality 0.5 --bench {dir}",
       2,
       kError + "'{dir}/results.csv' row 1, tessellation '99': expected a number from 0.125 to 16"},
      {Group::Options,
       "bench table time not a number",
       {{"results.csv",
         "scene,mode,tessellation,msaa,triangles,device_median_ms,flip\n"
         "default,phong,1,1,1000,nan,0.01\n"}},
       render + "--quality 0.5 --bench {dir}",
       2,
       kError + "'{dir}/results.csv' row 1, device_median_ms 'nan': expected a number from 0"},
      {Group::Options,
       "compare column with a negative lod bound",
       {},
       "compare -o {dir}/s.png --column lod=-1",
       2,
       kError + "--column 'lod=-1': lod '-1': expected off or an error bound in pixels"},
      {Group::Options,
       "unknown filter",
       {},
       render + "--filter cubic",
       2,
       kError + "--filter 'cubic'"},
      {Group::Options,
       "unknown scene",
       {},
       render + "nowhere",
       2,
       kError + "unknown scene 'nowhere'"},
      {Group::Options,
       "trace spp not square",
       {},
       "trace -o {dir}/t.png --size 8x8 --spp 3",
       2,
       kError + "--spp 3: expected a square number n*n from 1 to 256"},
      // The second review: outputs written beside another output once
      // overwrote the scene they were made from.
      {Group::Outputs,
       "compare numbers over its own scene",
       {{"my.json", R"({"objects": [{"shape": "sphere"}]})"}},
       "compare {dir}/my.json -o {dir}/my.png --size 16x9 --reference raster",
       2,
       kError + "output '{dir}/my.json' (the numbers beside the sheet) is the input"},
      {Group::Options,
       "viewer script scroll of NaN",
       {{"s.txt", "scroll nan\n"}},
       "view --script {dir}/s.txt",
       2,
       kError + "{dir}/s.txt:1: 'scroll nan': expected 'scroll N'"},
      {Group::Json,
       "sky too bright for the target",
       {{"s.json", R"({"environment": {"type": "sky", "intensity": 3e38}, "objects": []})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: environment.intensity: 3e+38 is too large"},
      {Group::Json,
       "sun too bright for the target",
       {{"s.json", R"({"environment": {"type": "sky", "sun_intensity": 1e38}, "objects": []})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: environment.sun_intensity: a component above 1e+06"},
      {Group::Options,
       "compare unknown mode",
       {},
       "compare -o {dir}/s.png --modes flat,toon",
       2,
       kError + "--modes 'toon'"},
      {Group::Options,
       "compare column unknown key",
       {},
       "compare -o {dir}/s.png --column phong,foo=1",
       2,
       kError + "--column 'phong,foo=1': unknown key 'foo': expected one of name, mode, tess"},
      {Group::Options,
       "compare column bad tess",
       {},
       "compare -o {dir}/s.png --column phong,tess=99",
       2,
       kError + "--column 'phong,tess=99': tess '99': expected a factor from 0.125 to 16, or auto"},
      {Group::Options,
       "compare column bad msaa",
       {},
       "compare -o {dir}/s.png --column phong,msaa=2",
       2,
       kError + "--column 'phong,msaa=2': msaa '2': expected 1 or 4"},
      {Group::Options,
       "compare column bad switch",
       {},
       "compare -o {dir}/s.png --column phong,env=maybe",
       2,
       kError + "--column 'phong,env=maybe': env 'maybe': expected one of on, off"},
      {Group::Options,
       "compare column unknown model",
       {},
       "compare -o {dir}/s.png --column toon,msaa=4",
       2,
       kError + "--column 'toon,msaa=4': 'toon' is neither a shading model"},
      {Group::Options,
       "compare column key twice",
       {},
       "compare -o {dir}/s.png --column phong,mode=flat",
       2,
       kError + "--column 'phong,mode=flat': key 'mode' given twice"},
      {Group::Options,
       "compare column duplicate name",
       {},
       "compare -o {dir}/s.png --column name=a,phong --column name=a,flat",
       2,
       kError + "--column 'name=a,flat': the name 'a' is already a column's"},
      {Group::Options,
       "compare column named reference",
       {},
       "compare -o {dir}/s.png --column name=reference,phong",
       2,
       kError + "--column 'name=reference,phong': name 'reference': expected a name other than"},
      {Group::Options,
       "compare against no column",
       {},
       "compare -o {dir}/s.png --column phong --column flat --against gouraud",
       2,
       kError + "--against 'gouraud': expected reference or a column's name ('phong', 'flat')"},
      {Group::Options,
       "compare against the only column",
       {},
       "compare -o {dir}/s.png --modes phong --against phong",
       2,
       kError + "--against 'phong': expected another column to measure against it"},
      {Group::Options,
       "compare modes and columns",
       {},
       "compare -o {dir}/s.png --modes flat --column phong",
       2,
       "shadelab: error: --modes excludes --column"},
      {Group::Options,
       "bench unknown filter",
       {},
       "bench -o {dir}/b --filters cubic",
       2,
       kError + "--filters 'cubic'"},
      {Group::Options,
       "bench list entry twice",
       {},
       "bench -o {dir}/b --modes phong,flat,phong",
       2,
       kError + "--modes 'phong,flat,phong': 'phong' is listed twice"},
      {Group::Options,
       "bench list leading comma",
       {},
       "bench -o {dir}/b --lights ,1",
       2,
       kError + "--lights ',1': entry 1 is empty"},
      {Group::Options,
       "bench list trailing comma",
       {},
       "bench -o {dir}/b --size 32x18,",
       2,
       kError + "--size '32x18,': entry 2 is empty"},
      {Group::Options,
       "bench number listed twice",
       {},
       "bench -o {dir}/b --tess 2,4,2.0",
       2,
       kError + "--tess: entries 1 and 3 are the same value"},
      {Group::Options,
       "compare model listed twice",
       {},
       "compare -o {dir}/s.png --modes gouraud,gouraud",
       2,
       kError + "--modes 'gouraud,gouraud': 'gouraud' is listed twice"},
      {Group::Options,
       "bench unknown reference",
       {},
       "bench -o {dir}/b --reference x",
       2,
       kError + "--reference 'x': expected none, trace, raster"},
      {Group::Options,
       "trace empty epsilon",
       {},
       "trace -o {dir}/t.png --size 32x18 --epsilon ''",
       2,
       kError + "--epsilon '': expected a number from 0 to 1"},
      {Group::Options,
       "bench tess budget",
       {{"plane.json", plane1024}},
       "bench {dir}/plane.json -o {dir}/b --tess 1,16",
       2,
       kError + "scene 'plane' at the sweep's finest tessellation: an estimated"},
      {Group::Options,
       "unknown device",
       {},
       render + "--device nosuchgpu",
       2,
       kError + "--device: no Vulkan 1.3 device whose name contains 'nosuchgpu'"},

      // Scene JSON.
      {Group::Json,
       "missing file",
       {},
       render + "{dir}/gone.json",
       2,
       kError + "scene file '{dir}/gone.json' does not exist"},
      {Group::Json,
       "syntax error",
       {{"s.json", R"({"objects": [)"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: "},
      {Group::Json,
       "empty file",
       {{"s.json", ""}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: "},
      {Group::Json,
       "no objects",
       {{"s.json", "{}"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects: "},
      {Group::Json,
       "unknown shape",
       {{"s.json", R"({"objects": [{"shape": "cone"}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].shape: "},
      {Group::Json,
       "tessellation above 1024",
       {{"s.json", R"({"objects": [{"shape": "sphere", "tessellation": 2000}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].tessellation: "},
      {Group::Json,
       "wrong type",
       {{"s.json", R"({"objects": [{"shape": "plane", "size": "big"}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].size: "},
      {Group::Json,
       "billboard without texture",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": {"kd": 0.5}}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].material: a billboard without a diffuse_map, expected a "
                "material with"},
      {Group::Json,
       "billboard without material",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard"}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].material: a billboard without a diffuse_map"},
      {Group::Json,
       "alpha cutoff above 1",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": "tree", "alpha_cutoff": 1.5}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].alpha_cutoff: alpha_cutoff 1.5 is outside 0..1"},
      {Group::Json,
       "alpha cutoff below 0",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": "tree", "alpha_cutoff": -0.25}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].alpha_cutoff: alpha_cutoff -0.25 is outside 0..1"},
      {Group::Json,
       "grid above the instance limit",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": "tree", "instances": {"grid": {"count": [1000, 1000, 1]}}}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].instances.grid.count: 1000000 instances is above the "
                "limit, expected at most 262144 per object"},
      {Group::Json,
       "scatter above the instance limit",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": "tree", "instances": {"scatter": {"count": 262145, "rectangle": [1, 1]}}}]})"}},
       render + "{dir}/s.json",
       2,
       kError +
           "{dir}/s.json: objects[0].instances.scatter.count: 262145 instances is above the limit"},
      {Group::Json,
       "scatter count 1e30",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": "tree", "instances": {"scatter": {"count": 1e30, "rectangle": [1, 1]}}}]})"}},
       render + "{dir}/s.json",
       2,
       kError +
           "{dir}/s.json: objects[0].instances.scatter.count: 1e+30 instances is above the limit"},
      {Group::Json,
       "grid counts whose product overflows 32 bits",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": "tree", "instances": {"grid": {"count": [65536, 65536, 2]}}}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].instances.grid.count: 8589934592 instances is above the "
                "limit"},
      {Group::Json,
       "grid spacing that places copies past the float range",
       {{"s.json",
         R"({"objects": [{"shape": "sphere", "instances": {"grid": {"count": [100, 1, 1], "spacing": 1e37}}}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].instances: copy 1 of 100 lands outside the float range, "
                "expected copies whose transforms (with the object's own) stay finite"},
      {Group::Json,
       "scatter on a rectangle with no area",
       {{"s.json",
         R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": "tree", "instances": {"scatter": {"count": 10, "rectangle": [0, 5]}}}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].instances.scatter.rectangle: [0, 5] has no area, "
                "expected a width and a depth > 0"},
      {Group::Json,
       "mesh copies above the scene's limit",
       {{"s.json",
         R"({"objects": [{"shape": "sphere", "instances": {"grid": {"count": [256, 256, 1]}}}, {"shape": "box", "instances": {"list": [[{"translate": [0, 1, 0]}]]}}]})"}},
       render + "{dir}/s.json",
       2,
       kError +
           "{dir}/s.json: objects[1].instances: the scene's mesh shapes have 65537 instances in "
           "all, above the limit, expected at most 65536 per scene "
           "(MAX_MESH_INSTANCES_PER_SCENE)"},
      {Group::Json,
       "scene above the total instance limit",
       {{"s.json", R"({"materials": {"tree": {"diffuse_map": {"procedural": "tree", "size": 8}}}, "objects": [{"shape": "billboard", "material": "tree", "instances": {"grid": {"count": [512, 512, 1]}}}, {"shape": "billboard", "material": "tree", "instances": {"grid": {"count": [512, 512, 1]}}}, {"shape": "billboard", "material": "tree", "instances": {"grid": {"count": [512, 512, 1]}}}, {"shape": "billboard", "material": "tree", "instances": {"grid": {"count": [512, 512, 1]}}}, {"shape": "billboard", "material": "tree", "instances": {"grid": {"count": [512, 512, 1]}}}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[4]: the scene's billboards have 1310720 instances in all, "
                "above the limit, expected at most 1048576 per scene"},
      {Group::Json,
       "nested 300 deep",
       {{"s.json", R"({"objects": [], "extras": )" + nested("[", "]", 300) + "}"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: "},
      {Group::Json,
       "nested 200000 deep",
       {{"s.json", R"({"objects": [], "extras": )" + nested("[", "]", 200000) + "}"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: "},
      {Group::Json,
       "scene is a folder",
       {{"s.json", "@folder"}},
       render + "{dir}/s.json",
       2,
       kError + "scene file '{dir}/s.json' is a directory"},
      {Group::Json,
       "scene is a FIFO",
       {{"s.json", "@fifo"}},
       render + "{dir}/s.json",
       2,
       kError + "scene file '{dir}/s.json' is a FIFO, expected a regular file"},
      {Group::Json,
       "scene links to /dev/zero",
       {{"s.json", "@link:/dev/zero"}},
       render + "{dir}/s.json",
       2,
       kError + "scene file '{dir}/s.json' is a character device, expected a regular file"},
      {Group::Json,
       "scene without extension",
       {},
       render + "{dir}/../../../../../../../../../../../../../../dev/zero",
       2,
       kError + "scene file '{dir}/../../../../../../../../../../../../../../dev/zero': unknown "
                "file type"},
      {Group::Json,
       "camera fovy zero",
       {{"s.json", R"({"camera": {"fovy": 0}, "objects": []})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: camera.fovy: "},
      // Inside 0..180 but past float precision: the image was black.
      {Group::Json,
       "camera fovy too narrow",
       {{"s.json", R"({"camera": {"fovy": 1e-30}, "objects": []})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: camera.fovy: fovy 1e-30 degrees is too narrow, expected 0.001 to "
                "180 degrees"},
      {Group::Json,
       "orthographic window too small",
       {{"s.json", R"({"camera": {"projection": "orthographic", "left": -1e-30, "right": 1e-30,
                                  "bottom": -1e-30, "top": 1e-30}, "objects": []})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: camera.right: the view window (2e-30 x 2e-30) is too small"},
      {Group::Json,
       "gltf object missing",
       {{"s.json", R"({"objects": [{"gltf": "gone.gltf"}]})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: objects[0].gltf: "},

      // Images: textures and panoramas.
      {Group::Images,
       "texture missing",
       {{"s.json", texturedScene("gone.png")}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: materials.m.diffuse_map: "},
      {Group::Json,
       "key twice in one object",
       {{"s.json", R"({"camera": {"fovy": 30, "fovy": 60}, "objects": []})"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: JSON: the key \"fovy\" appears twice in one object"},
      // A NUL would end the file name, and the message, wherever C reads it.
      {Group::Json,
       "texture path with a NUL",
       {{"s.json", texturedScene(R"(a\u0000b.png)")}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: materials.m.diffuse_map: a string with a NUL character"},
      {Group::Images,
       "texture is a FIFO",
       {{"s.json", texturedScene("t.png")}, {"t.png", "@fifo"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: materials.m.diffuse_map: texture file '{dir}/t.png' is a FIFO, "
                "expected a regular file"},
      {Group::Images,
       "texture links to /dev/zero",
       {{"s.json", texturedScene("t.png")}, {"t.png", "@link:/dev/zero"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: materials.m.diffuse_map: texture file '{dir}/t.png' is a character "
                "device, expected a regular file"},
      {Group::Images,
       "texture climbs to /dev/zero",
       {{"s.json", texturedScene(kClimb + "dev/zero")}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: materials.m.diffuse_map: texture file '{dir}/" + kClimb +
           "dev/zero' is a character device"},
      {Group::Images,
       "texture is text",
       {{"s.json", texturedScene("t.png")}, {"t.png", "hello"}},
       render + "{dir}/s.json",
       2,
       kError +
           "{dir}/s.json: materials.m.diffuse_map: texture file '{dir}/t.png' cannot be read as an "
           "image"},
      {Group::Images,
       "texture is a folder",
       {{"s.json", texturedScene("t.png")}, {"t.png", "@folder"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: materials.m.diffuse_map: texture file '{dir}/t.png' is a directory"},
      {Group::Images,
       "texture 16384 square",
       {{"s.json", texturedScene("t.png")}, {"t.png", "@copy:bad/huge_16384.png"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: materials.m.diffuse_map: {dir}/t.png: 16384x16384 texels, more than "
                "the 8192 allowed on a side"},
      {Group::Images,
       "panorama missing",
       {{"s.json", panoramaScene("gone.hdr")}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: environment.file: image '{dir}/gone.hdr' does not exist"},
      {Group::Images,
       "panorama is a FIFO",
       {{"s.json", panoramaScene("p.hdr")}, {"p.hdr", "@fifo"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: environment.file: image '{dir}/p.hdr' is a FIFO, expected a "
                "regular file"},
      {Group::Images,
       "panorama links to /dev/zero",
       {{"s.json", panoramaScene("p.hdr")}, {"p.hdr", "@link:/dev/zero"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: environment.file: image '{dir}/p.hdr' is a character "
                "device, expected a regular file"},
      {Group::Images,
       "panorama climbs to /dev/zero",
       {{"s.json", panoramaScene(kClimb + "dev/zero")}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: environment.file: image '{dir}/" + kClimb +
           "dev/zero' is a character device"},
      {Group::Images,
       "panorama is text",
       {{"s.json", panoramaScene("p.hdr")}, {"p.hdr", "hi"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: environment.file: cannot read image '{dir}/p.hdr'"},
      {Group::Images,
       "panorama 16384 square",
       {{"s.json", panoramaScene("p.png")}, {"p.png", "@copy:bad/huge_16384.png"}},
       render + "{dir}/s.json",
       2,
       kError + "{dir}/s.json: environment.file: image '{dir}/p.png': 16384x16384 texels, "
                "more than the 8192 allowed on a side"},
      {Group::Images,
       "viewer script is a FIFO",
       {{"keys.txt", "@fifo"}},
       "view --script {dir}/keys.txt",
       2,
       kError + "--script '{dir}/keys.txt' is a FIFO, expected a regular file"},
      {Group::Images,
       "viewer script links to /dev/zero",
       {{"keys.txt", "@link:/dev/zero"}},
       "view --script {dir}/keys.txt",
       2,
       kError + "--script '{dir}/keys.txt' is a character device, expected a regular file"},

      // glTF: the committed broken files, and files made here.
      // Fields of the wrong length or value were once ignored: a wrong image, silently.
      {Group::Gltf,
       "node matrix of 15 numbers",
       {{"m.gltf", triangleGltf(R"({"mesh": 0, "matrix": [2,0,0,0, 0,2,0,0, 0,0,2,0, 0,0,0]})")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: nodes[0].matrix: 15 numbers; expected 16"},
      {Group::Gltf,
       "node rotation of no length",
       {{"m.gltf", triangleGltf(R"({"mesh": 0, "rotation": [0, 0, 0, 0]})")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: nodes[0].rotation: has no length"},
      {Group::Gltf,
       "node scale too large to frame",
       {{"m.gltf", triangleGltf(R"({"mesh": 0, "scale": [1e38, 1e38, 1e38]})")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: the scene spans (0, 0, 0) to (1e+38, 1e+38, 0), too far to "
                "frame a camera on"},
      {Group::Gltf,
       "alpha mode unknown",
       {{"m.gltf", triangleGltf(R"({"mesh": 0})", R"({"alphaMode": "SOMETIMES"})")}},
       render + "{dir}/m.gltf",
       2,
       kError +
           "{dir}/m.gltf: materials[0].alphaMode: \"SOMETIMES\"; expected OPAQUE, MASK or BLEND"},
      {Group::Gltf,
       "base colour of five numbers",
       {{"m.gltf",
         triangleGltf(R"({"mesh": 0})",
                      R"({"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1, 1]}})")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: Array length of `baseColorFactor` parameter in "
                "pbrMetallicRoughness must be 4, but got 5"},
      {Group::Gltf,
       "texture on a uv set the mesh lacks",
       {},
       render + "{data}/bad/texcoord_missing.gltf",
       2,
       kError + "{data}/bad/texcoord_missing.gltf: meshes[0].primitives[0]: its material's "
                "textures read TEXCOORD_0, which it does not have"},
      {Group::Gltf,
       "light of negative intensity",
       {{"m.gltf",
         triangleGltf(
             R"({"mesh": 0, "children": [1]}, {"extensions": {"KHR_lights_punctual": {"light": 0}}})",
             "{}", "2.0",
             R"("extensionsUsed": ["KHR_lights_punctual"], "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": -5}]}},)")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: extensions.KHR_lights_punctual.lights[0].intensity: -5"},
      {Group::Gltf,
       "joints naming a missing accessor",
       {{"m.gltf", replaced(triangleGltf(R"({"mesh": 0})"), R"("POSITION": 0)",
                            R"("POSITION": 0, "JOINTS_0": 7)")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: meshes[0] primitives[0]: JOINTS_0 refers to accessor 7"},
      {Group::Gltf,
       "glTF 3.0",
       {{"m.gltf", triangleGltf(R"({"mesh": 0})", "{}", "3.0")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: asset.version: \"3.0\"; expected a glTF 2.x version"},
      {Group::Gltf,
       "truncated GLB",
       {},
       render + "{data}/bad/truncated.glb",
       2,
       kError + "{data}/bad/truncated.glb: invalid GLB: truncated"},
      {Group::Gltf,
       "syntax error",
       {},
       render + "{data}/bad/syntax_error.gltf",
       2,
       kError + "{data}/bad/syntax_error.gltf: "},
      {Group::Gltf,
       "accessor past its view",
       {},
       render + "{data}/bad/accessor_past_buffer.gltf",
       2,
       kError + "{data}/bad/accessor_past_buffer.gltf: "},
      {Group::Gltf,
       "accessor count overflow",
       {},
       render + "{data}/bad/accessor_count_overflow.gltf",
       2,
       kError + "{data}/bad/accessor_count_overflow.gltf: "},
      {Group::Gltf,
       "accessor offset overflow",
       {},
       render + "{data}/bad/accessor_offset_overflow.gltf",
       2,
       kError + "{data}/bad/accessor_offset_overflow.gltf: "},
      {Group::Gltf,
       "bufferView offset overflow",
       {},
       render + "{data}/bad/bufferview_offset_overflow.gltf",
       2,
       kError + "{data}/bad/bufferview_offset_overflow.gltf: "},
      {Group::Gltf,
       "missing buffer",
       {},
       render + "{data}/bad/missing_buffer.gltf",
       2,
       kError +
           "{data}/bad/missing_buffer.gltf: invalid glTF: File not found : does_not_exist.bin"},
      {Group::Gltf,
       "missing image",
       {},
       render + "{data}/bad/missing_image.gltf",
       2,
       kError + "{data}/bad/missing_image.gltf: "},
      // Found by the fuzzer: int(1e308) is undefined behaviour (UBSan).
      {Group::Gltf,
       "light index 1e308",
       {},
       render + "{data}/bad/light_index_1e308.gltf",
       2,
       kError + "{data}/bad/light_index_1e308.gltf: nodes[3]: KHR_lights_punctual: 'light' must "
                "be the index of one of the file's 0 lights"},
      {Group::Gltf,
       "negative alphaCutoff",
       {},
       render + "{data}/bad/alpha_cutoff_negative.gltf",
       2,
       kError + "{data}/bad/alpha_cutoff_negative.gltf: materials[0].alphaCutoff: expected a "
                "number >= 0, got -0.5"},
      {Group::Gltf,
       "alphaCutoff not a number",
       {},
       render + "{data}/bad/alpha_cutoff_not_a_number.gltf",
       2,
       kError + "{data}/bad/alpha_cutoff_not_a_number.gltf: materials[0].alphaCutoff: expected "
                "a number >= 0, got \"half\""},
      {Group::Gltf,
       "texture transform scale infinite as a float",
       {},
       render + "{data}/bad/texture_transform_infinite.gltf",
       2,
       kError + "{data}/bad/texture_transform_infinite.gltf: materials[0].pbrMetallicRoughness."
                "baseColorTexture.extensions.KHR_texture_transform.scale[0]: expected a finite "
                "number"},
      {Group::Gltf,
       "texture transform rotation not a number",
       {},
       render + "{data}/bad/texture_transform_not_a_number.gltf",
       2,
       kError + "{data}/bad/texture_transform_not_a_number.gltf: materials[0]."
                "pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform.rotation: "
                "expected a finite number"},
      // JSON cannot write an infinity; a number beyond a double is refused by the parser.
      {Group::Gltf,
       "texture transform offset beyond a double",
       {},
       render + "{data}/bad/texture_transform_1e999.gltf",
       2,
       kError + "{data}/bad/texture_transform_1e999.gltf: invalid glTF: "
                "[json.exception.out_of_range.406] number overflow parsing '1e999'"},
      {Group::Gltf,
       "required extension",
       {},
       render + "{data}/bad/required_extension.gltf",
       2,
       kError + "{data}/bad/required_extension.gltf: extensionsRequired"},
      {Group::Gltf,
       "no triangles",
       {},
       render + "{data}/bad/zero_triangles.gltf",
       2,
       kError + "{data}/bad/zero_triangles.gltf: "},
      {Group::Gltf,
       "index out of range",
       {},
       render + "{data}/bad/index_out_of_range.gltf",
       2,
       kError + "{data}/bad/index_out_of_range.gltf: "},
      {Group::Gltf,
       "buffer climbs to /etc/passwd",
       {{"m.gltf", gltfWithBuffer(kClimb + "etc/passwd")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: File read error : {dir}/" + kClimb +
           "etc/passwd : outside the model's folder '{dir}'"},
      {Group::Gltf,
       "buffer at an absolute path",
       {{"m.gltf", gltfWithBuffer("/etc/passwd")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: File not found : /etc/passwd"},
      {Group::Gltf,
       "buffer is a FIFO",
       {{"m.gltf", gltfWithBuffer("b.bin")}, {"b.bin", "@fifo"}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: File read error : {dir}/b.bin : external file "
                "'{dir}/b.bin' is a FIFO, expected a regular file"},
      {Group::Gltf,
       "buffer links to /dev/zero",
       {{"m.gltf", gltfWithBuffer("b.bin")}, {"b.bin", "@link:/dev/zero"}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: File read error : {dir}/b.bin : external file "
                "'{dir}/b.bin' is a character device, expected a regular file"},
      {Group::Gltf,
       "model is a FIFO",
       {{"m.gltf", "@fifo"}},
       render + "{dir}/m.gltf",
       2,
       kError + "glTF file '{dir}/m.gltf' is a FIFO, expected a regular file"},
      {Group::Gltf,
       "model links to /dev/zero",
       {{"m.glb", "@link:/dev/zero"}},
       render + "{dir}/m.glb",
       2,
       kError + "glTF file '{dir}/m.glb' is a character device, expected a regular file"},
      {Group::Gltf,
       "model is empty",
       {{"m.gltf", ""}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF"},
      {Group::Gltf,
       "GLB version 99",
       {{"m.glb", std::string("glTF\x63\0\0\0\x0c\0\0\0", 12)}},
       render + "{dir}/m.glb",
       2,
       kError + "{dir}/m.glb: invalid GLB: version 99"},
      {Group::Gltf,
       "data URI image declares 16384 square",
       {{"m.gltf",
         gltfWithImages(R"([{"uri": "data:image/png;base64,)" + kHugePngBase64 + R"("}])")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: images[0]: 16384x16384 texels, more than the 8192 "
                "allowed on a side"},
      {Group::Gltf,
       "bufferView image declares 16384 square",
       {{"m.gltf", gltfWithImages(R"([{"bufferView": 1, "mimeType": "image/png"}])")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: images[0]: 16384x16384 texels, more than the 8192 "
                "allowed on a side"},
      {Group::Gltf,
       "bufferView image past its buffer",
       {{"m.gltf", gltfWithImages(R"([{"bufferView": 2, "mimeType": "image/png"}])")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: images[0]: bufferView 2 (bytes 40 + 4000000) lies "
                "outside its buffer's 81 bytes"},
      {Group::Gltf,
       "image neither PNG nor JPEG",
       {{"m.gltf", gltfWithImages(R"([{"uri": "data:image/png;base64,Qk0AAAAA"}])")}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: invalid glTF: images[0]: not a PNG or JPEG image"},
      {Group::Gltf,
       "nested 200000 deep",
       {{"m.gltf", R"({"asset": {"version": "2.0"}, "extras": )" + nested("[", "]", 200000) + "}"}},
       render + "{dir}/m.gltf",
       2,
       kError + "{dir}/m.gltf: "},

      // Outputs: bad paths, and writes that fail half-way (a file size limit
      // stands in for a full disk).
      {Group::Outputs,
       "missing folder",
       {},
       "render -o {dir}/no/such/a.png --size 8x8",
       2,
       kError + "output '{dir}/no/such/a.png': folder '{dir}/no/such' does not exist"},
      {Group::Outputs,
       "unsupported extension",
       {},
       "render -o {dir}/a.bmp --size 8x8",
       2,
       kError + "output '{dir}/a.bmp': unsupported extension '.bmp'"},
      {Group::Outputs,
       "output is a folder",
       {{"a.png", "@folder"}},
       "render -o {dir}/a.png --size 8x8",
       2,
       kError + "output '{dir}/a.png' is a folder"},
      {Group::Outputs,
       "empty output",
       {},
       "render -o '' --size 8x8",
       2,
       kError + "output path is empty"},
      {Group::Outputs,
       "bench into a file",
       {{"b", "x"}},
       "bench -o {dir}/b",
       2,
       kError + "output '{dir}/b' exists and is not a folder"},
      // Sequences (render --turntable, --camera-path): counts and path files.
      {Group::Options,
       "turntable of no frames",
       {},
       "render -o {dir}/a.png --turntable 0",
       2,
       kError + "--turntable 0: expected an integer from 1 to 9999"},
      {Group::Options,
       "turntable of negative frames",
       {},
       "render -o {dir}/a.png --turntable -3",
       2,
       kError + "--turntable -3: expected an integer from 1 to 9999"},
      // Not a number of the option's kind: CLI11's "Could not convert", reworded.
      {Group::Options,
       "turntable not an integer",
       {},
       "render -o {dir}/a.png --turntable 2.5",
       2,
       kError + "--turntable '2.5': expected an integer (see --help)"},
      {Group::Options,
       "fovy not a number",
       {},
       "render -o {dir}/a.png --fovy wide",
       2,
       kError + "--fovy 'wide': expected a number (see --help)"},
      {Group::Options,
       "camera path not JSON",
       {{"path.json", R"([{"eye": [0, 1, 5], "at": [0, 0)"}},
       "render -o {dir}/a.png --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: JSON: malformed (not valid JSON)"},
      {Group::Options,
       "camera path eye of two numbers",
       {{"path.json", R"([{"eye": [0, 1], "at": [0, 0, 0]}])"}},
       "render -o {dir}/a.png --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: [0].eye: expected an array of three numbers"},
      {Group::Options,
       "camera path empty",
       {{"path.json", R"({"frames": 3, "cameras": []})"}},
       "render -o {dir}/a.png --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: cameras: expected a non-empty list of cameras"},
      {Group::Options,
       "camera path eye on the look-at point",
       {{"path.json", R"([{"eye": [0, 0, 0], "at": [0, 0, 0]}])"}},
       "render -o {dir}/a.png --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: [0]."},
      {Group::Options,
       "camera path fewer frames than keys",
       {{"path.json", R"({"frames": 1, "cameras": [{"eye": [0, 1, 5]}, {"eye": [5, 1, 0]}]})"}},
       "render -o {dir}/a.png --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: frames: 1 is fewer than the 2 cameras to pass through"},
      {Group::Options,
       "camera path passing through its look-at point",
       {{"path.json", R"({"frames": 3, "cameras": [{"eye": [0, 0, 5], "at": [0, 0, 0]},
                                                  {"eye": [0, 0, -5], "at": [0, 0, 0]}]})"}},
       "render -o {dir}/a.png --size 16x16 --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: frames: frame 2, between cameras[0] and cameras[1]: the camera's "
                "at: "},
      {Group::Options,
       "gif of one image",
       {},
       "render -o {dir}/a.png --gif",
       2,
       kError + "--gif: expected --turntable N or --camera-path FILE with it"},
      {Group::Options,
       "fps without gif",
       {},
       "render -o {dir}/a.png --turntable 3 --fps 5",
       2,
       "shadelab: error: --fps requires --gif"},
      {Group::Options,
       "camera path with a key twice",
       {{"path.json", R"([{"eye": [0, 1, 5], "eye": [5, 1, 0]}])"}},
       "render -o {dir}/a.png --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: JSON: the key \"eye\" appears twice in one object"},
      {Group::Options,
       "eye beyond a float's square",
       {},
       "render -o {dir}/a.png --eye 1e30,1e30,1e30",
       2,
       kError + "--eye: eye and at are farther apart than 1e18, expected eye within 1e18 of at"},
      {Group::Options,
       "camera path eye beyond a float",
       {{"path.json", R"([{"eye": [1e39, 0, 0], "at": [0, 0, 0]}])"}},
       "render -o {dir}/a.png --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: [0].eye[0]: expected a finite number"},
      {Group::Options,
       "camera path nested too deep",
       {{"path.json", std::string(100000, '[') + std::string(100000, ']')}},
       "render -o {dir}/a.png --camera-path {dir}/path.json",
       2,
       kError + "{dir}/path.json: JSON nests deeper than"},
      {Group::Options,
       "camera path missing",
       {},
       "render -o {dir}/a.png --camera-path {dir}/none.json",
       2,
       kError + "camera path '{dir}/none.json'"},
      {Group::Outputs,
       "PNG on a full disk",
       {},
       "render -o {dir}/a.png --size 256x256",
       2,
       kError + "cannot write '{dir}/a.png': File too large",
       kSmallDisk},
      // giflib reports no failed write: the GIF is read back before it counts,
      // and the frames written before it are removed with it.
      {Group::Outputs,
       "turntable GIF on a full disk",
       {},
       "render -o {dir}/s.png --turntable 12 --gif --size 128x72",  // frames < 8 KiB
       2,
       kError + "cannot write '{dir}/s.gif': the encoded GIF",
       kSmallDisk},
      {Group::Outputs,
       "EXR on a full disk",
       {},
       "render -o {dir}/a.exr --size 256x256",
       2,
       kError + "cannot write '{dir}/a.exr': File too large",
       kSmallDisk},
      {Group::Outputs,
       "trace on a full disk",
       {},
       "trace -o {dir}/t.png --size 384x384 --spp 1",
       2,
       kError + "cannot write '{dir}/t.png': File too large",
       kSmallDisk},
      {Group::Outputs,
       "compare sheet on a full disk",
       {},
       "compare -o {dir}/s.png --size 64x36 --modes flat --reference raster",
       2,
       kError + "cannot write '{dir}/s.png': File too large",
       kSmallDisk},
      {Group::Outputs,
       "bench CSV on a full disk",
       {},
       "bench -o {dir}/b --size 32x18 --frames 2 --rounds 1 --modes unlit --tess 1 --msaa 1 "
       "--reference raster",
       2,
       kError + "cannot write '{dir}/b/results.csv': File too large",
       kNoDisk},
      {Group::Outputs,
       "bench chart on a full disk",
       {},
       "bench -o {dir}/b --size 32x18 --frames 2 --rounds 1 --modes unlit --tess 1 --msaa 1 "
       "--reference raster",
       2,
       kError + "cannot write '{dir}/b/error_vs_time.png': File too large",
       kSmallDisk},
      {Group::Outputs,
       "zfight chart on a full disk",
       {},
       "study zfight -o {dir}/z --size 32x18",
       2,
       kError + "cannot write '{dir}/z/zfight_near.png': File too large",
       kSmallDisk},
  };
  return cases;
}

std::string substituted(std::string text, const fs::path& dir) {
  auto replace = [&](const std::string& key, const std::string& value) {
    for (size_t at = text.find(key); at != std::string::npos;
         at = text.find(key, at + value.size()))
      text.replace(at, key.size(), value);
  };
  replace("{dir}", dir.string());
  replace("{data}", SHADELAB_TEST_DATA_DIR);
  return text;
}

std::set<std::string> filesUnder(const fs::path& dir) {
  std::set<std::string> names;
  // Links are listed, not followed.
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir))
    names.insert(fs::relative(entry.path(), dir).string());
  return names;
}

void prepare(const fs::path& dir, const Setup& file) {
  fs::path path = dir / file.name;
  const std::string& text = file.text;
  if (text == "@fifo") {
    ASSERT_EQ(mkfifo(path.c_str(), 0600), 0) << path;
  } else if (text == "@folder") {
    fs::create_directory(path);
  } else if (text.rfind("@link:", 0) == 0) {
    fs::create_symlink(text.substr(6), path);
  } else if (text.rfind("@copy:", 0) == 0) {
    fs::copy_file(fs::path(SHADELAB_TEST_DATA_DIR) / text.substr(6), path);
  } else {
    std::ofstream(path, std::ios::binary) << text;
  }
}

void runGroup(Group group, const char* groupName) {
  int index = 0;
  for (const BadCase& bad : badCases()) {
    if (bad.group != group) continue;
    fs::path dir =
        fs::path(SHADELAB_TEST_OUTPUT_DIR) / "bad_input" / groupName / std::to_string(index++);
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const Setup& file : bad.files) prepare(dir, file);
    std::set<std::string> before = filesUnder(dir);
    // timeout: a case that hangs (a FIFO read) fails instead of stalling the suite.
    CommandResult r = run(substituted(bad.arguments, dir), bad.environment + " timeout 60");
    // The message's first line: every error, CLI11's usage errors too, reads
    // "shadelab: error: ..." (commands that report progress print it before).
    std::string expected = substituted(bad.firstLine, dir);
    EXPECT_EQ(expected.rfind("shadelab: ", 0), 0u) << bad.name << ": " << expected;
    size_t own = r.output.find("\nshadelab: ");
    size_t start = r.output.rfind("shadelab: ", 0) == 0 || own == std::string::npos ? 0 : own + 1;
    std::string firstLine = r.output.substr(start, r.output.find('\n', start) - start);
    EXPECT_EQ(r.exitCode, bad.exitCode) << bad.name << "\n" << r.output;
    EXPECT_EQ(firstLine.substr(0, expected.size()), expected) << bad.name << "\n" << r.output;
    EXPECT_EQ(filesUnder(dir), before) << bad.name << ": a file was left behind\n" << r.output;
  }
}

// At least 60 rows, every group represented.
TEST(BadInputTable, CoversEveryGroup) {
  EXPECT_GE(badCases().size(), 60u);
  for (Group group : {Group::Options, Group::Json, Group::Images, Group::Gltf, Group::Outputs})
    EXPECT_TRUE(std::any_of(badCases().begin(), badCases().end(),
                            [&](const BadCase& bad) { return bad.group == group; }));
}

TEST(BadInputOptions, ExitTwoWithMessageAndNoFile) {
  runGroup(Group::Options, "options");
}
TEST(BadInputJson, ExitTwoWithMessageAndNoFile) {
  runGroup(Group::Json, "json");
}
TEST(BadInputImages, ExitTwoWithMessageAndNoFile) {
  runGroup(Group::Images, "images");
}
TEST(BadInputGltf, ExitTwoWithMessageAndNoFile) {
  runGroup(Group::Gltf, "gltf");
}
TEST(BadInputOutputs, ExitTwoWithMessageAndNoFile) {
  runGroup(Group::Outputs, "outputs");
}

}  // namespace
