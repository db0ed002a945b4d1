#!/usr/bin/env python3
"""--json on render, trace, compare, bench and study: each run at a small
size prints exactly one JSON object on stdout (json.loads of the whole of
stdout, so a truncated object or a stray human line fails), with the fields
README's "Machine-readable output" lists, values that agree with what the
command prints for people and with the files it wrote, and metrics in range.
  test_json_output.py SHADELAB_BINARY
Runs in a temporary folder; prints one line per check group; exits 1
listing every failed check."""
import json
import os
import re
import struct
import subprocess
import sys
import tempfile

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def run(binary, args, cwd):
    result = subprocess.run([binary] + args, cwd=cwd, capture_output=True, text=True, timeout=600)
    if result.returncode != 0:
        failures.append(f"{' '.join(args)}: exit {result.returncode}: {result.stderr.strip()}")
    return result


def run_json(binary, args, cwd):
    """The object a --json run printed, or None (a failure noted)."""
    result = run(binary, args + ["--json"], cwd)
    try:
        value = json.loads(result.stdout)
    except json.JSONDecodeError as error:
        failures.append(f"{args[0]}: stdout is not one JSON object ({error}): {result.stdout[-80:]!r}")
        return None, result
    if not check(isinstance(value, dict), f"{args[0]}: stdout holds a {type(value).__name__}"):
        return None, result
    check(value.get("schema_version") == 1, f"{args[0]}: schema_version {value.get('schema_version')}")
    check(value.get("command") == args[0], f"{args[0]}: command {value.get('command')!r}")
    return value, result


