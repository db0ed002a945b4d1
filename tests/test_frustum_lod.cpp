// View-frustum culling's box test against brute force, box transforms, and
// the level-of-detail formulas (chord error, projected size), and the
// octahedral impostor's map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/scene/frustum.h"
#include "core/scene/impostor.h"
#include "core/scene/lod.h"
#include "core/scene/scene.h"
#include "core/scene/shape.h"
#include "core/scene/transform.h"

namespace shadelab {
namespace {

glm::vec3 corner(const Bounds& box, int index) {
  return {index & 1 ? box.max.x : box.min.x, index & 2 ? box.max.y : box.min.y,
          index & 4 ? box.max.z : box.min.z};
}

Frustum cameraFrustum() {
  Camera camera;  // eye (0, 2, 6) looking at the origin, 45 degrees, near 0.1, far 100
  return frustumFromMatrix(camera.projectionMatrix(16.0f / 9.0f) * camera.viewMatrix());
}

Bounds cube(glm::vec3 centre, float half) {
  return {centre - glm::vec3(half), centre + glm::vec3(half)};
}

class FrustumPlanes : public ::testing::TestWithParam<Projection> {};

TEST_P(FrustumPlanes, BoundWhatTheProjectionMapsIntoClipSpace) {
  Camera camera;
  camera.projection = GetParam();
  camera.left = -8.0f, camera.right = 6.0f, camera.bottom = -4.0f, camera.top = 5.0f;
  if (camera.projection == Projection::Frustum) {
    camera.left = -0.08f, camera.right = 0.05f, camera.bottom = -0.04f, camera.top = 0.06f;
  }
  glm::mat4 viewProjection = camera.projectionMatrix(1.5f) * camera.viewMatrix();
  Frustum frustum = frustumFromMatrix(viewProjection);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-30.0f, 30.0f);
  int inside = 0;
  for (int i = 0; i < 4000; ++i) {
    glm::vec3 p(coordinate(random), coordinate(random), coordinate(random));
    glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
    bool inClip = clip.w > 0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w &&
                  clip.z >= 0 && clip.z <= clip.w;
    bool inPlanes = true;
    for (const Plane& plane : frustum.planes) inPlanes &= plane.signedDistance(p) >= -1e-4f;
    // Points within float rounding of a plane may go either way.
    float margin = 1e9f;
    for (const Plane& plane : frustum.planes)
      margin = std::min(margin, std::abs(plane.signedDistance(p)));
    if (margin > 1e-3f) {
      EXPECT_EQ(inClip, inPlanes) << p.x << " " << p.y << " " << p.z;
    }
    inside += inClip;
  }
  EXPECT_GT(inside, 20);  // the sample reaches inside as well as out
}

INSTANTIATE_TEST_SUITE_P(Projections, FrustumPlanes,
                         ::testing::Values(Projection::Perspective, Projection::Frustum,
                                           Projection::Orthographic));

TEST(FrustumCulling, BoxesInsideOutsideAndStraddling) {
  Frustum frustum = cameraFrustum();
  EXPECT_TRUE(boxIntersectsFrustum(cube({0, 0, 0}, 0.5f), frustum));      // in the middle
  EXPECT_FALSE(boxIntersectsFrustum(cube({0, 2, 9}, 0.5f), frustum));     // behind the eye
  EXPECT_FALSE(boxIntersectsFrustum(cube({0, 0, -200}, 1.0f), frustum));  // beyond far
  EXPECT_FALSE(boxIntersectsFrustum(cube({-30, 0, 0}, 1.0f), frustum));   // off to the left
  EXPECT_TRUE(boxIntersectsFrustum(cube({-30, 0, 0}, 28.0f), frustum));   // reaching in
  EXPECT_TRUE(boxIntersectsFrustum(cube({0, 0, 0}, 500.0f), frustum));    // containing it all
}

// The positive-vertex test is exactly "all 8 corners outside one plane".
TEST(FrustumCulling, BoxTestEqualsBruteForceOverCorners) {
  Frustum frustum = cameraFrustum();
  std::mt19937 random(11);
  std::uniform_real_distribution<float> coordinate(-40.0f, 40.0f), size(0.01f, 15.0f);
  int culled = 0;
  for (int i = 0; i < 5000; ++i) {
    glm::vec3 low(coordinate(random), coordinate(random), coordinate(random));
    Bounds box{low, low + glm::vec3(size(random), size(random), size(random))};
    bool outsideOnePlane = false;
    for (const Plane& plane : frustum.planes) {
      bool allOut = true;
      for (int c = 0; c < 8; ++c) allOut &= plane.signedDistance(corner(box, c)) < 0.0f;
      outsideOnePlane |= allOut;
    }
    EXPECT_EQ(boxIntersectsFrustum(box, frustum), !outsideOnePlane);
    culled += outsideOnePlane;
  }
  EXPECT_GT(culled, 500);
  EXPECT_LT(culled, 4900);
}

// Arvo's box contains every transformed corner and touches each of its faces.
TEST(FrustumCulling, TransformedBoundsAreTightAroundTheCorners) {
  Bounds box{{-1, -2, -0.5f}, {3, 1, 0.5f}};
  glm::mat4 transform = translation({5, -1, 2}) * rotationAxis({1, 2, 3}, 0.7f) *
                        scaling({2, 0.5f, 3}) * shearing({.xy = 0.3f});
  Bounds out = transformBounds(box, transform);
  glm::vec3 low(1e9f), high(-1e9f);
  for (int c = 0; c < 8; ++c) {
    glm::vec3 p = glm::vec3(transform * glm::vec4(corner(box, c), 1.0f));
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(out.min[axis], low[axis], 1e-4f);
    EXPECT_NEAR(out.max[axis], high[axis], 1e-4f);
  }
}

// scaledShape describes what buildShape builds at a factor, for every kind
// (the detail chain of a --tess F scene starts from it).
TEST(LevelOfDetail, ScaledShapeBuildsWhatTheFactorBuilds) {
  for (ShapeKind kind : {ShapeKind::Plane, ShapeKind::UvSphere, ShapeKind::Icosphere,
                         ShapeKind::Torus, ShapeKind::Teapot, ShapeKind::Box}) {
    ShapeDesc shape;
    shape.kind = kind;
    shape.tessellation = kind == ShapeKind::Icosphere ? 2 : 8;
    for (float scale : {0.125f, 0.5f, 1.0f, 4.0f}) {
      Mesh scaled = buildShape(shape, scale);
      Mesh described = buildShape(scaledShape(shape, scale));
      EXPECT_EQ(described.indices, scaled.indices) << shapeKindName(kind) << " x" << scale;
      EXPECT_EQ(described.vertices.size(), scaled.vertices.size());
    }
  }
  ShapeDesc sphere;
  sphere.kind = ShapeKind::UvSphere;
  sphere.tessellation = 32;
  EXPECT_EQ(scaledShape(sphere, 4.0f).tessellation, 128u);
}

TEST(LevelOfDetail, ChordErrorSegmentsAreTheSmallestWithinTheBound) {
  for (float radius : {0.1f, 1.0f, 7.5f})
    for (float error : {0.0005f, 0.01f, 0.05f}) {
      uint32_t n = segmentsForChordError(radius, error);
      auto chord = [&](uint32_t segments) {
        return radius * (1.0f - std::cos(3.14159265f / float(segments)));
      };
      EXPECT_LE(chord(n), error * 1.0001f) << radius << " " << error;
      if (n > 3) {
        EXPECT_GT(chord(n - 1), error * 0.9999f) << radius << " " << error;
      }
    }
  EXPECT_EQ(segmentsForChordError(1.0f, 2.0f), 3u);  // any triangle is within 2
}

TEST(LevelOfDetail, PixelsPerUnitFollowTheProjection) {
  ViewSize view{Camera{}, 1280, 720};
  view.camera.fovyDegrees = 90.0f;  // tan(45) = 1: the view is 2 depth high
  EXPECT_NEAR(pixelsPerUnit(view, 4.0f), 720.0f / 8.0f, 1e-3f);
  view.camera.projection = Projection::Orthographic;
  view.camera.bottom = -3.0f;
  view.camera.top = 3.0f;
  EXPECT_NEAR(pixelsPerUnit(view, 4.0f), 120.0f, 1e-3f);
  EXPECT_NEAR(pixelsPerUnit(view, 40.0f), 120.0f, 1e-3f);
}

// --tess auto: a sphere far away needs fewer slices than the same sphere
// near; and the chosen slice count meets the pixel bound at the sphere's
// nearest point.
TEST(LevelOfDetail, AutoTessellationMeetsThePixelBound) {
  auto slicesAt = [](float distance) {
    Scene scene;
    scene.camera.eye = glm::vec3(0, 0, distance);
    scene.camera.at = glm::vec3(0);
    ShapeDesc sphere;
    sphere.kind = ShapeKind::UvSphere;
    sphere.radius = 1.0f;
    sphere.tessellation = 16;
    scene.objects.push_back({"ball", scene.addShape(sphere), glm::mat4(1.0f), Material{}});
    ViewSize view{scene.camera, 640, 360};
    tessellateForView(scene, view, 0.5f);
    uint32_t slices = scene.shapes[0].tessellation;
    float ppu = pixelsPerUnit(view, distance - 1.0f);
    EXPECT_LE((1.0f - std::cos(3.14159265f / float(slices))) * ppu, 0.5f) << distance;
    EXPECT_EQ(scene.meshes[0].triangleCount(), buildShape(scene.shapes[0]).triangleCount());
    return slices;
  };
  uint32_t near = slicesAt(3.0f), far = slicesAt(30.0f);
  EXPECT_GT(near, far);
  EXPECT_GE(far, 3u);
}

// The torus's ring (outer circle R + r, n segments) and tube (r, n / 2) and
// the teapot's body (radius 2, 4 patches of k quads around) meet the bound.
TEST(LevelOfDetail, TorusAndTeapotLevelsMeetThePixelBound) {
  Scene scene;
  scene.camera.eye = glm::vec3(0, 0, 12);
  ShapeDesc torus;
  torus.kind = ShapeKind::Torus;
  torus.majorRadius = 1.0f;
  torus.minorRadius = 0.3f;
  ShapeDesc teapot;
  teapot.kind = ShapeKind::Teapot;
  scene.objects.push_back({"torus", scene.addShape(torus), glm::mat4(1.0f), Material{}});
  scene.objects.push_back({"teapot", scene.addShape(teapot), scaling(glm::vec3(0.5f)), Material{}});
  ViewSize view{scene.camera, 1280, 720};
  tessellateForView(scene, view, 0.5f);
  auto chordPixels = [&](float radius, uint32_t segments, float depth, float scale) {
    return scale * radius * (1.0f - std::cos(3.14159265f / float(segments))) *
           pixelsPerUnit(view, depth);
  };
  uint32_t n = scene.shapes[0].tessellation;
  float torusDepth = 12.0f - boundingRadius(computeBounds(scene.meshes[0]));
  EXPECT_LE(chordPixels(1.3f, n, torusDepth, 1.0f), 0.5f);
  EXPECT_LE(chordPixels(0.3f, n / 2, torusDepth, 1.0f), 0.5f);
  uint32_t k = scene.shapes[1].tessellation;
  Bounds teapotBox = transformBounds(computeBounds(scene.meshes[1]), scaling(glm::vec3(0.5f)));
  float teapotDepth = 12.0f - centre(teapotBox).z - boundingRadius(teapotBox);
  EXPECT_LE(chordPixels(2.0f, 4 * k, teapotDepth, 0.5f), 0.5f);
  EXPECT_GT(chordPixels(2.0f, 4 * (k - 1), teapotDepth, 0.5f), 0.5f);  // and no finer
}

// --simplify: a finely tessellated sphere (a custom mesh, as glTF ones are)
// far away loses most triangles; near it keeps more.
TEST(LevelOfDetail, SimplificationKeepsMoreTrianglesWhenNearer) {
  auto keptAt = [](float distance) {
    Scene scene;
    scene.camera.eye = glm::vec3(0, 0, distance);
    scene.camera.at = glm::vec3(0);
    scene.objects.push_back(
        {"ball", scene.addMesh(makeUvSphere(1.0f, 128, 64)), glm::mat4(1.0f), Material{}});
    SimplifyStats stats = simplifyForView(scene, ViewSize{scene.camera, 640, 360}, 0.5f);
    EXPECT_EQ(stats.trianglesBefore, makeUvSphere(1.0f, 128, 64).triangleCount());
    EXPECT_EQ(stats.trianglesAfter, scene.meshes[0].triangleCount());
    return stats.trianglesAfter;
  };
  uint64_t near = keptAt(2.5f), far = keptAt(40.0f);
  EXPECT_LT(far, near);
  EXPECT_LT(far, makeUvSphere(1.0f, 128, 64).triangleCount() / 4);
}

// --lod auto's chain: each level about half the triangles of the one before,
// over the mesh's own vertices, with errors that only rise.
TEST(LevelOfDetail, ChainHalvesTrianglesWithRisingErrors) {
  Mesh sphere = makeUvSphere(1.0f, 128, 64);
  std::vector<MeshLevel> levels = simplifiedLevels(sphere);
  ASSERT_GE(levels.size(), 4u);
  size_t previousTriangles = sphere.indices.size() / 3;
  float previousError = 0.0f;
  for (const MeshLevel& level : levels) {
    size_t triangles = level.indices.size() / 3;
    EXPECT_EQ(level.indices.size() % 3, 0u);
    EXPECT_LE(triangles * 10, previousTriangles * 9);  // each level gains at least a tenth
    EXPECT_GE(triangles, 128u);                        // half of the 256 floor at most
    EXPECT_GT(level.error, previousError);
    EXPECT_LT(level.error, 1.0f);  // within the unit sphere's radius
    EXPECT_TRUE(std::all_of(level.indices.begin(), level.indices.end(),
                            [&](uint32_t i) { return i < sphere.vertices.size(); }));
    previousTriangles = triangles;
    previousError = level.error;
  }
  EXPECT_TRUE(simplifiedLevels(Mesh{}).empty());
  EXPECT_TRUE(simplifiedLevels(makeUvSphere(1.0f, 8, 4)).empty());  // too few to halve
}

// The choice: never above the bound; the coarsest within it on a first
// frame; and no switching back and forth for an error near the bound.
TEST(LevelOfDetail, LevelChoiceKeepsTheBoundWithHysteresis) {
  const std::vector<float> errors{0.0f, 0.2f, 0.6f, 1.5f, 4.0f};  // pixels, bound 1
  EXPECT_EQ(chooseLevel(errors, kNoLevel, 1.0f), 2u);
  EXPECT_EQ(chooseLevel(errors, 2, 1.0f), 2u);
  EXPECT_EQ(chooseLevel(errors, 0, 1.0f), 2u);  // coarser: 0.6 is under 0.75 of the bound
  EXPECT_EQ(chooseLevel(errors, 4, 1.0f), 2u);  // 4 px is over: back to the coarsest within
  // Level 2 at 0.9 px fits the bound but not the hysteresis: from level 1 it
  // stays at 1; from 2 it stays at 2; a first frame takes 2.
  const std::vector<float> near{0.0f, 0.3f, 0.9f, 3.0f};
  EXPECT_EQ(chooseLevel(near, 1, 1.0f), 1u);
  EXPECT_EQ(chooseLevel(near, 2, 1.0f), 2u);
  EXPECT_EQ(chooseLevel(near, kNoLevel, 1.0f), 2u);
  // An error wobbling around the bound (an object at the switching
  // distance): at most one switch, whatever the order.
  // Without hysteresis (1) it switches on every frame but the first.
  auto wobbleSwitches = [](float hysteresis, uint32_t& level) {
    uint32_t switches = 0;
    for (int frame = 0; frame < 100; ++frame) {
      float wobble = frame % 2 ? 1.02f : 0.98f;
      const std::vector<float> projected{0.0f, 0.5f * wobble, 1.0f * wobble, 2.0f * wobble};
      uint32_t next = chooseLevel(projected, level, 1.0f, hysteresis);
      switches += level != kNoLevel && next != level;
      level = next;
    }
    return switches;
  };
  uint32_t level = kNoLevel;
  EXPECT_LE(wobbleSwitches(kLodHysteresis, level), 1u);
  EXPECT_EQ(level, 1u);
  level = kNoLevel;
  EXPECT_EQ(wobbleSwitches(1.0f, level), 99u);
  // Any previous level, any rising errors: the chosen one is within the bound.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> step(0.0f, 1.0f);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<float> projected{0.0f};
    for (int i = 0; i < 5; ++i) projected.push_back(projected.back() + step(random));
    uint32_t previous = uint32_t(random() % 7);  // 6: no such level, as kNoLevel
    uint32_t chosen = chooseLevel(projected, previous, 1.0f);
    ASSERT_LT(chosen, projected.size());
    EXPECT_LE(projected[chosen], 1.0f) << trial;
  }
}

