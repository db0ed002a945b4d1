#!/usr/bin/env python3
"""Writes the tiny hand-made glTF files of tests/data (run from anywhere;
the output is committed, so tests need no Python). Each file covers one
feature of the loader; bad/ holds one defect per file."""
import base64, json, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def floats(values):
    return struct.pack("<%df" % len(values), *values)


def png(width, height, rgba):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    rows = b"".join(b"\0" + bytes(rgba[y * width * 4:(y + 1) * width * 4]) for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


class Builder:
    """One buffer; accessors appended as bufferViews of it."""

    def __init__(self):
        self.data = b""
        self.doc = {"asset": {"version": "2.0", "generator": "shadelab make_test_gltf.py"},
                    "buffers": [], "bufferViews": [], "accessors": []}

    def accessor(self, payload, count, kind, component=5126, minmax=None):
        while len(self.data) % 4:
            self.data += b"\0"
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)})
        self.data += payload
        accessor = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": component,
                    "count": count, "type": kind}
        if minmax:
            accessor["min"], accessor["max"] = minmax
        self.doc["accessors"].append(accessor)
        return len(self.doc["accessors"]) - 1

    def positions(self, points):
        flat = [c for p in points for c in p]
        lo = [min(p[i] for p in points) for i in range(3)]
        hi = [max(p[i] for p in points) for i in range(3)]
        return self.accessor(floats(flat), len(points), "VEC3", minmax=(lo, hi))

    def finish(self, name, external=None):
        if external:
            self.doc["buffers"] = [{"byteLength": len(self.data), "uri": external}]
            open(os.path.join(HERE, external), "wb").write(self.data)
        else:
            uri = "data:application/octet-stream;base64," + base64.b64encode(self.data).decode()
            self.doc["buffers"] = [{"byteLength": len(self.data), "uri": uri}]
        with open(os.path.join(HERE, name), "w") as out:
            json.dump(self.doc, out, indent=1)
            out.write("\n")
        return self.doc


TRIANGLE = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
UP = [(0, 0, 1)] * 3


def triangle_mesh(b, indexed=True):
    prim = {"attributes": {"POSITION": b.positions(TRIANGLE), "NORMAL": b.accessor(floats([c for n in UP for c in n]), 3, "VEC3")}}
    if indexed:
        prim["indices"] = b.accessor(struct.pack("<3H", 0, 1, 2), 3, "SCALAR", 5123)
    return prim


def hierarchy():
    # root: translate (10, 0, 0); child: rotate 90 degrees about z, scale 2;
    # grandchild: a column-major matrix translating (0, 0, 5). Each draws the triangle.
    b = Builder()
    b.doc["meshes"] = [{"name": "tri", "primitives": [triangle_mesh(b)]}]
    s = 0.5 ** 0.5
    b.doc["nodes"] = [
        {"name": "root", "translation": [10, 0, 0], "mesh": 0, "children": [1]},
        {"name": "child", "rotation": [0, 0, s, s], "scale": [2, 2, 2], "mesh": 0, "children": [2]},
        {"name": "grandchild", "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1], "mesh": 0},
    ]
    b.doc["scenes"] = [{"nodes": [0]}]
    b.doc["scene"] = 0
    b.finish("hierarchy.gltf")


def non_indexed():
    # A quad as 6 unindexed vertices, no normals (flat ones are computed), in an external .bin.
    b = Builder()
    quad = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 0, 0), (1, 1, 0), (0, 1, 0)]
    b.doc["meshes"] = [{"primitives": [{"attributes": {"POSITION": b.positions(quad)}}]}]
    b.doc["nodes"] = [{"mesh": 0}]
    b.doc["scenes"] = [{"nodes": [0]}]
    b.finish("non_indexed.gltf", external="non_indexed.bin")


