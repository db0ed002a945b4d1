#!/usr/bin/env python3
"""Writes tests/fuzz/corpus: small glTF and GLB seeds for the loader's fuzz
target (every accessor type and component type, counts and offsets near the
limits that once overflowed, deep nesting, sparse, strided, GLB chunks), and
tests/fuzz/gltf.dict, libFuzzer's dictionary of glTF keys and values. Buffers
are data: URIs or the GLB chunk: the fuzz target reads no files. Run from
anywhere; the output is committed (scripts/fuzz.sh and ctest use it)."""
import base64
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "corpus")

COMPONENTS = {5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4}
TYPES = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}
# Attributes and the types glTF allows for them (the loader must refuse the rest).
ATTRIBUTES = {"POSITION": "VEC3", "NORMAL": "VEC3", "TANGENT": "VEC4", "TEXCOORD_0": "VEC2",
              "COLOR_0": "VEC4"}
NEAR_LIMITS = [0, 1, 2**31 - 1, 2**32 - 1, 2**32, 2**53, 2**62, 6148914691236517206,
               2**63 - 1, 2**64 - 1, 2**64 - 4]


def data_uri(payload):
    return "data:application/octet-stream;base64," + base64.b64encode(payload).decode()


def triangle(position=None, indices=None, extra=None):
    """A one-triangle document; `position`, `indices` override accessor fields."""
    points = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    index_bytes = struct.pack("<3H", 0, 1, 2) + b"\0\0"
    payload = points + index_bytes
    doc = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(payload), "uri": data_uri(payload)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [
            dict({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                  "min": [0, 0, 0], "max": [1, 1, 0]}, **(position or {})),
            dict({"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                 **(indices or {})),
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "scene": 0,
    }
    if extra:
        extra(doc)
    return doc


def attribute_seed(name, kind, component):
    """`name` as an accessor of `kind` x `component`, sized to fit its view."""
    count = 3
    size = count * TYPES[kind] * COMPONENTS[component]
    def add(doc):
        payload = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
        offset = (len(payload) + 3) // 4 * 4
        payload = payload.ljust(offset, b"\0") + bytes(range(size % 256)) + b"\0" * (size - size % 256)
        doc["buffers"][0] = {"byteLength": len(payload), "uri": data_uri(payload)}
        doc["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": size})
        doc["accessors"].append({"bufferView": 2, "componentType": component, "count": count,
                                 "type": kind, "normalized": component not in (5125, 5126)})
        doc["meshes"][0]["primitives"][0]["attributes"][name] = 2
    return triangle(extra=add)


def png(width, height, pixels=True):
    """An RGBA PNG; without pixels, only the header that declares its size."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    header = chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
    rows = b"".join(b"\0" + b"\xff\x80\x00\xff" * width for _ in range(height)) if pixels else b""
    body = chunk(b"IDAT", zlib.compress(rows)) if pixels else b""
    return b"\x89PNG\r\n\x1a\n" + header + body + chunk(b"IEND", b"")


# A JPEG's first segments up to a baseline frame header of 16384 x 16384.
JPEG_HEADER = (b"\xff\xd8\xff\xe0\x00\x10JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00"
               b"\xff\xc0\x00\x11\x08\x40\x00\x40\x00\x03" + b"\x00" * 9)


def image_seed(image=None, in_buffer=None, view=None):
    """A textured triangle (TEXCOORD_0, a material with a base colour texture)
    whose image is `image` (an images[] entry), or `in_buffer` bytes in
    bufferView 3 with `view` overriding that view's fields."""
    def add(doc):
        payload = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
        offset = (len(payload) + 3) // 4 * 4
        payload = payload.ljust(offset, b"\0") + struct.pack("<6f", 0, 0, 1, 0, 0, 1)
        doc["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": 24})
        doc["accessors"].append({"bufferView": 2, "componentType": 5126, "count": 3,
                                 "type": "VEC2"})
        primitive = doc["meshes"][0]["primitives"][0]
        primitive["attributes"]["TEXCOORD_0"] = 2
        primitive["material"] = 0
        doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
        doc["textures"] = [{"source": 0}]
        entry = image
        if in_buffer is not None:
            start = len(payload)
            payload += in_buffer
            doc["bufferViews"].append(dict({"buffer": 0, "byteOffset": start,
                                            "byteLength": len(in_buffer)}, **(view or {})))
            entry = {"bufferView": 3, "mimeType": "image/png"}
        doc["images"] = [entry]
        doc["buffers"][0] = {"byteLength": len(payload), "uri": data_uri(payload)}
    return triangle(extra=add)


def png_uri(data):
    return "data:image/png;base64," + base64.b64encode(data).decode()