// A procedural shape's chain: half the tessellation each time, down to its
// kind's coarsest, with the chord error --tess auto bounds rising.
TEST(LevelOfDetail, ShapeChainHalvesTessellationWithRisingErrors) {
  ShapeDesc sphere{.kind = ShapeKind::UvSphere, .radius = 2.0f, .tessellation = 64};
  std::vector<ShapeLevel> levels = tessellationLevels(sphere);
  ASSERT_EQ(levels.size(), 4u);  // 32, 16, 8, 4
  float previous = 0.0f;
  uint32_t tessellation = 64;
  for (const ShapeLevel& level : levels) {
    EXPECT_EQ(level.shape.tessellation, tessellation / 2);
    tessellation = level.shape.tessellation;
    EXPECT_GT(level.error, previous);
    // The level's error is the bound --tess auto would choose it for (up
    // to float rounding at the exact boundary).
    EXPECT_LE(segmentsForChordError(2.0f, level.error * 1.0001f), tessellation);
    previous = level.error;
  }
  EXPECT_NEAR(levels[0].error, 2.0f * (1.0f - std::cos(3.14159265f / 32.0f)), 1e-6f);
  ShapeDesc icosphere{.kind = ShapeKind::Icosphere, .radius = 1.0f, .tessellation = 3};
  ASSERT_EQ(tessellationLevels(icosphere).size(), 3u);  // levels 2, 1, 0
  EXPECT_EQ(tessellationLevels(icosphere).back().shape.tessellation, 0u);
  ShapeDesc teapot{.kind = ShapeKind::Teapot, .tessellation = 8};
  EXPECT_EQ(tessellationLevels(teapot).size(), 3u);  // 4, 2, 1
  EXPECT_TRUE(tessellationLevels({.kind = ShapeKind::Box}).empty());
  EXPECT_TRUE(tessellationLevels({.kind = ShapeKind::Plane, .tessellation = 64}).empty());
  EXPECT_TRUE(tessellationLevels({.kind = ShapeKind::Custom}).empty());
}