def strip_fan():
    b = Builder()
    strip = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]  # two counter-clockwise triangles
    fan = [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1), (-1, 1, 1)]  # three, around vertex 0
    normals = lambda n: b.accessor(floats([0, 0, 1] * n), n, "VEC3")
    b.doc["meshes"] = [{"name": "strip and fan", "primitives": [
        {"attributes": {"POSITION": b.positions(strip), "NORMAL": normals(4)}, "mode": 5},
        {"attributes": {"POSITION": b.positions(fan), "NORMAL": normals(5)}, "mode": 6},
        {"attributes": {"POSITION": b.positions(strip)}, "mode": 1},  # lines: not drawn
    ]}]
    b.doc["nodes"] = [{"mesh": 0}]
    b.doc["scenes"] = [{"nodes": [0]}]
    b.finish("strip_fan.gltf")


def textured():
    # A quad with UVs, a 2x2 sRGB base colour texture (clamp / mirrored repeat, nearest)
    # and a 1x1 normal map with scale 0.5 and no TANGENT attribute (generated).
    b = Builder()
    quad = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    prim = {"attributes": {
        "POSITION": b.positions(quad),
        "NORMAL": b.accessor(floats([0, 0, 1] * 4), 4, "VEC3"),
        "TEXCOORD_0": b.accessor(floats([0, 1, 1, 1, 1, 0, 0, 0]), 4, "VEC2")},
        "indices": b.accessor(struct.pack("<6H", 0, 1, 2, 0, 2, 3), 6, "SCALAR", 5123),
        "material": 0}
    colour = png(2, 2, [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255])
    normal = png(1, 1, [128, 128, 255, 255])
    b.doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(colour).decode()},
                       {"uri": "data:image/png;base64," + base64.b64encode(normal).decode()}]
    b.doc["samplers"] = [{"wrapS": 33071, "wrapT": 33648, "magFilter": 9728, "minFilter": 9984}]
    b.doc["textures"] = [{"source": 0, "sampler": 0}, {"source": 1}]
    b.doc["materials"] = [{"name": "checker", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": 0}, "baseColorFactor": [1, 1, 1, 0.25],
        "metallicFactor": 0.0, "roughnessFactor": 0.5},
        "normalTexture": {"index": 1, "scale": 0.5}, "alphaMode": "BLEND",
        "emissiveFactor": [0.1, 0.2, 0.3]}]
    b.doc["meshes"] = [{"primitives": [prim]}]
    b.doc["nodes"] = [{"mesh": 0}]
    b.doc["scenes"] = [{"nodes": [0]}]
    b.finish("textured.gltf")


