#include "core/mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace shadelab {

namespace {

const glm::vec3 kFallbackNormal{0.0f, 1.0f, 0.0f};

// Scaling by the largest component first keeps tiny non-zero vectors from underflowing to NaN.
glm::vec3 safeNormalize(glm::vec3 v, glm::vec3 fallback) {
    const float largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(largest > 0.0f) || !std::isfinite(largest)) {
        return fallback;
    }
    v /= largest;
    return v / std::sqrt(glm::dot(v, v));
}

glm::vec3 anyPerpendicular(glm::vec3 n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    return glm::normalize(axis - n * glm::dot(n, axis));
}

struct TangentSums {
    std::vector<glm::vec3> alongU;
    std::vector<glm::vec3> alongV;
};

// Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh" (2001): solve
// [e1 e2] = [dP/du dP/dv] * [[s1 s2] [t1 t2]] for the two surface derivatives of each triangle.
TangentSums accumulateTriangleTangents(const Mesh& mesh) {
    TangentSums sums{std::vector<glm::vec3>(mesh.vertices.size(), glm::vec3(0.0f)),
                     std::vector<glm::vec3>(mesh.vertices.size(), glm::vec3(0.0f))};
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const uint32_t ia = mesh.indices[i];
        const uint32_t ib = mesh.indices[i + 1];
        const uint32_t ic = mesh.indices[i + 2];
        assert(ia < mesh.vertices.size() && ib < mesh.vertices.size() && ic < mesh.vertices.size());
        const Vertex& a = mesh.vertices[ia];
        const Vertex& b = mesh.vertices[ib];
        const Vertex& c = mesh.vertices[ic];

        const glm::vec3 e1 = b.position - a.position;
        const glm::vec3 e2 = c.position - a.position;
        const glm::vec2 d1 = b.uv - a.uv;
        const glm::vec2 d2 = c.uv - a.uv;
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (det == 0.0f) {
            continue;
        }
        const float r = 1.0f / det;
        const glm::vec3 dpdu = (e1 * d2.y - e2 * d1.y) * r;
        const glm::vec3 dpdv = (e2 * d1.x - e1 * d2.x) * r;
        if (!std::isfinite(glm::dot(dpdu, dpdu)) || !std::isfinite(glm::dot(dpdv, dpdv))) {
            continue;
        }
        for (const uint32_t index : {ia, ib, ic}) {
            sums.alongU[index] += dpdu;
            sums.alongV[index] += dpdv;
        }
    }
    return sums;
}

}  // namespace

void computeNormals(Mesh& mesh) {
    assert(mesh.indices.size() % 3 == 0);
    std::vector<glm::vec3> sums(mesh.vertices.size(), glm::vec3(0.0f));
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const uint32_t ia = mesh.indices[i];
        const uint32_t ib = mesh.indices[i + 1];
        const uint32_t ic = mesh.indices[i + 2];
        assert(ia < sums.size() && ib < sums.size() && ic < sums.size());
        const glm::vec3 a = mesh.vertices[ia].position;
        // The unnormalised cross product has length 2 * area, which is what weights by area.
        const glm::vec3 face = glm::cross(mesh.vertices[ib].position - a, mesh.vertices[ic].position - a);
        sums[ia] += face;
        sums[ib] += face;
        sums[ic] += face;
    }
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        mesh.vertices[v].normal = safeNormalize(sums[v], kFallbackNormal);
    }
}

void computeTangents(Mesh& mesh) {
    assert(mesh.indices.size() % 3 == 0);
    const TangentSums sums = accumulateTriangleTangents(mesh);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        Vertex& vertex = mesh.vertices[v];
        const glm::vec3 n = safeNormalize(vertex.normal, kFallbackNormal);
        const glm::vec3 projected = sums.alongU[v] - n * glm::dot(n, sums.alongU[v]);
        glm::vec3 t = safeNormalize(projected, glm::vec3(0.0f));
        if (t == glm::vec3(0.0f)) {
            t = anyPerpendicular(n);
        }
        // Mirrored UVs make dP/dv point against cross(n, t); the shader flips the bitangent by w.
        const float w = glm::dot(glm::cross(n, t), sums.alongV[v]) < 0.0f ? -1.0f : 1.0f;
        vertex.tangent = glm::vec4(t, w);
    }
}

Bounds computeBounds(const Mesh& mesh) {
    if (mesh.vertices.empty()) {
        return Bounds{};
    }
    Bounds bounds{mesh.vertices.front().position, mesh.vertices.front().position};
    for (const Vertex& vertex : mesh.vertices) {
        bounds.min = glm::min(bounds.min, vertex.position);
        bounds.max = glm::max(bounds.max, vertex.position);
    }
    return bounds;
}

void appendMesh(Mesh& mesh, const Mesh& other) {
    if (&mesh == &other) {
        const Mesh copy = other;  // inserting a vector's own range into itself is undefined
        appendMesh(mesh, copy);
        return;
    }
    assert(mesh.vertices.size() + other.vertices.size() <= std::numeric_limits<uint32_t>::max());
    const auto offset = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin(), other.vertices.end());
    mesh.indices.reserve(mesh.indices.size() + other.indices.size());
    for (const uint32_t index : other.indices) {
        mesh.indices.push_back(index + offset);
    }
}

}  // namespace shadelab
