// The JSON scene format
// =====================
// A scene file is one JSON object. Only "objects" is required; every other
// field has the default of scene.h / shape.h. Unknown fields are errors, so a
// typo such as "colour" is reported rather than silently ignored. Example:
//
// {
//   "camera": {"eye": [0, 2, 6], "at": [0, 0, 0], "up": [0, 1, 0],
//              "projection": "perspective", "fovy": 45, "near": 0.1, "far": 100},
//   "ambient": 0.3,
//   "background": [0.02, 0.02, 0.03],
//   "lights": [
//     {"type": "point", "position": [3, 5, 4], "intensity": [1, 1, 1], "attenuation": [1, 0,
//     0.01]},
//     {"type": "directional", "direction": [1, -1, 0], "intensity": 0.3}
//   ],
//   "materials": {
//     "red": {"ka": [0.1, 0, 0], "kd": [0.8, 0.1, 0.1], "ks": 0.5, "shininess": 64}
//   },
//   "objects": [
//     {"name": "ball", "shape": "sphere", "radius": 1, "tessellation": 32, "material": "red",
//      "transform": [{"translate": [0, 1, 0]}, {"scale": 0.5}]}
//   ]
// }
//
// description one line saying what the scene shows (a string; `shadelab scenes` lists it).
// camera      eye [0, 2, 6], at [0, 0, 0], up [0, 1, 0] (non-zero, not parallel to at - eye,
//             at != eye); projection "perspective" (default), "frustum" or "orthographic";
//             fovy 45 degrees (perspective, 0 < fovy < 180); near 0.1, far 100 (0 < near < far);
//             left -1, right 1, bottom -1, top 1 (frustum: the window on the near plane;
//             orthographic: the sides of the view volume; left < right, bottom < top).
// ambient     Ia, [r, g, b] or one number for grey; default 1.
// background  the linear clear colour, [r, g, b] or a number; default 0.
// environment what surrounds the scene at infinity, drawn behind it (the skybox) and seen in
//             reflective and transparent materials; default none (the background colour).
//             {"type": "none"}
//             {"type": "sky", "zenith": [0.12, 0.3, 0.75], "horizon": [0.75, 0.82, 0.95],
//              "ground": [0.22, 0.2, 0.18], "sun_direction": [-0.4, -0.6, -0.7] (the way sunlight
//              travels, as for a directional light), "sun_size": 3 (angular diameter in degrees,
//              0..90, 0: no sun), "sun_intensity": 20 (the disc's radiance)}: a gradient, sqrt in
//              the elevation, from horizon to zenith above and to ground below;
//             {"type": "equirect", "file": "sky.hdr", "rotation": 0}: an equirectangular
//              panorama (JPEG/PNG decoded from sRGB, HDR/EXR linear); its centre looks along -z,
//              its top straight up; "rotation" turns it about +y in degrees (counter-clockwise
//              seen from above);
//             {"type": "cube", "faces": ["px.png", "nx.png", "py.png", "ny.png", "pz.png",
//              "nz.png"]}: six square faces of one size in Vulkan's cube layout.
//             Files are relative to the scene file's folder. Every type but "none" may have
//             "intensity" (>= 0, default 1, multiplies it); sky and equirect may have
//             "resolution", the cube face size (a power of two, 16..2048; default 512 for the
//             sky, a panorama's width / 4 rounded up to a power of two within 64..2048).
// lights      at most 8 (MAX_LIGHTS, the renderer's limit). "type" is "point" (default) or
//             "directional". A point light needs "position" [x, y, z] and may have
//             "attenuation" [a, b, c] for f_att = 1 / (a + b d + c d^2): all >= 0, not all 0,
//             default [1, 0, 0]. A directional light needs "direction" [x, y, z], the way its
//             light travels (non-zero). "intensity" Ip: [r, g, b] or a number, default 1.
//             "shadows": true (default) or false: whether the light casts shadows when the
//             frame draws them (--shadows).
// materials   name -> {"ka", "kd", "ks": [r, g, b] or a number >= 0, "shininess": n >= 0},
//             the Phong terms of I = Ia ka + sum f_att Ip [kd (N.L) + ks (R.V)^n];
//             defaults ka 0.1, kd 0.7, ks 0.3, shininess 32. Also "reflectivity" kr and
//             "transparency" kt (0..1, default 0: the mirror and transmitted fractions the
//             ray tracer and environment mapping add), "ior" (> 0, default 1.5: the inside's
//             index of refraction, the outside being air) and "emissive" (colour, default 0).
//             Textures (see below): "diffuse_map", "normal_map", "height_map", "bump_scale",
//             "sampler", "uv_mapping", "uv_scale".
// objects     required, may be empty. Each object has "name" (default: its JSON path),
//             "shape", "material" (a name from "materials" or an inline material object;
//             default the material defaults), "transform" and "children". An object
//             without "shape" is a group: it draws nothing, takes no material and must have
//             a non-empty "children" array. Shaped objects may have children too.
//             Shaped objects may have "casts_shadows" and "receives_shadows" (true or false,
//             default true: in the shadow maps, and darkened by them); glTF objects do both.
//             An object with "gltf" instead of "shape" places a glTF 2.0 file (.gltf or
//             .glb, its path relative to this scene file) under the object's transform:
//             {"gltf": "models/x.gltf", "transform": [{"scale": 2}]}. Its meshes,
//             materials and textures are added as objects (the glTF node hierarchy
//             continues the matrix stack); its lights and cameras are ignored, since the
//             scene file has its own. Such an object takes "name", "transform" and
//             "children" only.
//
// Shapes, centred on the origin; lengths and radii must be > 0:
//   "plane"     size 1 (side, in the XZ plane facing +y); tessellation 16 quads per side (1..1024)
//   "box"       size 1: full edge lengths, one number (a cube) or [x, y, z]
//   "sphere"    radius 1; tessellation 16 slices (3..1024), stacks = slices / 2
//   "icosphere" radius 1; tessellation 3 = subdivision level (0..7)
//   "torus"     around the y axis: major_radius 1, minor_radius 0.25 (< major_radius);
//               tessellation 16 segments around the ring (3..1024), half as many around the tube
//   "teapot"    the Utah teapot standing on y = 0, spout along +x, 3.15 high, 6.4 long;
//               tessellation 16 quads per patch side (1..64; 32 patches)
//   "billboard" a textured quad that turns towards the viewer, drawn by the billboard pass
//               (passes/billboard_pass.h; the ray tracer traces the same quads). Fields:
//               "kind" "screen" (parallel to the image plane) | "spherical" (default: faces the
//               eye point) | "cylindrical" (turns about "axis" only, e.g. a tree);
//               "axis" [0, 1, 0] (world space: the cylindrical axis, the spherical up);
//               "size" [width, height] or a number, default 1; "anchor" "center" (default) or
//               "bottom": where the object's origin sits on the quad; "material" must have a
//               "diffuse_map" (colour and alpha; {"procedural": "tree", "size": 128} makes a
//               conifer with alpha); "alpha" "test" (default: texels below "alpha_cutoff",
//               0..1, default 0.5, are cut away; writes depth) or "blend" (opacity = texel alpha
//               x (1 - transparency), sorted back to front with the transparent objects);
//               "receives_shadows" (default true; billboards never cast); "instances" (below).
//               A billboard takes only position and width/height scale from its transform.
//   "instances" on a billboard or a mesh shape: copies drawn in one instanced draw, each
//               culled (and, for a mesh, given its level of detail) on its own;
//               exactly one of {"list": [transform, ...]} (one "transform" list per copy),
//               {"grid": {"count": [nx, ny, nz], "spacing": [x, y, z] or a number (default
//               1)}} (centred on the object's origin), {"scatter": {"count": n, "seed": 1,
//               "rectangle": [width, depth] (> 0: in the object's xz plane, centred), "scale":
//               [min, max] (uniform per copy, default [1, 1]), "yaw": [min, max] (degrees about
//               y, uniform per copy; default none)}} (std::mt19937: the same copies
//               on every machine). Each copy's matrix is the object's times its own. At most
//               262,144 (MAX_INSTANCES_PER_OBJECT) per object, 1,048,576 billboard copies
//               and 65,536 mesh copies (MAX_MESH_INSTANCES_PER_SCENE) per scene. A mesh
//               copy is an object of its own, named "NAME[i]".
// Every shape may have "crease_angle" (degrees, 0..180): its normals are then recomputed as
// area-weighted averages, with vertices split wherever faces meet at more than the angle
// (0: faceted, as flat shading sees it; 180: all smooth, e.g. a box with rounded shading).
// Without it, shapes keep their exact normals.
// Objects with identical shape descriptions share one mesh.
//
// Material textures:
//   "diffuse_map"  multiplies kd and ka; a colour texture (sRGB, so texels are decoded to
//                  linear light before filtering and lighting).
//   "normal_map"   tangent space, xyz = 2 rgb - 1, green toward +v (OpenGL convention); linear.
//   "height_map"   the red channel is the height h (0..1); linear. The normal is perturbed by
//                  its central differences per texel: n = (-s dh/du, -s dh/dv, 1).
//   Each is a file name (relative to the scene file; PNG, JPEG, HDR, EXR, anything
//   OpenImageIO reads; float images are linear light and are sRGB-encoded for diffuse maps)
//   or a generator: {"procedural": "checker" | "bricks" | "dimples" | "waves",
//   "size": 256 (texels per side, 1..4096), "repeats": 8 (cells per side: checks, brick rows,
//   dimples, wave periods, 1..4096)}. A generator makes a height field h in 0..1: a diffuse
//   map is then mix(low, high, h) with "colors": [low, high] (linear colours, default
//   [0, 1]); a height map is h itself; a normal map is derived from h with "depth" (texels
//   a height of 1 stands for, >= 0, default 4). A missing or unreadable file is an error that
//   names the file and the material.
//   "bump_scale"   >= 0, default 1: scales a normal map's xy, and is s above for a height map
//                  (both maps: their normals are combined). Bump mapping is per fragment:
//                  Phong and Blinn-Phong apply it; flat and Gouraud ignore normal and height
//                  maps (their lighting happens before any fragment exists).
//   "sampler"      for all of the material's maps: {"wrap_u", "wrap_v": "repeat" (default) |
//                  "clamp_to_edge" | "mirrored_repeat"; "filter": "nearest" (the base level
//                  only, no mipmaps) | "bilinear" (the nearest mip level) | "trilinear"
//                  (default) | "aniso" (trilinear plus anisotropic; slow on llvmpipe);
//                  "anisotropy": 2..16, default 8, only with "aniso"}.
//   "uv_mapping"   where texture coordinates come from: "mesh" (default: the shape's own UVs)
//                  or an S-mapping fitted to the mesh's bounds, "planar" (along -z onto xy),
//                  "cylindrical" (around y), "spherical", "box" (planar along the normal's
//                  dominant axis); formulas in core/scene/uv_mapping.h.
//   "uv_scale"     repeats per unit of UV, a number or [u, v] > 0, default 1 (tiling).
//   UVs have their origin at the image's bottom left (v up).
//
// Transforms: "transform" is a list of steps, each an object with exactly one key:
//   {"translate": [x, y, z]}
//   {"rotate": {"axis": [x, y, z], "degrees": a}}                     about the origin
//   {"rotate": {"axis": [x, y, z], "degrees": a, "about": [x, y, z]}}  about the line through
//   "about"
//   {"rotate": {"axis": "x", "degrees": a}}  "x", "y" or "z": the elementary rotation R_x, R_y,
//                                            R_z (entries exactly cos a, sin a, 0 and 1; an axis
//                                            vector goes through Rodrigues' formula, whose
//                                            diagonal can be 1 ulp from 1); "about" works too
//   {"scale": [sx, sy, sz]} or {"scale": s}                             non-zero factors
//   {"shear": {"xy": 0, "xz": 0, "yx": 0, "yz": 0, "zx": 0, "zy": 0}}  any subset of the six
// Rotations are right-handed (counter-clockwise looking down the axis toward the origin);
// shear is x' = x + xy y + xz z, y' = y + yx x + yz z, z' = z + zx x + zy y.
// The matrix is the product in list order, M = T1 T2 ... Tn, so the LAST step is applied to
// the points first: [{"translate": t}, {"scale": s}] scales, then translates. M must be
// invertible. Children use a matrix stack: a child's world matrix = parent's world matrix * M.
#include "core/scene/scene_json.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "core/base/errors.h"
#include "core/base/files.h"
#include "core/base/json_nesting.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/scene_json_billboards.h"
#include "core/scene/scene_json_environment.h"
#include "core/scene/scene_json_fields.h"
#include "core/scene/scene_json_textures.h"
#include "core/scene/scene_json_transform.h"
#include "core/scene/transform.h"
#include "interface.h"