// The octahedral map and its inverse agree over the sphere; every direction
// falls in a cell whose direction is within the parallax angle of it, and
// the angle shrinks as cells are added (about 1/cells).
TEST(Impostor, OctahedralCellsCoverTheSphereWithinTheParallaxAngle) {
  std::mt19937 random(7);
  std::normal_distribution<float> normal;
  for (uint32_t cells : {4u, 16u}) {
    float angle = impostorParallaxAngle(cells);
    for (int i = 0; i < 4000; ++i) {
      glm::vec3 d = glm::normalize(glm::vec3(normal(random), normal(random), normal(random)));
      glm::vec3 back = octahedralDecode(octahedralEncode(d));
      ASSERT_NEAR(glm::length(back - d), 0.0f, 1e-5f) << d.x << "," << d.y << "," << d.z;
      ImpostorCell cell = impostorCell(d, cells);
      ASSERT_LT(cell.column, cells);
      ASSERT_LT(cell.row, cells);
      glm::vec3 captured = impostorCellDirection(cell, cells);
      EXPECT_LE(std::acos(std::clamp(glm::dot(d, captured), -1.0f, 1.0f)), angle * 1.0001f);
      // A cell's own direction falls in that cell.
      ImpostorCell again = impostorCell(captured, cells);
      EXPECT_EQ(again.index(cells), cell.index(cells));
    }
  }
  float a4 = impostorParallaxAngle(4), a16 = impostorParallaxAngle(16);
  std::printf("parallax angle: 4 cells %.2f deg, 16 cells %.2f deg\n", double(glm::degrees(a4)),
              double(glm::degrees(a16)));
  EXPECT_GT(a4, 3.0f * a16);
  EXPECT_LT(a16, glm::radians(15.5f));
  // The poles: +y encodes to the centre, -y to the corners; neither is a
  // cell's direction, and every cell has a right-handed frame.
  EXPECT_EQ(octahedralEncode(glm::vec3(0, 1, 0)), glm::vec2(0.0f));
  EXPECT_EQ(glm::abs(octahedralEncode(glm::vec3(0, -1, 0))), glm::vec2(1.0f));
  for (uint32_t index = 0; index < 16 * 16; ++index) {
    glm::vec3 d = impostorCellDirection({index % 16, index / 16}, 16);
    ImpostorFrame frame = impostorFrame(d);
    EXPECT_NEAR(glm::dot(glm::cross(frame.right, frame.up), d), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(frame.right, d), 0.0f, 1e-5f);
  }
}

