#!/usr/bin/env python3
"""scripts/glmark2_model.py, the .3ds -> glTF converter behind
scripts/peer_bench.sh: a tetrahedron written as 3DS chunks comes out with its
vertices, faces and glmark2-style normals, shadelab draws it, and broken files
are refused with exit 2 and a message naming the file.
  test_glmark2_model.py CONVERTER SHADELAB_BINARY"""
import base64
import json
import math
import os
import struct
import subprocess
import sys
import tempfile

converter, shadelab = sys.argv[1], sys.argv[2]
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print(f"FAILED: {what}")


def chunk(chunk_id, body):
    return struct.pack("<HI", chunk_id, 6 + len(body)) + body


POINTS = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]  # outward, counter-clockwise


def model(points=POINTS, faces=FACES, vertex_count=None):
    vertices = struct.pack("<H", len(points) if vertex_count is None else vertex_count)
    vertices += b"".join(struct.pack("<3f", *p) for p in points)
    face_list = struct.pack("<H", len(faces))
    face_list += b"".join(struct.pack("<4H", *f, 0) for f in faces)
    mesh = chunk(0x4100, chunk(0x4110, vertices) + chunk(0x4120, face_list))
    # An unknown chunk (material, 0xAFFF) before the object is skipped.
    editor = chunk(0x3D3D, chunk(0xAFFF, b"\1\2\3") + chunk(0x4000, b"tetra\0" + mesh))
    return chunk(0x4D4D, editor)


def run(*args):
    return subprocess.run(args, capture_output=True, text=True)


def expected_normal(vertex):
    total = [0.0, 0.0, 0.0]
    for face in FACES:
        if vertex not in face:
            continue
        a, b, c = (POINTS[i] for i in face)
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        length = math.sqrt(sum(x * x for x in n))
        total = [total[k] + n[k] / length for k in range(3)]
    length = math.sqrt(sum(x * x for x in total))
    return [x / length for x in total]


with tempfile.TemporaryDirectory() as folder:
    source = os.path.join(folder, "tetra.3ds")
    target = os.path.join(folder, "tetra.gltf")
    with open(source, "wb") as out:
        out.write(model())
    result = run(sys.executable, converter, source, target)
    check(result.returncode == 0, f"converter exit {result.returncode}: {result.stderr}")
    check("4 triangles" in result.stdout, f"converter says 4 triangles: {result.stdout!r}")
    gltf = json.load(open(target))
    blob = base64.b64decode(gltf["buffers"][0]["uri"].split(",", 1)[1])

    def read(accessor, fmt):
        view = gltf["bufferViews"][gltf["accessors"][accessor]["bufferView"]]
        data = blob[view["byteOffset"]:view["byteOffset"] + view["byteLength"]]
        return list(struct.unpack(f"<{len(data) // struct.calcsize(fmt)}{fmt}", data))

    primitive = gltf["meshes"][0]["primitives"][0]
    positions = read(primitive["attributes"]["POSITION"], "f")
    normals = read(primitive["attributes"]["NORMAL"], "f")
    indices = read(primitive["indices"], "I")
    check(positions == [x for p in POINTS for x in p], f"positions {positions}")
    check(indices == [i for f in FACES for i in f], f"indices {indices}")
    for vertex in range(len(POINTS)):
        got = normals[3 * vertex:3 * vertex + 3]
        want = expected_normal(vertex)
        check(all(abs(got[k] - want[k]) < 1e-6 for k in range(3)),
              f"normal of vertex {vertex}: {got}, expected {want}")

    # shadelab draws what came out: all four faces, none dropped.
    scene = os.path.join(folder, "scene.json")
    with open(scene, "w") as out:
        json.dump({"camera": {"eye": [2, 1.5, 3], "at": [0.3, 0.3, 0.3]},
                   "objects": [{"gltf": "tetra.gltf"}]}, out)
    result = run(shadelab, "render", scene, "--size", "64x48", "-o",
                 os.path.join(folder, "tetra.png"))
    check(result.returncode == 0, f"shadelab render exit {result.returncode}: {result.stderr}")
    check("4 triangles" in result.stdout, f"shadelab drew 4 triangles: {result.stdout!r}")

    # Broken input: exit 2, the file named, no output left behind.
    broken = {
        "truncated chunk": model()[:-5],
        "face beyond the vertex list": model(faces=[(0, 1, 7)]),
        "no mesh": chunk(0x4D4D, chunk(0x3D3D, b"")),
        "vertex count past its chunk": model(vertex_count=9),
    }
    for name, data in broken.items():
        bad = os.path.join(folder, "bad.3ds")
        out_path = os.path.join(folder, "bad.gltf")
        with open(bad, "wb") as out:
            out.write(data)
        result = run(sys.executable, converter, bad, out_path)
        check(result.returncode == 2, f"{name}: exit {result.returncode}, expected 2")
        check(bad in result.stderr, f"{name}: message names the file: {result.stderr!r}")
        check(not os.path.exists(out_path), f"{name}: no output written")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