namespace shadelab {
namespace {

using scene_json::billboardFields;
using scene_json::describe;
using scene_json::Field;
using scene_json::formatNumber;
using scene_json::Names;
using scene_json::parseBillboard;
using scene_json::parseTransform;
using scene_json::TextureLibrary;
using MaterialTable = std::map<std::string, Material>;

constexpr int kMaxDepth = 64;  // nested children; deeper is a mistake, not a model

void checkCamera(const Field& field, const Camera& camera) {
  std::optional<CameraProblem> problem = findCameraProblem(camera);
  if (!problem) return;
  std::string at = problem->field;
  if (at == "far" && !field.has("far")) at = "near";
  field.at(at).fail(problem->problem, problem->expected);
}

Camera parseCamera(const Field& field) {
  field.expectObject(
      {"eye", "at", "up", "projection", "fovy", "near", "far", "left", "right", "bottom", "top"});
  Camera camera;
  if (auto f = field.optional("eye")) camera.eye = f->vec3();
  if (auto f = field.optional("at")) camera.at = f->vec3();
  if (auto f = field.optional("up")) camera.up = f->vec3();
  if (auto f = field.optional("projection"))
    camera.projection = f->choose("projection", kProjectionNames);
  if (auto f = field.optional("fovy")) {
    camera.fovyDegrees = f->number();
    if (!(camera.fovyDegrees > 0.0f && camera.fovyDegrees < 180.0f))
      f->fail(describe(f->json()) + " degrees is not a field of view",
              "an angle between 0 and 180 degrees");
  }
  if (auto f = field.optional("near")) camera.near = f->positive();
  if (auto f = field.optional("far")) camera.far = f->number();
  if (auto f = field.optional("left")) camera.left = f->number();
  if (auto f = field.optional("right")) camera.right = f->number();
  if (auto f = field.optional("bottom")) camera.bottom = f->number();
  if (auto f = field.optional("top")) camera.top = f->number();
  checkCamera(field, camera);
  return camera;
}

glm::vec3 parseAttenuation(const Field& field) {
  glm::vec3 abc = field.vec3();
  for (const Field& coefficient : field.elements("an array of 3 numbers"))
    coefficient.nonNegative();
  if (abc == glm::vec3(0.0f))
    field.fail("all coefficients are 0, so f_att = 1 / 0", "[a, b, c] >= 0, not all 0");
  return abc;
}

Light parseLight(const Field& field) {
  Light light;
  if (auto f = field.optional("type")) light.type = f->choose("light type", kLightTypeNames);
  if (light.type == LightType::Point) {
    field.expectObject({"type", "position", "intensity", "attenuation", "shadows"});
    light.position = field.required("position", "the point light's position [x, y, z]").vec3();
    if (auto f = field.optional("attenuation")) light.attenuation = parseAttenuation(*f);
  } else {
    field.expectObject({"type", "direction", "intensity", "shadows"});
    Field direction = field.required("direction", "the direction the light travels [x, y, z]");
    light.direction = direction.vec3();
    if (glm::length(light.direction) == 0.0f)
      direction.fail("zero-length direction", "a non-zero vector");
  }
  if (auto f = field.optional("intensity")) light.intensity = f->colour();
  if (auto f = field.optional("shadows")) light.shadows = f->boolean();
  return light;
}

std::vector<Light> parseLights(const Field& field) {
  std::vector<Field> entries = field.elements("an array of lights");
  if (entries.size() > MAX_LIGHTS)
    field.fail(std::to_string(entries.size()) + " lights",
               "at most " + std::to_string(MAX_LIGHTS) + " (MAX_LIGHTS, the renderer's limit)");
  std::vector<Light> lights;
  for (const Field& entry : entries) lights.push_back(parseLight(entry));
  return lights;
}

float unitInterval(const Field& field) {
  float value = field.number();
  if (value < 0.0f || value > 1.0f)
    field.fail("value " + formatNumber(value) + " is outside 0..1", "a fraction from 0 to 1");
  return value;
}

// `owner` names the material in texture messages ("material 'brick'").
Material parseMaterial(const Field& field, const std::string& owner, TextureLibrary& textures) {
  Names allowed = {"ka",           "kd",           "ks",  "shininess",
                   "reflectivity", "transparency", "ior", "emissive"};
  allowed.insert(allowed.end(), TextureLibrary::fieldNames().begin(),
                 TextureLibrary::fieldNames().end());
  field.expectObject(allowed);
  Material material;
  if (auto f = field.optional("ka")) material.ka = f->colour();
  if (auto f = field.optional("kd")) material.kd = f->colour();
  if (auto f = field.optional("ks")) material.ks = f->colour();
  if (auto f = field.optional("shininess")) material.shininess = f->nonNegative();
  if (auto f = field.optional("reflectivity")) material.reflectivity = unitInterval(*f);
  if (auto f = field.optional("transparency")) material.transparency = unitInterval(*f);
  if (auto f = field.optional("ior")) material.ior = f->positive();
  if (auto f = field.optional("emissive")) material.emissive = f->colour();
  textures.parseTextures(field, owner, material);
  return material;
}

MaterialTable parseMaterials(const Field& field, TextureLibrary& textures) {
  MaterialTable materials;
  for (const auto& [name, value] : field.members())
    materials[name] = parseMaterial(value, "material '" + name + "'", textures);
  return materials;
}

// What each "shape" accepts beyond the fields every object has.
struct ShapeSpec {
  std::string_view name;
  ShapeKind kind;
  Names fields;
  uint32_t minTessellation, maxTessellation, defaultTessellation;
  std::string_view tessellationMeaning;  // empty: the shape has no tessellation
};

const std::vector<ShapeSpec>& shapeSpecs() {
  // The teapot's limit is lower: it has 32 patches of n x n quads each.
  static const std::vector<ShapeSpec> specs = {
      {"plane", ShapeKind::Plane, {"size", "tessellation"}, 1, 1024, 16, "quads per side"},
      {"box", ShapeKind::Box, {"size"}, 0, 0, 0, ""},
      {"sphere", ShapeKind::UvSphere, {"radius", "tessellation"}, 3, 1024, 16, "slices"},
      {"icosphere", ShapeKind::Icosphere, {"radius", "tessellation"}, 0, 7, 3, "subdivision level"},
      {"torus",
       ShapeKind::Torus,
       {"major_radius", "minor_radius", "tessellation"},
       3,
       1024,
       16,
       "segments around the ring"},
      {"teapot", ShapeKind::Teapot, {"tessellation"}, 1, 64, 16, "quads per patch side"},
  };
  return specs;
}

const ShapeSpec& shapeSpec(const Field& field) {
  Names names;
  for (const ShapeSpec& spec : shapeSpecs()) names.push_back(spec.name);
  names.push_back("billboard");  // handled by ObjectBuilder before this lookup
  return shapeSpecs()[field.choice("shape", names)];
}

glm::vec3 positiveSize(const Field& field) {
  if (field.json().is_number()) return glm::vec3(field.positive());
  glm::vec3 size = field.vec3OrNumber();
  for (const Field& edge : field.elements("an array of 3 numbers")) edge.positive();
  return size;
}

void checkTorusRadii(const Field& object, const ShapeDesc& shape) {
  if (shape.minorRadius < shape.majorRadius) return;
  object.at(object.has("minor_radius") ? "minor_radius" : "major_radius")
      .fail("minor_radius (" + formatNumber(shape.minorRadius) +
                ") is not less than major_radius (" + formatNumber(shape.majorRadius) + ")",
            "minor_radius < major_radius");
}

// Every value is checked here, before buildShape: the mesh functions assert.
ShapeDesc parseShape(const Field& object, const ShapeSpec& spec) {
  ShapeDesc shape;
  shape.kind = spec.kind;
  if (!spec.tessellationMeaning.empty()) {
    shape.tessellation = spec.defaultTessellation;
    if (auto f = object.optional("tessellation"))
      shape.tessellation =
          f->integer(spec.minTessellation, spec.maxTessellation,
                     std::string(spec.name) + " " + std::string(spec.tessellationMeaning));
  }
  if (auto f = object.optional("size")) {
    if (spec.kind == ShapeKind::Box)
      shape.halfExtents = 0.5f * positiveSize(*f);
    else
      shape.size = f->positive();
  }
  if (auto f = object.optional("radius")) shape.radius = f->positive();
  if (auto f = object.optional("crease_angle")) {
    float degrees = f->number();
    if (!(degrees >= 0.0f && degrees <= 180.0f))
      f->fail("crease_angle " + formatNumber(degrees) + " is out of range",
              "an angle in degrees from 0 to 180");
    shape.creaseAngleDegrees = degrees;
  }
  if (spec.kind == ShapeKind::Torus) {
    if (auto f = object.optional("major_radius")) shape.majorRadius = f->positive();
    if (auto f = object.optional("minor_radius")) shape.minorRadius = f->positive();
    checkTorusRadii(object, shape);
  }
  return shape;
}

bool sameShape(const ShapeDesc& a, const ShapeDesc& b) {
  return a.kind == b.kind && a.size == b.size && a.halfExtents == b.halfExtents &&
         a.radius == b.radius && a.majorRadius == b.majorRadius && a.minorRadius == b.minorRadius &&
         a.tessellation == b.tessellation && a.creaseAngleDegrees == b.creaseAngleDegrees &&
         a.mirrored == b.mirrored;
}

// Walks the object tree depth first, keeping the parent's world matrix: the
// matrix stack of the course, one frame per recursion level.
class ObjectBuilder {
 public:
  ObjectBuilder(Scene& scene, const MaterialTable& materials, TextureLibrary& textures,
                std::filesystem::path baseDirectory)
      : scene_(scene),
        materials_(materials),
        textures_(textures),
        baseDirectory_(std::move(baseDirectory)) {}