def lights_camera():
    # KHR_lights_punctual point, directional and spot lights, and an orthographic camera
    # at (0, 0, 5) looking down -z.
    b = Builder()
    b.doc["meshes"] = [{"primitives": [triangle_mesh(b)]}]
    b.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    b.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "point", "color": [1, 0.5, 0.25], "intensity": 20, "range": 10},
        {"type": "directional", "intensity": 2},
        {"type": "spot", "intensity": 5, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}}]}}
    b.doc["cameras"] = [{"type": "orthographic",
                         "orthographic": {"xmag": 2, "ymag": 1.5, "znear": 0.5, "zfar": 20}}]
    b.doc["nodes"] = [
        {"mesh": 0},
        {"translation": [0, 3, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"rotation": [-0.5 ** 0.5, 0, 0, 0.5 ** 0.5], "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"translation": [1, 1, 1], "extensions": {"KHR_lights_punctual": {"light": 2}}},
        {"translation": [0, 0, 5], "camera": 0},
    ]
    b.doc["scenes"] = [{"nodes": [0, 1, 2, 3, 4]}]
    b.finish("lights_camera.gltf")


def glb(doc_builder, name):
    b = doc_builder
    b.doc["buffers"] = [{"byteLength": len(b.data)}]
    text = json.dumps(b.doc).encode()
    text += b" " * (-len(text) % 4)
    data = b.data + b"\0" * (-len(b.data) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + data
    with open(os.path.join(HERE, name), "wb") as out:
        out.write(struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body)


def binary():
    b = Builder()
    b.doc["meshes"] = [{"primitives": [triangle_mesh(b)]}]
    b.doc["nodes"] = [{"mesh": 0}]
    b.doc["scenes"] = [{"nodes": [0]}]
    glb(b, "triangle.glb")


def bad():
    def tri(external=None):
        b = Builder()
        b.doc["meshes"] = [{"primitives": [triangle_mesh(b)]}]
        b.doc["nodes"] = [{"mesh": 0}]
        b.doc["scenes"] = [{"nodes": [0]}]
        return b
    b = tri(); b.doc["accessors"][0]["count"] = 300; b.finish("bad/accessor_past_buffer.gltf")
    # Sizes whose products and sums wrap 64 bits.
    b = tri(); b.doc["accessors"][0]["count"] = 6148914691236517206
    b.finish("bad/accessor_count_overflow.gltf")
    b = tri(); b.doc["accessors"][0]["byteOffset"] = 2**64 - 8
    b.finish("bad/accessor_offset_overflow.gltf")
    b = tri(); b.doc["bufferViews"][0]["byteOffset"] = 2**64 - 1
    b.finish("bad/bufferview_offset_overflow.gltf")
    b = tri(); b.finish("bad/missing_buffer.gltf", external="does_not_exist.bin")
    os.remove(os.path.join(HERE, "does_not_exist.bin"))  # written beside data/, absent from bad/
    b = tri(); b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    b.finish("bad/required_extension.gltf")
    b = tri(); b.doc["accessors"][2]["count"] = 2; b.finish("bad/zero_triangles.gltf")
    b = Builder()
    prim = triangle_mesh(b, indexed=False)
    prim["indices"] = b.accessor(struct.pack("<3H", 0, 1, 7), 3, "SCALAR", 5123)
    b.doc["meshes"] = [{"primitives": [prim]}]; b.doc["nodes"] = [{"mesh": 0}]
    b.finish("bad/index_out_of_range.gltf")
    b = tri()
    b.doc["meshes"][0]["primitives"][0]["material"] = 0
    b.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    b.doc["textures"] = [{"source": 0}]
    b.doc["images"] = [{"uri": "no_such_image.png"}]
    b.finish("bad/missing_image.gltf")
    # A texture on uv set 0 of a primitive with no TEXCOORD_0.
    b = tri()
    b.doc["meshes"][0]["primitives"][0]["material"] = 0
    b.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    b.doc["textures"] = [{"source": 0}]
    b.doc["images"] = [embed_png(2, 2, bytes([255, 0, 0, 255]) * 4)]
    b.finish("bad/texcoord_missing.gltf")
    text = open(os.path.join(HERE, "hierarchy.gltf")).read()
    open(os.path.join(HERE, "bad/syntax_error.gltf"), "w").write(text.replace('"nodes": [', '"nodes": [,', 1))
    whole = open(os.path.join(HERE, "triangle.glb"), "rb").read()
    open(os.path.join(HERE, "bad/truncated.glb"), "wb").write(whole[:len(whole) // 2])


def quad_primitive(b, corners, normal, uvs, material, extra_uvs=None):
    """A quad (two counter-clockwise triangles seen from `normal`'s side)."""
    attributes = {
        "POSITION": b.positions(corners),
        "NORMAL": b.accessor(floats(list(normal) * 4), 4, "VEC3"),
        "TEXCOORD_0": b.accessor(floats([c for uv in uvs for c in uv]), 4, "VEC2")}
    if extra_uvs:
        attributes["TEXCOORD_1"] = b.accessor(floats([c for uv in extra_uvs for c in uv]), 4, "VEC2")
    return {"attributes": attributes,
            "indices": b.accessor(struct.pack("<6H", 0, 1, 2, 0, 2, 3), 6, "SCALAR", 5123),
            "material": material}


QUAD_UVS = [(0, 1), (1, 1), (1, 0), (0, 0)]  # glTF v down the image


def embed_png(width, height, rgba):
    return {"uri": "data:image/png;base64," + base64.b64encode(png(width, height, rgba)).decode()}


def camera_and_sun(b, eye, sun_rotation, camera_rotation=(0, 0, 0, 1)):
    """A perspective camera at `eye` looking down its -z, and a directional light."""
    b.doc["extensionsUsed"] = ["KHR_lights_punctual"]
    b.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "intensity": 1}]}}
    b.doc["cameras"] = [{"type": "perspective",
                         "perspective": {"yfov": 0.8, "aspectRatio": 4 / 3, "znear": 0.1, "zfar": 50}}]
    return [{"translation": list(eye), "rotation": list(camera_rotation), "camera": 0},
            {"rotation": sun_rotation, "extensions": {"KHR_lights_punctual": {"light": 0}}}]


def alpha_mask():
    # alphaMode MASK: a 4x4 checker of alpha 0 and 1 (nearest) on a quad standing
    # over a grey floor, cut-off 0.5; the sun throws the quad's shadow, with its
    # holes, onto the floor.
    b = Builder()
    floor = quad_primitive(b, [(-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, -3)], (0, 1, 0), QUAD_UVS, 0)
    wall = quad_primitive(b, [(-1, 0.5, 0), (1, 0.5, 0), (1, 2.5, 0), (-1, 2.5, 0)], (0, 0, 1), QUAD_UVS, 1)
    checker = []
    for y in range(4):
        for x in range(4):
            checker += [230, 120, 40, 255 if (x + y) % 2 == 0 else 0]
    b.doc["images"] = [embed_png(4, 4, checker)]
    b.doc["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]
    b.doc["textures"] = [{"source": 0, "sampler": 0}]
    b.doc["materials"] = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                                   "metallicFactor": 0, "roughnessFactor": 1}},
        {"name": "cut-out", "alphaMode": "MASK", "alphaCutoff": 0.5, "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}, "metallicFactor": 0, "roughnessFactor": 1}}]
    b.doc["meshes"] = [{"primitives": [floor]}, {"primitives": [wall]}]
    s = 0.5 ** 0.5
    # The sun in front (turned -45 degrees about x: shining down and away from
    # the camera), so the holed shadow falls on the floor behind the quad; the
    # camera above, looking down 25 degrees, sees it through the holes and beside.
    b.doc["nodes"] = [{"mesh": 0}, {"mesh": 1}] + camera_and_sun(
        b, (0, 4, 6), [-0.3826834323650898, 0, 0, 0.9238795325112867],
        [-0.21643961393810288, 0, 0, 0.9762960071199334])
    b.doc["scenes"] = [{"nodes": [0, 1, 2, 3]}]
    b.finish("alpha_mask.gltf")


def alpha_blend():
    # alphaMode BLEND: a quad whose 4x4 texture's alpha rises across it (0, 85,
    # 170, 255 by column, nearest) at a factor alpha of 0.8, standing in front
    # of a blue wall over a grey floor: the wall shows through by 1 - 0.8 x the
    # texel's alpha.
    b = Builder()
    floor = quad_primitive(b, [(-3, 0, 3), (3, 0, 3), (3, 0, -3), (-3, 0, -3)], (0, 1, 0), QUAD_UVS, 0)
    wall = quad_primitive(b, [(-3, 0, -2), (3, 0, -2), (3, 3, -2), (-3, 3, -2)], (0, 0, 1), QUAD_UVS, 1)
    pane = quad_primitive(b, [(-1, 0.5, 0), (1, 0.5, 0), (1, 2.5, 0), (-1, 2.5, 0)], (0, 0, 1), QUAD_UVS, 2)
    ramp = []
    for y in range(4):
        for x in range(4):
            ramp += [230, 120, 40, 85 * x]
    b.doc["images"] = [embed_png(4, 4, ramp)]
    b.doc["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]
    b.doc["textures"] = [{"source": 0, "sampler": 0}]
    b.doc["materials"] = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1],
                                                   "metallicFactor": 0, "roughnessFactor": 1}},
        {"name": "wall", "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.2, 0.8, 1],
                                                  "metallicFactor": 0, "roughnessFactor": 1}},
        {"name": "pane", "alphaMode": "BLEND", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}, "baseColorFactor": [1, 1, 1, 0.8],
            "metallicFactor": 0, "roughnessFactor": 1}}]
    b.doc["meshes"] = [{"primitives": [floor]}, {"primitives": [wall]}, {"primitives": [pane]}]
    b.doc["nodes"] = [{"mesh": 0}, {"mesh": 1}, {"mesh": 2}] + camera_and_sun(
        b, (0, 2, 6), [-0.3826834323650898, 0, 0, 0.9238795325112867],
        [-0.0871557427476582, 0, 0, 0.9961946980917455])
    b.doc["scenes"] = [{"nodes": [0, 1, 2, 3, 4]}]
    b.finish("alpha_blend.gltf")


