#include "passes/impostor_capture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <tuple>

#include "core/scene/impostor.h"
#include "core/vulkan/barriers.h"
#include "core/vulkan/shader.h"
#include "core/vulkan/vk_check.h"
#include "passes/graphics_pipeline.h"

namespace shadelab {
namespace {

constexpr VkFormat kAtlasFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kAtlasDepthFormat = VK_FORMAT_D32_SFLOAT;

// impostor_capture.vert's push constants.
struct CaptureConstants {
  glm::mat4 objectToClip;
  glm::vec4 right, up, towardsViewer;
};
static_assert(sizeof(CaptureConstants) == 112);

// Object space to a cell's clip space: an orthographic view from
// centre + 2 radius direction towards the centre, x along the frame's right,
// Vulkan clip y down (so the frame's up is the top row), depth 0..1 over the
// 0.5 .. 3.5 radius in front of the eye that holds the whole sphere.
glm::mat4 cellToClip(glm::vec3 centre, float radius, float halfSize, glm::vec3 direction,
                     const ImpostorFrame& frame) {
  glm::vec3 eye = centre + 2.0f * radius * direction;
  float depthRange = 3.0f * radius;
  glm::mat4 m(0.0f);
  auto row = [&](int r, glm::vec3 axis, float scale, float offset) {
    m[0][r] = axis.x * scale;
    m[1][r] = axis.y * scale;
    m[2][r] = axis.z * scale;
    m[3][r] = -glm::dot(axis, eye) * scale + offset;
  };
  row(0, frame.right, 1.0f / halfSize, 0.0f);
  row(1, frame.up, -1.0f / halfSize, 0.0f);
  row(2, direction, -1.0f / depthRange, -0.5f * radius / depthRange);
  m[3][3] = 1.0f;
  return m;
}

// Uncovered texels (alpha 0) take the mean normal and height of their
// covered 8-neighbours, ring by ring out to the cell's edge, within each
// cell: the mip levels of a far impostor then average its own normals
// rather than the clear's (a normal facing the captured viewer, which
// lit the silhouettes of far copies brighter, cell by cell).
void dilateIntoMargins(Texture& normals, uint32_t cellTexels, uint32_t cells) {
  uint32_t side = cellTexels * cells;
  std::vector<uint8_t> next = normals.rgba8;
  for (uint32_t ring = 0; ring < cellTexels; ++ring) {
    bool changed = false;
    for (uint32_t y = 0; y < side; ++y)
      for (uint32_t x = 0; x < side; ++x) {
        size_t at = 4 * (size_t(y) * side + x);
        if (normals.rgba8[at + 3] != 0) continue;
        uint32_t cellX = x / cellTexels * cellTexels, cellY = y / cellTexels * cellTexels;
        uint32_t sum[4] = {0, 0, 0, 0}, count = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            int nx = int(x) + dx, ny = int(y) + dy;
            if (nx < int(cellX) || ny < int(cellY) || nx >= int(cellX + cellTexels) ||
                ny >= int(cellY + cellTexels))
              continue;
            const uint8_t* neighbour = &normals.rgba8[4 * (size_t(ny) * side + size_t(nx))];
            if (neighbour[3] == 0) continue;
            for (int c = 0; c < 4; ++c) sum[c] += neighbour[c];
            ++count;
          }
        if (count == 0) continue;
        for (int c = 0; c < 4; ++c) next[at + c] = uint8_t((sum[c] + count / 2) / count);
        changed = true;
      }
    normals.rgba8 = next;
    if (!changed) break;
  }
}

}  // namespace

ImpostorCapture::ImpostorCapture(const Context& context) : context_(context) {
  VkDevice device = context.device();
  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(CaptureConstants)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  layout_ = PipelineLayout(device, layout);
  vertex_ = loadShader(device, "impostor_capture.vert");
  fragment_ = loadShader(device, "impostor_capture.frag");
}

