// Limits, binding numbers and the structs shared by C++ and GLSL.
// Included by both sides: in C++ the GLSL type names alias GLM types, so each
// struct is written once. Only vec4/mat4/ivec4 members are used, so std140
// and std430 layouts equal the C++ layout (checked by static_asserts in
// src/core/vulkan/gpu_scene.cpp).
#ifndef SHADELAB_INTERFACE_H
#define SHADELAB_INTERFACE_H

#ifdef __cplusplus
#include <glm/glm.hpp>
namespace shadelab::gpu {
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;
#endif

#define MAX_LIGHTS 8

// Descriptor set 0
#define BINDING_FRAME 0        // uniform buffer: FrameData
#define BINDING_SHADOWS 4      // uniform buffer: ShadowData
#define BINDING_OBJECTS 1      // storage buffer: ObjectData[]
#define BINDING_ENVIRONMENT 2  // combined image sampler: the environment cube map
#define BINDING_SHADOW_MAP \
  3  // combined image sampler (compare): the shadow maps, one layer per view
// Translucent casters (kt > 0: glass, glTF BLEND factors), per layer of the
// shadow maps: the opaque casters' depth alone and the product of every
// translucent one's transmittance (passes/shadow_pass.h). Read only by
// SHADOW_TRANSLUCENT variants.
#define BINDING_OPAQUE_SHADOW_MAP 5  // combined image sampler (compare)
#define BINDING_TRANSMITTANCE 6      // combined image sampler: R16F, nearest

// Compute passes that build the environment cube (their own set 0)
#define BINDING_CUBE_TARGET 0  // storage image2DArray: one mip level of the cube, layer = face
#define BINDING_PANORAMA 1     // combined image sampler: the equirectangular panorama
#define CUBE_BUILD_GROUP_SIZE 8

// Descriptor set 1, one per material: its textures (a 1x1 dummy when a slot
// is empty, since lavapipe crashes on never-written descriptors)
#define BINDING_DIFFUSE_MAP 0
#define BINDING_NORMAL_MAP 1
#define BINDING_HEIGHT_MAP 2

// Descriptor set 2 of the billboard pass: the frame's visible billboard
// instances (BillboardInstance[], eye space), indexed by gl_InstanceIndex.
#define BINDING_BILLBOARD_INSTANCES 0

// Billboard kinds (SPEC_BILLBOARD_KIND and DrawConstants::optics.x of a
// billboard draw): how the quad turns towards the viewer
// (passes/billboard_pass.h).
#define BILLBOARD_SCREEN 0       // parallel to the image plane
#define BILLBOARD_SPHERICAL 1    // facing the eye point, its up kept near BillboardInstance::up
#define BILLBOARD_CYLINDRICAL 2  // turning about BillboardInstance::up only
// An object's impostor (core/scene/impostor.h): the quad faces the eye
// point through the atlas centre; its texture is three cells of the atlas
// (DrawConstants::optics.z per side), each found where the view ray meets
// the plane it was captured in, blended (BillboardInstance says where).
#define BILLBOARD_IMPOSTOR 3
// The most instances one object may have, and a scene in all: each visible
// one is 64 bytes per frame in flight; a million is ~1 s per frame on lavapipe.
#define MAX_INSTANCES_PER_OBJECT 262144
#define MAX_INSTANCES_PER_SCENE 1048576
// Copies of meshes a scene may have in all: each is an object of its own on
// the host (culled, levelled, 128 bytes of ObjectData per frame in flight).
#define MAX_MESH_INSTANCES_PER_SCENE 65536

// Specialization constant ids and the values of SHADING_MODEL. The number of
// point and of directional lights are constants too: with them each kind of
// light has its own loop that unrolls, every light is read at a constant
// offset and a directional light pays for no distance or attenuation. On
// llvmpipe a loop bound read from a uniform buffer made each light a per-lane
// gather and Phong 2x slower; one loop for both kinds cost the dense scene's
// Phong frame 25.9 ms against 20.6 ms with two (both measured). Skipping
// f_att when no point light attenuates saved another ~0.5 ms there.
#define SPEC_SHADING_MODEL 0
#define SPEC_POINT_LIGHTS 1
#define SPEC_DIRECTIONAL_LIGHTS 2
#define SPEC_ATTENUATED_POINT_LIGHTS 3
#define SPEC_SHADOW_FILTER 4  // SHADOW_*: how the shadow maps are filtered (off: not read)
// Environment term in the forward pass (id 8: clear of the ids other features add).
#define SPEC_ENVIRONMENT 8
// glTF materials: alphaMode MASK (fragments below the cut-off discarded) and
// doubleSided (back faces lit with the flipped normal). Constants, not flags,
// so the pipelines of other materials keep no discard (which would turn off
// early depth testing) and no extra branch.
#define SPEC_ALPHA_MASK 9
#define SPEC_DOUBLE_SIDED 10
// Bit i set: FrameData::lights[i] casts shadows (its JSON "shadows"). A
// constant, so a light without shadows has no lookup at all: llvmpipe runs
// both sides of a branch, even a uniform one, and paid for it regardless.
#define SPEC_SHADOWED_LIGHTS 11
// The draw's material compiled in (ForwardFrame::materialConstants): when
// set, ka, kd, ks and n are these constants instead of DrawConstants' values.
// llvmpipe loads a push-constant value per fragment at each use and folds a
// constant into the code. Ids 13..22 hold the ten floats.
#define SPEC_MATERIAL_CONSTANTS 12
#define SPEC_MATERIAL_KA 13         // 13, 14, 15: r, g, b
#define SPEC_MATERIAL_KD 16         // 16, 17, 18
#define SPEC_MATERIAL_KS 19         // 19, 20, 21
#define SPEC_MATERIAL_SHININESS 22  // n
// Textured forward and billboard pipelines: the TEXTURE_* flags of the maps
// the draw applies (its material's, with the frame's --bump and --mip-tint)
// and whether their uv transform does.
// A constant, since llvmpipe runs both sides of even a uniform branch: read
// from the push constants, every textured fragment paid for the mip-tint
// query and the five bump lookups whether its material had them or not
// (billboards-10000: 22.5 ms against 16.8 without, docs/PERFORMANCE.md).
#define SPEC_TEXTURE_MAPS 23
// With the environment term: the draw is transparent (kt > 0) and looks the
// cube up along T as well. A constant for the same reason: as a branch on
// kt every reflecting fragment paid for the refraction and its second
// lookup (env: 25-26 ms against 21-22 ms, docs/PERFORMANCE.md).
#define SPEC_ENVIRONMENT_REFRACTS 24
// Billboard pass: the draw's BILLBOARD_* kind (DrawConstants::optics.x
// holds it too, for the host).
#define SPEC_BILLBOARD_KIND 25
// The frame's ambient term and lights compiled in (ForwardFrame::lights):
// when set, frameAmbient() and frameLight(i) (common.glsl) return these
// constants instead of FrameData's. They are eye-space values, so only a run
// whose camera and lights hold still uses them (Renderer::compileLights).
// Ids 27..101 hold ambient r, g, b, then per light i (MAX_LIGHTS of them, in
// FrameData's order) from 30 + 9 i: position (point) or direction towards
// the light (directional) x, y, z; intensity r, g, b; attenuation a, b, c.
#define SPEC_LIGHT_CONSTANTS 26
#define SPEC_LIGHT_VALUES 27
#define LIGHT_VALUE_WORDS (3 + 9 * MAX_LIGHTS)
// The draw's emission compiled in with the rest of its material
// (SPEC_MATERIAL_CONSTANTS): DrawConstants::object.w's bits, one uint.
#define SPEC_MATERIAL_EMISSIVE (SPEC_LIGHT_VALUES + LIGHT_VALUE_WORDS)
#define SHADING_FLAT 0
#define SHADING_GOURAUD 1
#define SHADING_PHONG 2
#define SHADING_BLINN_PHONG 3
#define SHADING_UNLIT 4  // constant colour: the timing floor the others are measured against
#define SHADOW_OFF 0
#define SHADOW_HARD 1
#define SHADOW_PCF3 2
#define SHADOW_PCF5 3
// Or-ed into SPEC_SHADOW_FILTER: the maps have translucent layers to read.
#define SHADOW_TRANSLUCENT 16

// A light in eye space.
struct GpuLight {
  vec4 position;     // point: eye-space position, w = 1; directional: unit eye-space direction
                     // *towards* the light, w = 0
  vec4 intensity;    // rgb = Ip per channel
  vec4 attenuation;  // f_att = 1 / (a + b d + c d^2): xyz = (a, b, c)
};

struct FrameData {
  mat4 projection;
  vec4 ambient;  // rgb = Ia
  // The point lights first, then the directional ones; how many of each is a
  // specialization constant (SPEC_POINT_LIGHTS, SPEC_DIRECTIONAL_LIGHTS), so
  // neither a count nor a light's type is uploaded.
  GpuLight lights[MAX_LIGHTS];
  mat4 viewToWorld;  // inverse view rotation: eye-space directions to world space for the cube map
};

// The shadow maps as the forward pass reads them (BINDING_SHADOW_MAP's layers).
// Everything is indexed by the light's slot, which is a constant once the
// shader's light loops are unrolled: lavapipe loads such values once per
// draw, where a per-fragment index (e.g. a cube face) costs a gather per lane.
struct ShadowData {
  // Per light, in FrameData::lights' order: x = its first layer (-1: no
  // map), y = the world size of a texel (directional) or of a texel per unit
  // of distance (point), z = 1 / map size.
  vec4 lights[MAX_LIGHTS];
  // Point lights: the cube faces' projection as numbers. For a direction v
  // from the light with major axis m = |v_major| (the face), depth =
  // x - y / m and the face's xy = z * (right, up) / m (shadows.glsl).
  vec4 cube[MAX_LIGHTS];
  vec4 bias;  // ShadowBias in texels: x = constant, y = slope, z = normal offset
  // Directional lights: eye space to the map's clip space (xy -1..1, depth 0..1).
  mat4 eyeToLight[MAX_LIGHTS];
  // The bias towards the light per light, premultiplied on the host
  // (shadows.glsl, shadowMapCoordinates): moving towards the light by
  // bias.x + bias.y tan(theta) texels is, for a directional light, map
  // depth + x + y tan; for a point light, the vector from the light scaled
  // by x - y tan. z: a directional map's depth per texel (what the PCF
  // kernels' receiver-plane gradient is held to). w unused.
  vec4 lookup[MAX_LIGHTS];
};

// Per object and per frame: its matrices (read by the vertex stage only).
struct ObjectData {
  mat4 modelView;
  mat4 normalMatrix;  // inverse transpose of modelView's upper 3x3, padded to a mat4
};

// DrawConstants::object.y: which of the material's textures the draw has
// (set 1 always holds all three, dummies where absent); the host compiles
// them, with the frame's switches, into its pipeline (SPEC_TEXTURE_MAPS).
#define TEXTURE_DIFFUSE 1
#define TEXTURE_NORMAL 2
#define TEXTURE_HEIGHT 4
#define TEXTURE_MIP_TINT 8  // debug: replace the diffuse texel by its mip level's colour
// The textures' KHR_texture_transform (diffuseUv, normalUv and the
// rotations) applies; without it st is used as is.
#define TEXTURE_UV_TRANSFORM 16
// glTF BLEND (Material::alphaCoverage) with a diffuse map: the texel's alpha
// scales the opacity kd.w the blended draw writes (and, in the shadow maps,
// what the texel passes: shadow_pass.cpp).
#define TEXTURE_ALPHA 32

// Per draw, as push constants: the material and the object's index. Fragment
// shaders read the material from here, never from the storage buffer (on
// llvmpipe that load cost 3 ms per 1280x720 frame, measured).
struct DrawConstants {
  vec4 ka;  // rgb, w = alpha mask threshold: with SPEC_ALPHA_MASK, fragments whose diffuse texel
            // alpha (1 without a texture) is below it are discarded (alphaCutoff / factor alpha)
  vec4 kd;  // rgb
  vec4 ks;  // rgb, w = shininess n
  ivec4 object;    // x = index into ObjectData[], y = TEXTURE_* flags (the host's record:
                   // shaders read SPEC_TEXTURE_MAPS), z = 1: receives shadows, w = emission
                   // (Material::emissive) as RGB9E5 bits: r, g, b mantissas in bits 0-8,
                   // 9-17, 18-26, the shared exponent (bias 15) in 27-31 (packEmissive)
  vec4 texturing;  // xy = uv scale (repeats), z = bump scale, w = diffuse map's uv rotation
  vec4 optics;     // environment term: x = reflectivity kr, y = transparency kt, z = ior;
                   // w = normal (and height) map's uv rotation
  // KHR_texture_transform in the sampled (glTF) uv space: xy = offset, zw = scale.
  vec4 diffuseUv;
  vec4 normalUv;
};

// One billboard instance of one frame, in eye space (written by the host
// per frame for the instances that survive culling).
// Impostors use them otherwise: centre.xyz is the atlas centre and w the
// square quad's side; up the mesh's rotation to eye space (a unit
// quaternion, xyzw); right.xyz the three blended atlas cells' indices and
// outline.xyz their weights (the floats' bits); core/scene/impostor.h,
// impostorBlend.
struct BillboardInstance {
  vec4 centre;  // xyz = the anchor point, eye space; w = the quad's width
  vec4 up;      // xyz = unit axis (cylindrical) or up (spherical), eye space; w = the height
  vec4 right;   // unused but by impostors
  // Trimmed copies (DrawConstants::optics.w = 1): the corners of the triangle
  // drawn instead of the quad, in quad coordinates (x across, y up, 0..1 on
  // the quad), two halves each (packHalf2x16): x = corner 0, y = 1, z = 2.
  uvec4 outline;
};

// The procedural sky (shaders/sky.glsl, mirrored by skyRadiance in core/scene/environment.cpp).
struct SkyParameters {
  vec4 zenith;        // rgb, straight up
  vec4 horizon;       // rgb, at the horizon (both halves)
  vec4 ground;        // rgb, straight down
  vec4 sunDirection;  // xyz = unit direction towards the sun, w = cos(angular radius)
  vec4 sunRadiance;   // rgb = the disc's radiance, w = cos(0.5 * angular radius): soft edge starts
  ivec4 face;         // x = cube face size in texels
};

// The skybox pass, as push constants.
struct SkyboxConstants {
  mat4 clipToWorld;  // inverse(projection * view rotation): clip position -> world direction
  vec4 depth;  // x = the far plane's depth (what the depth buffer is cleared to), y = the near's
};

// Equirectangular panorama -> cube conversion.
struct PanoramaParameters {
  ivec4 face;     // x = cube face size in texels
  vec4 sampling;  // x = panorama mip level, y = rotation about +y (radians), z = intensity
};

#ifdef __cplusplus
}  // namespace shadelab::gpu
#endif
#endif