def double_sided():
    # Two quads whose front faces look away from the camera (normal -z), lit
    # by a sun behind the camera: the left one doubleSided (drawn, its back lit
    # with the flipped normal), the right one not (culled).
    b = Builder()
    left = quad_primitive(b, [(-0.2, -1, 0), (-2.2, -1, 0), (-2.2, 1, 0), (-0.2, 1, 0)], (0, 0, -1), QUAD_UVS, 0)
    right = quad_primitive(b, [(2.2, -1, 0), (0.2, -1, 0), (0.2, 1, 0), (2.2, 1, 0)], (0, 0, -1), QUAD_UVS, 1)
    plastic = {"baseColorFactor": [0.2, 0.5, 0.9, 1], "metallicFactor": 0, "roughnessFactor": 0.4}
    b.doc["materials"] = [{"name": "two-sided", "doubleSided": True, "pbrMetallicRoughness": plastic},
                          {"name": "one-sided", "pbrMetallicRoughness": plastic}]
    b.doc["meshes"] = [{"primitives": [left]}, {"primitives": [right]}]
    # The sun shines along -z, from behind the camera (identity rotation: its -z).
    b.doc["nodes"] = [{"mesh": 0}, {"mesh": 1}] + camera_and_sun(b, (0, 0, 5), [0, 0, 0, 1])
    b.doc["scenes"] = [{"nodes": [0, 1, 2, 3]}]
    b.finish("double_sided.gltf")