  void add(const Field& field, const glm::mat4& parentWorld, int depth) {
    if (depth > kMaxDepth)
      field.fail("objects nested more than " + std::to_string(kMaxDepth) + " levels deep",
                 "a shallower hierarchy");
    if (!field.json().is_object()) field.wrongType("an object (a shape or a group)");
    const ShapeSpec* spec = nullptr;
    bool billboard = false;
    if (auto f = field.optional("shape")) {
      billboard = f->json() == "billboard";
      if (!billboard) spec = &shapeSpec(*f);
    }
    std::optional<Field> gltf = field.optional("gltf");
    Names allowed = {"name", "shape", "transform", "children"};
    if (gltf) {
      allowed = {"name", "gltf", "transform", "children"};
    } else if (billboard) {
      allowed.push_back("material");
      allowed.insert(allowed.end(), billboardFields().begin(), billboardFields().end());
    } else if (spec) {
      allowed.push_back("instances");
      allowed.push_back("material");
      allowed.push_back("crease_angle");
      allowed.push_back("casts_shadows");
      allowed.push_back("receives_shadows");
      allowed.insert(allowed.end(), spec->fields.begin(), spec->fields.end());
    }
    field.expectObject(allowed);

    std::string name = field.path();
    if (auto f = field.optional("name")) name = f->string();
    glm::mat4 world = parentWorld;
    if (auto f = field.optional("transform")) world = parentWorld * parseTransform(*f);
    if (gltf) {
      addGltf(*gltf, world);
    } else if (billboard) {
      addBillboard(parseBillboard(field, name, world, material(field, name)), field);
    } else if (spec) {
      ShapeDesc shape = parseShape(field, *spec);
      Material surface =
          material(field, name);  // checked before the (possibly large) mesh is built
      Object object{name, 0, world, surface};
      if (auto f = field.optional("casts_shadows")) object.castsShadows = f->boolean();
      if (auto f = field.optional("receives_shadows")) object.receivesShadows = f->boolean();
      if (auto f = field.optional("instances")) {
        addCopies(object, shape, parseInstances(*f, world), *f);
      } else {
        object.mesh = mesh(shape, world);
        scene_.objects.push_back(object);
      }
    }

    std::optional<Field> children = field.optional("children");
    std::vector<Field> list;
    if (children) list = children->elements("an array of objects");
    if (!spec && !gltf && !billboard && list.empty())
      (children ? *children : field)
          .fail("a group (an object without \"shape\" or \"gltf\") with no children",
                "a \"shape\", a \"gltf\" file or a non-empty \"children\" array");
    for (const Field& child : list) add(child, world, depth + 1);
  }