ImpostorTextures ImpostorCapture::capture(const GpuScene& scene, const DrawItem& draw,
                                          glm::vec3 centre, float radius, uint32_t cells,
                                          uint32_t cellTexels) const {
  if (!pipeline_) {
    VkPipelineShaderStageCreateInfo stages[2] = {
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex_.get();
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fragment_.get();
    stages[1].pName = "main";
    VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attributes[] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)}};
    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = 1;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = 2;
    vertexInput.pVertexAttributeDescriptions = attributes;
    VkPipelineRasterizationStateCreateInfo raster{
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    // Not culled: the depth test keeps the nearest surface, whichever way it winds.
    raster.cullMode = VK_CULL_MODE_NONE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = VK_TRUE;
    depth.depthWriteEnable = VK_TRUE;
    depth.depthCompareOp = VK_COMPARE_OP_LESS;
    VkPipelineColorBlendAttachmentState blend{};
    blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                           VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    // Built on first use: a scene without detail chains never pays for it.
    pipeline_ = createGraphicsPipeline(context_.device(),
                                       {stages, &vertexInput, &raster, &multisample, &depth, blend,
                                        kAtlasFormat, kAtlasDepthFormat, layout_.get()});
  }
  uint32_t side = cells * cellTexels;
  Image color(context_, {kAtlasFormat, side, side, 1, 1,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
  Image depth(context_, {kAtlasDepthFormat, side, side, 1, 1,
                         VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT});
  Buffer readback(context_, VkDeviceSize(side) * side * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                  MemoryUse::HostVisible);
  float halfSize = impostorHalfSize(radius, cellTexels);
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    imageBarrier(cmd, color.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::Undefined,
                 ImageUse::ColorAttachment);
    imageBarrier(cmd, depth.get(), VK_IMAGE_ASPECT_DEPTH_BIT, ImageUse::Undefined,
                 ImageUse::DepthAttachment);
    VkRenderingAttachmentInfo colorAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    colorAttachment.imageView = color.view();
    colorAttachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colorAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    colorAttachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    // Uncovered texels: no coverage, and a normal facing the viewer, which
    // is what the filtered edge of a silhouette leans towards.
    colorAttachment.clearValue.color = {{0.5f, 0.5f, 1.0f, 0.0f}};
    VkRenderingAttachmentInfo depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depthAttachment.imageView = depth.view();
    depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depthAttachment.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {side, side}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &colorAttachment;
    rendering.pDepthAttachment = &depthAttachment;
    vkCmdBeginRendering(cmd, &rendering);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
    VkBuffer vertices = scene.vertices.get();
    VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
    vkCmdBindIndexBuffer(cmd, scene.indices.get(), 0, VK_INDEX_TYPE_UINT32);
    for (uint32_t row = 0; row < cells; ++row)
      for (uint32_t column = 0; column < cells; ++column) {
        glm::vec3 direction = impostorCellDirection({column, row}, cells);
        ImpostorFrame frame = impostorFrame(direction);
        CaptureConstants constants{cellToClip(centre, radius, halfSize, direction, frame),
                                   glm::vec4(frame.right, 0.0f), glm::vec4(frame.up, 0.0f),
                                   glm::vec4(direction, radius / halfSize)};
        VkViewport viewport{float(column * cellTexels),
                            float(row * cellTexels),
                            float(cellTexels),
                            float(cellTexels),
                            0.0f,
                            1.0f};
        VkRect2D scissor{{int32_t(column * cellTexels), int32_t(row * cellTexels)},
                         {cellTexels, cellTexels}};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdPushConstants(cmd, layout_.get(),
                           VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(constants), &constants);
        vkCmdDrawIndexed(cmd, draw.indexCount, 1, draw.firstIndex, draw.vertexOffset, 0);
      }
    vkCmdEndRendering(cmd);
    imageBarrier(cmd, color.get(), VK_IMAGE_ASPECT_COLOR_BIT, ImageUse::ColorAttachment,
                 ImageUse::TransferSource);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {side, side, 1};
    vkCmdCopyImageToBuffer(cmd, color.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.get(),
                           1, &region);
    transferToHostBarrier(cmd);
  });
  // Covered texels have an alpha of at least 1 (impostor_capture.frag), the
  // clear's is 0: coverage is 255 where the alpha is not 0.
  ImpostorTextures out;
  out.coverage = {"impostor coverage", side, side, std::vector<uint8_t>(size_t(side) * side * 4),
                  true};
  out.normals = {"impostor normals", side, side, std::vector<uint8_t>(size_t(side) * side * 4),
                 false};
  const auto* texels = static_cast<const uint8_t*>(readback.mapped());
  for (size_t i = 0; i < size_t(side) * side; ++i) {
    const uint8_t* texel = texels + 4 * i;
    uint8_t* coverage = &out.coverage.rgba8[4 * i];
    uint8_t* normal = &out.normals.rgba8[4 * i];
    coverage[0] = coverage[1] = coverage[2] = 255;
    coverage[3] = texel[3] > 0 ? 255 : 0;
    std::memcpy(normal, texel, 4);
  }
  dilateIntoMargins(out.normals, side / cells, cells);
  return out;
}