// The blend: three cells with weights from 0 to 1 summing to 1; a view from
// a cell's own direction takes that cell alone; the weights move little when
// the view does (no jump between cells); and the weighted angle stays within
// impostorBlendAngle, itself within the nearest cell's angle.
TEST(Impostor, BlendWeighsThreeCellsContinuously) {
  std::mt19937 random(11);
  std::normal_distribution<float> normal;
  for (uint32_t cells : {4u, 16u}) {
    float blendAngle = impostorBlendAngle(cells);
    EXPECT_LE(blendAngle, impostorParallaxAngle(cells) * 1.0001f);
    auto weightOf = [&](const ImpostorBlend& blend, uint32_t index) {
      float sum = 0.0f;
      for (size_t k = 0; k < 3; ++k)
        if (blend.cells[k].index(cells) == index) sum += blend.weights[k];
      return sum;
    };
    for (int i = 0; i < 2000; ++i) {
      glm::vec3 d = glm::normalize(glm::vec3(normal(random), normal(random), normal(random)));
      ImpostorBlend blend = impostorBlend(d, cells);
      float sum = 0.0f, angle = 0.0f;
      for (size_t k = 0; k < 3; ++k) {
        ASSERT_GE(blend.weights[k], -1e-6f);
        ASSERT_LE(blend.weights[k], 1.0f + 1e-6f);
        ASSERT_LT(blend.cells[k].column, cells);
        ASSERT_LT(blend.cells[k].row, cells);
        sum += blend.weights[k];
        angle += blend.weights[k] *
                 std::acos(std::clamp(glm::dot(d, impostorCellDirection(blend.cells[k], cells)),
                                      -1.0f, 1.0f));
      }
      EXPECT_NEAR(sum, 1.0f, 1e-5f);
      EXPECT_LE(angle, blendAngle * 1.0001f);
      // A nudge of 0.001 rad changes no cell's weight by more than a few
      // hundredths (the nearest cell alone would jump from 0 to 1). Views
      // from above the horizon: below it the map's outer edge wraps round.
      if (d.y < 0.0f) continue;
      glm::vec3 nudged =
          glm::normalize(d + 0.001f * glm::normalize(glm::cross(d, glm::vec3(0.3f, 1, 0.2f))));
      ImpostorBlend next = impostorBlend(nudged, cells);
      for (size_t k = 0; k < 3; ++k) {
        uint32_t index = next.cells[k].index(cells);
        EXPECT_NEAR(weightOf(next, index), weightOf(blend, index), 0.05f)
            << cells << " cells, direction " << d.x << "," << d.y << "," << d.z;
      }
    }
    for (uint32_t index = 0; index < cells * cells; ++index) {
      ImpostorCell cell{index % cells, index / cells};
      ImpostorBlend own = impostorBlend(impostorCellDirection(cell, cells), cells);
      EXPECT_NEAR(weightOf(own, index), 1.0f, 1e-4f) << index;
    }
  }
  std::printf("blend angle: 4 cells %.2f deg, 16 cells %.2f deg\n",
              double(glm::degrees(impostorBlendAngle(4))),
              double(glm::degrees(impostorBlendAngle(16))));
}

// The error the chain ranks an impostor by: the parallax part radius *
// sin(angle) plus half a texel, linear in the radius.
TEST(Impostor, ErrorIsParallaxPlusHalfATexel) {
  float r = 2.0f;
  float expected = r * std::sin(impostorParallaxAngle(16)) + impostorHalfSize(r, 32) / 32.0f;
  EXPECT_NEAR(impostorError(r, 16, 32), expected, 1e-5f);
  EXPECT_NEAR(impostorError(2.0f * r, 16, 32), 2.0f * expected, 1e-5f);
  EXPECT_GT(impostorHalfSize(r, 32), r);  // the margin
}

}  // namespace
}  // namespace shadelab