def png_size(path):
    with open(path, "rb") as file:
        header = file.read(24)
    if header[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return struct.unpack(">II", header[16:24])


def check_file(command, path, size=None):
    if not check(os.path.isabs(path), f"{command}: output path {path!r} is not absolute"):
        return
    if not check(os.path.isfile(path), f"{command}: output {path} does not exist"):
        return
    if size is not None:
        check(png_size(path) == size, f"{command}: {path} is {png_size(path)}, expected {size}")


def in_range(command, name, value, low, high):
    check(isinstance(value, (int, float)) and low <= value <= high,
          f"{command}: {name} {value!r} outside [{low}, {high}]")


def check_render(binary, cwd):
    args = ["render", "teapot", "--size", "64x36", "--mode", "gouraud", "--frames", "3",
            "--shadows", "off"]
    value, result = run_json(binary, args + ["-o", "r.png"], cwd)
    # Without --json the same run prints its human line on stdout.
    plain = run(binary, args + ["-o", "plain.png"], cwd)
    printed = re.search(r"(\d+) triangles in (\d+) draws", plain.stdout)
    check(printed is not None, f"render: no triangle count in {plain.stdout!r}")
    check("wrote r.png" in result.stderr, "render --json: the human line is not on stderr")
    if value is None or printed is None:
        return None
    check(value["triangles"] == int(printed.group(1)),
          f"render: triangles {value['triangles']} != {printed.group(1)} printed without --json")
    check(value["draw_calls"] == int(printed.group(2)),
          f"render: draw_calls {value['draw_calls']} != {printed.group(2)}")
    check(value["scene"] == "teapot", f"render: scene {value['scene']!r}")
    check((value["billboard_copies"], value["trimmed_copies"]) == (0, 0),
          f"render: the teapot has no billboards, counted {value['billboard_copies']}")
    check(value["settings"]["billboard_outline"] == "trimmed",
          f"render: billboard_outline {value['settings']['billboard_outline']!r}")
    check(value["settings"]["draw_order"] == "sorted",
          f"render: draw_order {value['settings']['draw_order']!r}")
    settings = value["settings"]
    check((settings["width"], settings["height"]) == (64, 36), f"render: size {settings}")
    check(settings["mode"] == "gouraud" and settings["frames"] == 3 and settings["shadows"] == "off",
          f"render: settings {settings}")
    timings = value["timings"]
    check(timings["steady_frames"] + timings["warmup_frames"] == 3, f"render: frames {timings}")
    in_range("render", "device_median_ms", timings["device_median_ms"], 1e-6, 60000)
    check(timings["device_median_ms"] <= timings["device_p95_ms"], f"render: median > p95 {timings}")
    check_file("render", value["outputs"]["image"], (64, 36))
    return value["triangles"]


def check_trace(binary, cwd, render_triangles):
    value, _ = run_json(binary, ["trace", "teapot", "-o", "t.png", "--size", "32x18", "--spp", "4"],
                        cwd)
    if value is None:
        return
    check(value["rays"]["primary"] == 32 * 18 * 4, f"trace: primary rays {value['rays']}")
    check(value["settings"]["spp"] == 4 and value["settings"]["bounces"] == 5,
          f"trace: settings {value['settings']}")
    if render_triangles is not None:  # the teapot is all in view: render culls nothing
        check(value["triangles"] == render_triangles,
              f"trace: triangles {value['triangles']} != render's {render_triangles}")
    in_range("trace", "trace_seconds", value["timings"]["trace_seconds"], 1e-9, 600)
    check_file("trace", value["outputs"]["image"], (32, 18))


def check_compare(binary, cwd):
    value, _ = run_json(binary, ["compare", "-o", "c.png", "--size", "32x18", "--spp", "1",
                                 "--modes", "flat,phong"], cwd)
    if value is None:
        return
    modes = value["modes"]
    check([m["mode"] for m in modes] == ["flat", "phong"], f"compare: modes {modes}")
    for m in modes:
        in_range("compare", f"{m['mode']} flip", m["flip"], 0.0, 1.0)
        in_range("compare", f"{m['mode']} ssim", m["ssim"], -1.0, 1.0)
        in_range("compare", f"{m['mode']} rmse", m["rmse"], 0.0, 255.0)
    check(value["settings"]["cell_width"] == 32 and value["settings"]["modes"] == ["flat", "phong"],
          f"compare: settings {value['settings']}")
    check_file("compare", value["outputs"]["sheet"])
    check_file("compare", value["outputs"]["json"])
    if os.path.isfile(value["outputs"]["json"]):
        with open(value["outputs"]["json"]) as file:
            check(json.load(file)["modes"] == modes, "compare: c.json's modes differ from stdout's")


def check_compare_columns(binary, cwd):
    """--column: each column with its name, spec and settings, measured
    against --against's column; the baseline column itself has no metrics."""
    value, _ = run_json(binary, ["compare", "-o", "k.png", "--size", "32x18", "--spp", "1",
                                 "--column", "name=coarse,gouraud,tess=0.5",
                                 "--column", "name=fine,phong,tess=4,msaa=4,shadows=pcf3",
                                 "--column", "flat,env=off,depth=reversed",
                                 "--against", "fine"], cwd)
    if value is None:
        return
    columns = value["columns"]
    check([c["name"] for c in columns] == ["coarse", "fine", "flat,env=off,depth=reversed"],
          f"compare columns: names {[c['name'] for c in columns]}")
    check(value["against"] == "fine", f"compare columns: against {value['against']}")
    if len(columns) == 3:
        coarse, fine, flat = columns
        check(coarse["settings"]["tess"] == 0.5 and coarse["settings"]["mode"] == "gouraud",
              f"compare columns: coarse {coarse['settings']}")
        check(fine["settings"]["msaa"] == 4 and fine["settings"]["shadows"] == "pcf3" and
              fine["settings"]["tess"] == 4, f"compare columns: fine {fine['settings']}")
        check(flat["settings"]["environment"] is False and flat["settings"]["depth"] == "reversed",
              f"compare columns: flat {flat['settings']}")
        check("metrics" not in fine, "compare columns: the baseline measured against itself")
        # More tessellation, more triangles.
        check(fine["triangles"] > coarse["triangles"] > 0,
              f"compare columns: triangles {coarse['triangles']}, {fine['triangles']}")
        for c in (coarse, flat):
            check(c["against"] == "fine", f"compare columns: {c['name']} against {c['against']}")
            in_range("compare columns", f"{c['name']} flip", c["metrics"]["flip"], 1e-6, 1.0)
            in_range("compare columns", f"{c['name']} rmse", c["metrics"]["rmse"], 1e-6, 255.0)
    if os.path.isfile(value["outputs"]["json"]):
        with open(value["outputs"]["json"]) as file:
            written = json.load(file)
        check(written["columns"] == columns and written["against"] == "fine",
              "compare columns: k.json's columns differ from stdout's")


def check_bench(binary, cwd):
    value, _ = run_json(binary, ["bench", "-o", "b", "--size", "32x18", "--frames", "2",
                                 "--rounds", "1", "--modes", "unlit,phong", "--tess", "1",
                                 "--msaa", "1"], cwd)
    if value is None:
        return
    results = value["results"]
    check([r["setting"]["mode"] for r in results] == ["unlit", "phong"], f"bench: {results}")
    for r in results:
        in_range("bench", "flip", r["metrics"]["flip"], 0.0, 1.0)
        in_range("bench", "device_median_ms", r["device_median_ms"], 1e-6, 60000)
        check(r["triangles"] > 0, f"bench: triangles {r['triangles']}")
    check(any(r["pareto"] for r in results), "bench: nothing on the Pareto front")
    for key in ("csv", "error_vs_time", "error_vs_triangles"):
        check_file("bench", value["outputs"][key])
    if os.path.isfile(value["outputs"]["csv"]):
        with open(value["outputs"]["csv"]) as file:
            rows = [line for line in file.read().splitlines() if line]
        check(len(rows) == 1 + len(results), f"bench: {len(rows)} CSV lines for {len(results)} results")


def check_study(binary, cwd):
    value, _ = run_json(binary, ["study", "tir", "-o", "tir"], cwd)
    if value is not None:
        rows = value["tables"].get("tir.csv", [])
        check(len(rows) > 10, f"study: {len(rows)} rows of tir.csv")
        # Refraction keeps energy: transmitted + reflected = 1 at every angle.
        for row in rows:
            check(abs(row["energy"] - 1.0) < 1e-3, f"study: tir energy {row}")
        for path in value["outputs"]["files"]:
            check_file("study", path)
    listing, _ = run_json(binary, ["study"], cwd)
    if listing is not None:
        check("tir" in [s["name"] for s in listing["studies"]], f"study: list {listing}")


def main(argv):
    binary = os.path.abspath(argv[1])
    with tempfile.TemporaryDirectory() as cwd:
        triangles = check_render(binary, cwd)
        print(f"render: {len(failures)} failed check(s) so far")
        check_trace(binary, cwd, triangles)
        print(f"trace: {len(failures)} failed check(s) so far")
        check_compare(binary, cwd)
        check_compare_columns(binary, cwd)
        print(f"compare: {len(failures)} failed check(s) so far")
        check_bench(binary, cwd)
        print(f"bench: {len(failures)} failed check(s) so far")
        check_study(binary, cwd)
        print(f"study: {len(failures)} failed check(s) so far")
    for failure in failures:
        print(f"FAILED: {failure}")
    print(f"{len(failures)} failed check(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