def texture_transform():
    # KHR_texture_transform on three quads, each with the 2x2 texture (red,
    # green / blue, white; nearest, repeat):
    #  left: offset (0.5, 0), rotation pi/2, scale (2, 1) on the base colour;
    #  middle: texCoord 1 overrides the textureInfo's 0 (TEXCOORD_0 is all 0);
    #  right: a normal map (left half tilted to +x, right half to -x) shifted
    #  half its width by offset (0.5, 0), so the halves swap.
    b = Builder()
    zeros = [(0, 0)] * 4
    left = quad_primitive(b, [(-3.3, -1, 0), (-1.3, -1, 0), (-1.3, 1, 0), (-3.3, 1, 0)], (0, 0, 1), QUAD_UVS, 0)
    middle = quad_primitive(b, [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], (0, 0, 1), zeros, 1,
                            extra_uvs=QUAD_UVS)
    right = quad_primitive(b, [(1.3, -1, 0), (3.3, -1, 0), (3.3, 1, 0), (1.3, 1, 0)], (0, 0, 1), QUAD_UVS, 2)
    colours = [255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255]
    tilt = 0.6  # the normal's x in the map
    plus = [int(round((tilt + 1) * 127.5)), 128, int(round((1 - tilt * tilt) ** 0.5 * 127.5 + 127.5)), 255]
    minus = [255 - plus[0]] + plus[1:]
    b.doc["images"] = [embed_png(2, 2, colours), embed_png(2, 1, plus + minus)]
    b.doc["samplers"] = [{"magFilter": 9728, "minFilter": 9728}]
    b.doc["textures"] = [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}]
    b.doc["extensionsUsed"] = ["KHR_texture_transform"]
    matte = {"metallicFactor": 0, "roughnessFactor": 1}
    b.doc["materials"] = [
        {"name": "moved", "pbrMetallicRoughness": dict(matte, baseColorTexture={
            "index": 0, "extensions": {"KHR_texture_transform": {
                "offset": [0.5, 0], "rotation": 1.5707963267948966, "scale": [2, 1]}}})},
        {"name": "second set", "pbrMetallicRoughness": dict(matte, baseColorTexture={
            "index": 0, "texCoord": 0, "extensions": {"KHR_texture_transform": {"texCoord": 1}}})},
        {"name": "bumps swapped", "pbrMetallicRoughness": dict(matte, baseColorFactor=[0.8, 0.8, 0.8, 1]),
         "normalTexture": {"index": 1, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0]}}}}]
    b.doc["meshes"] = [{"primitives": [left]}, {"primitives": [middle]}, {"primitives": [right]}]
    # The sun from the left (turned -40 degrees about y), so the tilts show.
    nodes = camera_and_sun(b, (0, 0, 6), [0, -0.3420201433256687, 0, 0.9396926207859084])
    b.doc["extensionsUsed"] = ["KHR_lights_punctual", "KHR_texture_transform"]
    b.doc["nodes"] = [{"mesh": 0}, {"mesh": 1}, {"mesh": 2}] + nodes
    b.doc["scenes"] = [{"nodes": [0, 1, 2, 3, 4]}]
    b.finish("texture_transform.gltf")