  // Procedural meshes are described now and built by buildShapes(), after
  // the whole file has been read and its cost estimated (Scene::estimate
  // reads the descriptions, not the meshes).
  void buildShapes() {
    for (uint32_t i : unbuilt_) scene_.meshes[i] = buildShape(scene_.shapes[i]);
    unbuilt_.clear();
  }

 private:
  Material material(const Field& object, const std::string& objectName) const {
    if (!object.has("material")) return Material{};
    Field field = object.at("material");
    if (field.json().is_object())
      return parseMaterial(field, "the material of object '" + objectName + "'", textures_);
    if (!field.json().is_string()) field.wrongType("a material name or a material object");
    auto found = materials_.find(field.string());
    if (found != materials_.end()) return found->second;
    Names names;
    for (const auto& [name, value] : materials_) names.push_back(name);
    field.fail("unknown material " + describe(field.json()),
               names.empty() ? "a material defined in \"materials\" (there are none)"
                             : "one of " + joinNames(names));
  }

  // The glTF's nodes continue this object's matrix stack; its own lights and
  // cameras are not used (the scene file has its own).
  void addGltf(const Field& field, const glm::mat4& world) {
    std::filesystem::path path = baseDirectory_ / field.string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
      field.fail("glTF file '" + path.string() + "' does not exist",
                 "a .gltf or .glb file, its path relative to the scene file");
    appendGltf(scene_, path, world);
  }

