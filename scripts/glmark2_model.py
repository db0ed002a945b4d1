#!/usr/bin/env python3
"""Write a glmark2 .3ds model as a glTF 2.0 file, so shadelab can draw the very
mesh glmark2 benchmarks (scripts/peer_bench.sh uses it for the shading scene's
cat). Only what glmark2's own loader reads is kept: each object's vertex list
(chunk 0x4110) and face list (0x4120). Normals are computed as glmark2
computes them (the normalised sum of the unit normals of the faces around a
vertex); glTF would otherwise ask for flat normals. The material is glmark2's
blue with a highlight about as narrow (Phong exponent ~100).
  scripts/glmark2_model.py IN.3ds OUT.gltf
"""
import base64
import json
import struct
import sys

CONTAINERS = {0x4D4D, 0x3D3D, 0x4100}  # main, editor, triangle mesh: children only
OBJECT, VERTICES, FACES = 0x4000, 0x4110, 0x4120


def fail(message):
    print(f"glmark2_model: {message}", file=sys.stderr)
    sys.exit(2)


def read_objects(data, path):
    """The (vertices, faces) of each object, walking the chunk tree."""
    objects = []
    def need(fits, chunk, offset, what):
        if not fits:
            fail(f"{path}: chunk 0x{chunk:04x} at byte {offset} is too short for {what}")
    def walk(start, end):
        offset = start
        while offset + 6 <= end:
            chunk, length = struct.unpack_from("<HI", data, offset)
            if length < 6 or offset + length > end:
                fail(f"{path}: chunk 0x{chunk:04x} at byte {offset} has length {length}, "
                     f"expected 6..{end - offset}")
            body, stop = offset + 6, offset + length
            if chunk in CONTAINERS:
                walk(body, stop)
            elif chunk == OBJECT:
                name_end = data.index(b"\0", body, stop)
                objects.append(([], []))
                walk(name_end + 1, stop)
            elif chunk == VERTICES and objects:
                (count,) = struct.unpack_from("<H", data, body)
                need(body + 2 + 12 * count <= stop, chunk, offset, f"{count} vertices")
                objects[-1][0].extend(struct.unpack_from(f"<{3 * count}f", data, body + 2))
            elif chunk == FACES and objects:
                (count,) = struct.unpack_from("<H", data, body)
                need(body + 2 + 8 * count <= stop, chunk, offset, f"{count} faces")
                words = struct.unpack_from(f"<{4 * count}H", data, body + 2)
                for f in range(count):  # a, b, c, flags
                    objects[-1][1].extend(words[4 * f:4 * f + 3])
            offset = stop
    walk(0, len(data))
    return [(v, f) for v, f in objects if v and f]


def vertex_normals(vertices, faces):
    """The normalised sum of the unit normals of the faces at each vertex."""
    normals = [0.0] * len(vertices)
    def point(i):
        return vertices[3 * i:3 * i + 3]
    for f in range(0, len(faces), 3):
        a, b, c = (point(i) for i in faces[f:f + 3])
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        length = sum(x * x for x in n) ** 0.5
        if length == 0.0:
            continue
        for i in faces[f:f + 3]:
            for k in range(3):
                normals[3 * i + k] += n[k] / length
    for i in range(0, len(normals), 3):
        length = sum(x * x for x in normals[i:i + 3]) ** 0.5
        normals[i:i + 3] = [x / length for x in normals[i:i + 3]] if length else [0.0, 0.0, 1.0]
    return normals


def main():
    if len(sys.argv) != 3:
        fail("usage: glmark2_model.py IN.3ds OUT.gltf")
    source, target = sys.argv[1], sys.argv[2]
    try:
        data = open(source, "rb").read()
    except OSError as error:
        fail(f"{source}: {error.strerror}")
    try:
        objects = read_objects(data, source)
    except (struct.error, ValueError) as error:  # a count or name running past its chunk
        fail(f"{source}: not a 3DS mesh this reader understands ({error})")
    if not objects:
        fail(f"{source}: no object with vertices and faces (chunks 0x4110, 0x4120)")
    blob, views, accessors, meshes = bytearray(), [], [], []
    for vertices, faces in objects:
        vertex_count = len(vertices) // 3
        if max(faces) >= vertex_count:
            fail(f"{source}: a face refers to vertex {max(faces)} of {vertex_count}")
        xs, ys, zs = vertices[0::3], vertices[1::3], vertices[2::3]
        normals = vertex_normals(vertices, faces)
        for payload, target_kind in ((struct.pack(f"<{len(vertices)}f", *vertices), 34962),
                                     (struct.pack(f"<{len(normals)}f", *normals), 34962),
                                     (struct.pack(f"<{len(faces)}I", *faces), 34963)):
            views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(payload),
                          "target": target_kind})
            blob += payload
        accessors.append({"bufferView": len(views) - 3, "componentType": 5126,
                          "count": vertex_count, "type": "VEC3",
                          "min": [min(xs), min(ys), min(zs)], "max": [max(xs), max(ys), max(zs)]})
        accessors.append({"bufferView": len(views) - 2, "componentType": 5126,
                          "count": vertex_count, "type": "VEC3"})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5125,
                          "count": len(faces), "type": "SCALAR"})
        meshes.append({"primitives": [{"attributes": {"POSITION": len(accessors) - 3,
                                                      "NORMAL": len(accessors) - 2},
                                       "indices": len(accessors) - 1, "material": 0}]})
    gltf = {
        "asset": {"version": "2.0", "generator": "shadelab scripts/glmark2_model.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(meshes)))}],
        "nodes": [{"mesh": m} for m in range(len(meshes))],
        "meshes": meshes,
        # glmark2's MaterialDiffuse; shadelab maps roughness 0.374 to shininess ~100.
        "materials": [{"name": "glmark2 blue", "pbrMetallicRoughness": {
            "baseColorFactor": [0, 0, 1, 1], "metallicFactor": 0, "roughnessFactor": 0.374}}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(bytes(blob)).decode("ascii")}],
    }
    with open(target, "w") as out:
        json.dump(gltf, out)
    triangles = sum(len(f) // 3 for _, f in objects)
    print(f"wrote {target}: {len(objects)} object(s), {triangles} triangles")


if __name__ == "__main__":
    main()