def glb(doc):
    """The document as GLB, its buffer moved into the BIN chunk."""
    payload = base64.b64decode(doc["buffers"][0]["uri"].split(",", 1)[1])
    doc = json.loads(json.dumps(doc))
    doc["buffers"][0] = {"byteLength": len(payload)}
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    payload += b"\0" * (-len(payload) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text
    chunks += struct.pack("<II", len(payload), 0x004E4942) + payload
    return b"glTF" + struct.pack("<II", 2, 12 + len(chunks)) + chunks


def seeds():
    yield "triangle.gltf", triangle()
    for name, kind in ATTRIBUTES.items():
        if name == "POSITION":
            continue
        for component in COMPONENTS:
            yield f"attr_{name.lower()}_{component}.gltf", attribute_seed(name, kind, component)
    for kind in TYPES:  # every type, including the matrices no attribute may use
        yield f"type_{kind.lower()}.gltf", attribute_seed("TEXCOORD_0", kind, 5126)
    for component in (5121, 5123, 5125):
        yield f"indices_{component}.gltf", triangle(indices={"componentType": component})
    for i, value in enumerate(NEAR_LIMITS):
        yield f"position_count_{i}.gltf", triangle(position={"count": value})
        yield f"position_offset_{i}.gltf", triangle(position={"byteOffset": value})
        yield f"indices_count_{i}.gltf", triangle(indices={"count": value})
        yield f"view_offset_{i}.gltf", triangle(
            extra=lambda doc, v=value: doc["bufferViews"][0].update(byteOffset=v))
        yield f"view_stride_{i}.gltf", triangle(
            extra=lambda doc, v=value: doc["bufferViews"][0].update(byteStride=v))
    yield "strided.gltf", triangle(extra=lambda doc: doc["bufferViews"][0].update(byteStride=12))
    yield "sparse.gltf", triangle(position={"sparse": {
        "count": 1, "indices": {"bufferView": 1, "componentType": 5123},
        "values": {"bufferView": 0}}})
    yield "no_view.gltf", triangle(position={"bufferView": None})
    deep = {}
    for _ in range(300):
        deep = {"a": [deep]}
    yield "deep_extras.gltf", triangle(extra=lambda doc: doc.update(extras=deep))
    chain = [{"children": [i + 1]} for i in range(63)] + [{"mesh": 0}]
    yield "deep_nodes.gltf", triangle(extra=lambda doc: doc.update(nodes=chain))
    yield "cycle.gltf", triangle(extra=lambda doc: doc.update(nodes=[{"children": [0], "mesh": 0}]))
    # Images: embedded as data URIs and in bufferViews, sizes declared in
    # headers past the 8192 limit, views past their buffer, not PNG at all.
    yield "image_uri.gltf", image_seed({"uri": png_uri(png(2, 2))})
    yield "image_uri_huge.gltf", image_seed({"uri": png_uri(png(16384, 16384, pixels=False))})
    yield "image_uri_jpeg_huge.gltf", image_seed(
        {"uri": "data:image/jpeg;base64," + base64.b64encode(JPEG_HEADER).decode()})
    yield "image_uri_not_png.gltf", image_seed({"uri": png_uri(b"BM" + b"\0" * 60)})
    yield "image_view.gltf", image_seed(in_buffer=png(2, 2))
    yield "image_view_huge.gltf", image_seed(in_buffer=png(16384, 16384, pixels=False))
    for i, value in enumerate(NEAR_LIMITS):
        yield f"image_view_offset_{i}.gltf", image_seed(in_buffer=png(2, 2),
                                                        view={"byteOffset": value})
        yield f"image_view_length_{i}.gltf", image_seed(in_buffer=png(2, 2),
                                                        view={"byteLength": value})


def main():
    os.makedirs(CORPUS, exist_ok=True)
    for name, doc in seeds():
        with open(os.path.join(CORPUS, name), "w") as out:
            json.dump(doc, out, separators=(",", ":"))
    for name, doc in [("triangle.glb", triangle()),
                      ("glb_position_count.glb", triangle(position={"count": 2**62})),
                      ("glb_image_view.glb", image_seed(in_buffer=png(2, 2)))]:
        with open(os.path.join(CORPUS, name), "wb") as out:
            out.write(glb(doc))
    keys = ["asset", "version", "buffers", "bufferViews", "accessors", "meshes", "primitives",
            "attributes", "indices", "nodes", "children", "scenes", "scene", "mesh", "matrix",
            "translation", "rotation", "scale", "byteLength", "byteOffset", "byteStride",
            "buffer", "bufferView", "componentType", "count", "type", "normalized", "min",
            "max", "sparse", "values", "uri", "mode", "materials", "pbrMetallicRoughness",
            "baseColorFactor", "baseColorTexture", "normalTexture", "textures", "images",
            "samplers", "source", "sampler", "texCoord", "extensions", "extensionsUsed",
            "extensionsRequired", "extras", "KHR_lights_punctual", "lights", "cameras",
            "perspective", "orthographic", "yfov", "znear", "zfar", "mimeType"]
    keys += list(TYPES) + list(ATTRIBUTES)
    values = [str(c) for c in COMPONENTS] + [str(v) for v in NEAR_LIMITS]
    values += ["data:application/octet-stream;base64,", "glTF", "JSON", "BIN\\x00", "-1", "1e308",
               "data:image/png;base64,", "data:image/jpeg;base64,", "image/png", "image/jpeg",
               "\\x89PNG", "IHDR", "\\xff\\xd8\\xff\\xc0"]
    with open(os.path.join(HERE, "gltf.dict"), "w") as out:
        out.write("# libFuzzer dictionary: glTF keys and values (tests/fuzz/make_corpus.py)\n")
        for word in keys:
            out.write(f'"\\"{word}\\""\n')
        for word in values:
            out.write(f'"{word}"\n')


if __name__ == "__main__":
    main()