  // The scene's instances in all stay within MAX_INSTANCES_PER_SCENE.
  void addBillboard(Billboard billboard, const Field& field) {
    instanceTotal_ += billboard.instances.size();
    if (instanceTotal_ > MAX_INSTANCES_PER_SCENE)
      field.fail("the scene's billboards have " + std::to_string(instanceTotal_) +
                     " instances in all, above the limit",
                 "at most " + std::to_string(MAX_INSTANCES_PER_SCENE) +
                     " per scene (MAX_INSTANCES_PER_SCENE)");
    scene_.billboards.push_back(std::move(billboard));
  }

  // A mesh shape's "instances": one object per copy, in one instance group.
  void addCopies(Object object, const ShapeDesc& shape, const std::vector<glm::mat4>& copies,
                 const Field& field) {
    meshCopies_ += copies.size();
    if (meshCopies_ > MAX_MESH_INSTANCES_PER_SCENE)
      field.fail("the scene's mesh shapes have " + std::to_string(meshCopies_) +
                     " instances in all, above the limit",
                 "at most " + std::to_string(MAX_MESH_INSTANCES_PER_SCENE) +
                     " per scene (MAX_MESH_INSTANCES_PER_SCENE)");
    object.instanceGroup = uint32_t(scene_.objects.size());
    std::string name = object.name;
    // The shape's mesh, and the one wound for a mirroring copy: each looked
    // up once, not once per copy (up to 65,536).
    std::optional<uint32_t> meshes[2];
    for (size_t i = 0; i < copies.size(); ++i) {
      object.name = name + "[" + std::to_string(i) + "]";
      object.transform = copies[i];
      std::optional<uint32_t>& found = meshes[mirrors(copies[i])];
      if (!found) found = mesh(shape, copies[i]);
      object.mesh = *found;
      scene_.objects.push_back(object);
    }
  }