def bad_materials():
    # One defect per file in the material fields the loader checks itself.
    def masked(cutoff, name):
        b = Builder()
        b.doc["meshes"] = [{"primitives": [dict(triangle_mesh(b), material=0)]}]
        b.doc["materials"] = [{"alphaMode": "MASK", "alphaCutoff": cutoff}]
        b.doc["nodes"] = [{"mesh": 0}]
        b.doc["scenes"] = [{"nodes": [0]}]
        b.finish(name)
    masked(-0.5, "bad/alpha_cutoff_negative.gltf")
    masked("half", "bad/alpha_cutoff_not_a_number.gltf")

    def transformed(transform, name, replace=None):
        b = Builder()
        b.doc["meshes"] = [{"primitives": [quad_primitive(
            b, [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)], (0, 0, 1), QUAD_UVS, 0)]}]
        b.doc["images"] = [embed_png(1, 1, [255, 255, 255, 255])]
        b.doc["textures"] = [{"source": 0}]
        b.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {
            "index": 0, "extensions": {"KHR_texture_transform": transform}}}}]
        b.doc["nodes"] = [{"mesh": 0}]
        b.doc["scenes"] = [{"nodes": [0]}]
        b.finish(name)
        if replace:  # JSON has no infinity: a number too large for a double stands in
            path = os.path.join(HERE, name)
            text = open(path).read().replace(*replace)
            open(path, "w").write(text)
    # 1e39 is a double but infinite as the float the shaders get; 1e999 is not
    # even a double (the JSON parser refuses it).
    transformed({"scale": [12345.5, 1]}, "bad/texture_transform_infinite.gltf", ("12345.5", "1e39"))
    transformed({"offset": [12345.5, 0]}, "bad/texture_transform_1e999.gltf", ("12345.5", "1e999"))
    transformed({"rotation": "90deg"}, "bad/texture_transform_not_a_number.gltf")


if __name__ == "__main__":
    hierarchy(); non_indexed(); strip_fan(); textured(); lights_camera(); binary(); bad()
    alpha_mask(); alpha_blend(); double_sided(); texture_transform(); bad_materials()