void ImpostorCapture::addImpostors(const Scene& source, GpuScene& scene, uint32_t cells,
                                   uint32_t cellTexels) const {
  if (cells == 0 || cellTexels == 0) return;
  std::map<uint32_t, ImpostorSphere> spheres;  // by mesh
  auto sphereOf = [&](uint32_t mesh) {
    auto found = spheres.find(mesh);
    if (found != spheres.end()) return found->second;
    return spheres[mesh] = impostorSphere(source.meshes[mesh]);
  };
  // An atlas per full index range; a billboard per atlas and material.
  std::map<std::tuple<uint32_t, uint32_t, int32_t>, int32_t> atlases;
  // Keyed by atlas, material numbers and emission bits.
  std::map<std::tuple<int32_t, std::array<float, 11>, int32_t>, uint32_t> billboards;
  // Chains are shared by the draws of one mesh: rebuilt once per (chain, impostor).
  std::map<std::tuple<uint32_t, uint32_t, uint32_t>, uint32_t> chains;
  std::vector<DrawLevel> levels;
  for (DrawItem& draw : scene.draws) {
    uint32_t impostor = DrawLevel::kNoImpostor;
    const Object& object = source.objects[size_t(draw.constants.object.x)];
    ImpostorSphere sphere = sphereOf(object.mesh);
    bool eligible = draw.levelCount > 0 && !draw.textured && !draw.transparent && !draw.masked &&
                    !draw.hidden && object.material.reflectivity == 0.0f &&
                    impostorRadiusUsable(sphere.radius) &&
                    impostorTransformUsable(object.transform);
    auto key = std::make_tuple(draw.firstIndex, draw.indexCount, draw.vertexOffset);
    // A scene of many distinct meshes gets atlases for the first ones only.
    eligible = eligible && (atlases.count(key) > 0 || atlases.size() < kMaxImpostorAtlases);
    if (eligible) {
      auto [atlas, added] = atlases.emplace(key, int32_t(scene.impostorTextures.size() / 2));
      if (added) {
        // The coarsest level of the chain within half a texel looks the
        // same in the atlas as the full mesh and costs a fraction to draw
        // 256 times.
        DrawItem source = draw;
        float halfTexel = impostorHalfSize(sphere.radius, cellTexels) / float(cellTexels);
        for (uint32_t i = 0; i < draw.levelCount; ++i) {
          const DrawLevel& level = scene.levels[draw.firstLevel + i];
          if (level.error > halfTexel) break;
          source.firstIndex = level.firstIndex;
          source.indexCount = level.indexCount;
          source.vertexOffset = level.vertexOffset;
        }
        ImpostorTextures textures =
            capture(scene, source, sphere.centre, sphere.radius, cells, cellTexels);
        scene.impostorTextures.push_back(std::move(textures.coverage));
        scene.impostorTextures.push_back(std::move(textures.normals));
      }
      const gpu::DrawConstants& c = draw.constants;
      std::array<float, 11> material{c.ka.x, c.ka.y, c.ka.z, c.kd.x, c.kd.y,           c.kd.z,
                                     c.ks.x, c.ks.y, c.ks.z, c.ks.w, float(c.object.z)};
      auto [billboard, fresh] = billboards.emplace(
          std::make_tuple(atlas->second, material, c.object.w), uint32_t(scene.billboards.size()));
      if (fresh) {
        GpuBillboard out;
        // The cut-out at half coverage; opaque; the atlas's two maps always.
        out.constants.ka = glm::vec4(glm::vec3(c.ka), 0.5f);
        out.constants.kd = glm::vec4(glm::vec3(c.kd), 1.0f);
        out.constants.ks = c.ks;
        out.constants.object =
            glm::ivec4(0, TEXTURE_DIFFUSE | TEXTURE_NORMAL, c.object.z, c.object.w);
        out.constants.texturing = glm::vec4(1.0f, 1.0f, 1.0f, 0.0f);
        out.constants.optics = glm::vec4(float(BILLBOARD_IMPOSTOR), 0.5f, float(cells), 0.0f);
        out.impostor = {atlas->second, sphere.centre, impostorHalfSize(sphere.radius, cellTexels),
                        cells};
        scene.billboards.push_back(std::move(out));
      }
      impostor = billboard->second;
    }
    auto chainKey = std::make_tuple(draw.firstLevel, draw.levelCount, impostor);
    auto [chain, newChain] = chains.emplace(chainKey, uint32_t(levels.size()));
    if (newChain) {
      for (uint32_t i = 0; i < draw.levelCount; ++i)
        levels.push_back(scene.levels[draw.firstLevel + i]);
      if (impostor != DrawLevel::kNoImpostor) {
        float coarsest = draw.levelCount > 0 ? levels.back().error : 0.0f;
        float error = std::max(impostorError(sphere.radius, cells, cellTexels), coarsest);
        levels.push_back({0, 0, 0, error, impostor});
      }
    }
    draw.firstLevel = chain->second;
    if (impostor != DrawLevel::kNoImpostor) {
      ++draw.levelCount;
      ++scene.impostorDraws;
    }
  }
  scene.levels = std::move(levels);
}

}  // namespace shadelab