  // The mesh of `shape` placed by `world`: wound for it if it mirrors.
  uint32_t mesh(ShapeDesc shape, const glm::mat4& world) {
    shape.mirrored = mirrors(world);
    for (uint32_t i = 0; i < scene_.shapes.size(); ++i)
      if (sameShape(scene_.shapes[i], shape)) return i;
    scene_.meshes.emplace_back();
    scene_.shapes.push_back(shape);
    unbuilt_.push_back(uint32_t(scene_.meshes.size() - 1));
    return unbuilt_.back();
  }

  Scene& scene_;
  const MaterialTable& materials_;
  TextureLibrary& textures_;
  std::filesystem::path baseDirectory_;
  std::vector<uint32_t> unbuilt_;  // Scene::meshes slots still empty
  size_t instanceTotal_ = 0;       // billboard instances so far
  size_t meshCopies_ = 0;          // mesh-shape instances so far
};

// "[json.exception.parse_error.101] parse error at line 3, column 8: syntax error ..."
// -> "syntax error ...": the position is reported separately.
std::string jsonErrorDescription(std::string what) {
  size_t tag = what.find("] ");
  if (tag != std::string::npos) what.erase(0, tag + 2);
  if (what.starts_with("parse error")) {
    size_t colon = what.find(": ");
    if (colon != std::string::npos) what.erase(0, colon + 2);
  }
  return what;
}

// `byte` counts from 1 (the offending character is text[byte - 1]); 0 = unknown.
InputError syntaxError(std::string_view text, const std::string& source, size_t byte,
                       const std::string& what) {
  std::string message = source + ": ";
  if (byte > 0) {
    size_t offset = std::min(byte - 1, text.size());
    std::string_view before = text.substr(0, offset);
    size_t line = 1 + size_t(std::count(before.begin(), before.end(), '\n'));
    size_t lastNewline = before.rfind('\n');
    size_t column = lastNewline == std::string_view::npos ? offset + 1 : offset - lastNewline;
    message += "line " + std::to_string(line) + ", column " + std::to_string(column) + ": ";
  }
  return InputError(message + "invalid JSON: " + jsonErrorDescription(what));
}

// Number overflow ("number overflow parsing '1e999'") carries no position:
// find the literal it quotes.
size_t quotedLiteralByte(std::string_view text, const std::string& what) {
  size_t open = what.find('\'');
  size_t close = what.rfind('\'');
  if (open == std::string::npos || close <= open + 1) return 0;
  size_t found = text.find(std::string_view(what).substr(open + 1, close - open - 1));
  return found == std::string_view::npos ? 0 : found + 1;
}

nlohmann::json parseDocument(std::string_view text, const std::string& source) {
  checkJsonNesting(text, source);  // the parser recurses once per level
  try {
    return nlohmann::json::parse(text.begin(), text.end(), scene_json::refuseDuplicateKeys(source));
  } catch (const nlohmann::json::parse_error& error) {
    throw syntaxError(text, source, error.byte, error.what());
  } catch (const nlohmann::json::exception& error) {
    throw syntaxError(text, source, quotedLiteralByte(text, error.what()), error.what());
  }
}

}  // namespace

Scene parseSceneJson(std::string_view text, const std::string& sourceName,
                     const TriangleBudget& budget) {
  nlohmann::json document = parseDocument(text, sourceName);
  Field root(document, "", sourceName);
  root.expectObject({"description", "camera", "ambient", "background", "environment", "lights",
                     "materials", "objects"});
  Scene scene;
  scene.name = std::filesystem::path(sourceName).stem().string();
  if (auto f = root.optional("description")) scene.description = f->string();
  if (auto f = root.optional("camera")) scene.camera = parseCamera(*f);
  if (auto f = root.optional("ambient")) scene.ambient = f->colour();
  if (auto f = root.optional("background")) scene.background = f->colour();
  if (auto f = root.optional("environment"))
    scene.environment =
        scene_json::parseEnvironment(*f, std::filesystem::path(sourceName).parent_path());
  if (auto f = root.optional("lights")) scene.lights = parseLights(*f);
  TextureLibrary textures(scene, std::filesystem::path(sourceName).parent_path());
  MaterialTable materials;
  if (auto f = root.optional("materials")) materials = parseMaterials(*f, textures);
  ObjectBuilder builder(scene, materials, textures,
                        std::filesystem::path(sourceName).parent_path());
  Field objects = root.required("objects", "an array of objects (it may be empty)");
  for (const Field& object : objects.elements("an array of objects"))
    builder.add(object, glm::mat4(1.0f), 0);
  checkTriangleBudget(scene, 1.0f, budget.maxTriangles, "its own tessellation (before building)",
                      budget.option);
  builder.buildShapes();
  return scene;
}

Scene loadSceneJson(const std::filesystem::path& path, const TriangleBudget& budget) {
  std::string name = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw InputError("scene file '" + name + "' does not exist");
  if (std::filesystem::is_directory(path, error))
    throw InputError("scene file '" + name + "' is a directory, expected a .json file");
  return parseSceneJson(readInputFile(path, "scene file", kMaxTextInputBytes), name, budget);
}

}  // namespace shadelab
