#!/usr/bin/env python3
"""Checks every #include under ROOT/src against the layer rules listed in
docs/ARCHITECTURE.md ("Layer rules"), so the list and the check cannot drift.

    check_layers.py RULES_MD ROOT

Exit 0 when every include keeps the rules, 1 naming each file, line and rule
broken, 2 when the rules or the tree cannot be read.

Rule lines, the list items of that section (one per folder of src/, plus
rules on other libraries' headers; any other list item there is an error):
    - `core/trace` includes `core/scene`, `core/metrics`, `core/base`
    - `core/base` includes nothing of ours
    - `app` includes everything
    - `<GLFW/...>`, `<imgui...>`: only in `view`
    - `<vulkan/...>`: never in `core/base`, `core/scene`
A file may always include headers of its own folder. `shaders` stands for the
headers in ROOT/shaders (interface.h, shared with GLSL).
"""
import re
import sys
from pathlib import Path

SOURCE_SUFFIXES = {".h", ".hpp", ".cpp", ".cc", ".inl"}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]')
FOLDER_RULE = re.compile(r"^- `([\w/]+)` includes (.*)$")
HEADER_RULE = re.compile(r"^- (.*`<[^`]+>`.*): (only|never) in (.*)$")
TICKED = re.compile(r"`([^`]+)`")


class Rules:
    def __init__(self):
        self.allowed = {}  # folder -> set of folders, or None for everything
        self.text = {}  # folder -> the rule as written, for messages
        self.headers = []  # (prefixes, "only" | "never", folders, text)


def rule_lines(path):
    """The list items of the "## Layer rules" section."""
    lines = path.read_text(encoding="utf-8").splitlines()
    try:
        start = lines.index("## Layer rules") + 1
    except ValueError:
        raise ValueError(f"{path}: no '## Layer rules' section")
    for line in lines[start:]:
        if line.startswith("## "):
            break
        if line.startswith("- "):
            yield line


def read_rules(path):
    rules = Rules()
    for line in rule_lines(path):
        match = FOLDER_RULE.match(line)
        if match:
            folder, rest = match.groups()
            if rest == "everything":
                rules.allowed[folder] = None
            elif rest == "nothing of ours":
                rules.allowed[folder] = set()
            else:
                rules.allowed[folder] = set(TICKED.findall(rest))
            rules.text[folder] = line[2:]
            continue
        match = HEADER_RULE.match(line)
        if match:
            patterns, kind, rest = match.groups()
            # `<GLFW/...>` -> "GLFW/", `<imgui...>` -> "imgui", `<volk.h>` -> "volk.h"
            prefixes = [p.strip("<>").replace("...", "") for p in TICKED.findall(patterns)
                        if p.startswith("<")]
            rules.headers.append((prefixes, kind, set(TICKED.findall(rest)), line[2:]))
            continue
        raise ValueError(f"{path}: cannot read the layer rule '{line}'")
    if not rules.allowed:
        raise ValueError(f"{path}: no layer rules found (lines like '- `core/base` includes ...')")
    known = set(rules.allowed) | {"shaders"}
    for folder, allowed in rules.allowed.items():
        if allowed is not None and allowed - known:
            raise ValueError(f"{path}: the rule for {folder} names unknown folders "
                             f"{sorted(allowed - known)}")
    for _, _, folders, text in rules.headers:
        if folders - known:
            raise ValueError(f"{path}: the rule '{text}' names unknown folders {sorted(folders - known)}")
    return rules


def folder_of(relative, folders):
    """The longest rule folder that `relative` (a path under src/) lies in."""
    best = None
    for folder in folders:
        if relative == folder or relative.startswith(folder + "/"):
            if best is None or len(folder) > len(best):
                best = folder
    return best


def check_file(path, root, rules, problems):
    relative_file = path.relative_to(root).as_posix()
    folder = folder_of(path.relative_to(root / "src").as_posix(), rules.allowed)
    if folder is None:
        problems.append(f"{relative_file}: its folder has no layer rule")
        return
    allowed = rules.allowed[folder]
    lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    for number, line in enumerate(lines, start=1):
        match = INCLUDE.match(line)
        if not match:
            continue
        delimiter, included = match.groups()
        where = f"{relative_file}:{number}"
        if delimiter == "<":
            for prefixes, kind, folders, text in rules.headers:
                if not any(included.startswith(prefix) for prefix in prefixes):
                    continue
                if (kind == "only") != (folder in folders):
                    problems.append(f'{where}: includes <{included}>, breaking "{text}"')
            continue
        target = folder_of(included, rules.allowed)
        if target is None:
            if (path.parent / included).is_file():
                target = folder
            elif (root / "shaders" / included).is_file():
                target = "shaders"
            else:
                problems.append(f'{where}: includes "{included}", which is in no layer '
                                f"(another library's header takes <>)")
                continue
        if target == folder or allowed is None or target in allowed:
            continue
        problems.append(f'{where}: includes "{included}" ({target}), breaking "{rules.text[folder]}"')


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    rules_path, root = Path(argv[1]), Path(argv[2]).resolve()
    try:
        rules = read_rules(rules_path)
    except (OSError, ValueError) as error:
        print(f"check_layers: {error}", file=sys.stderr)
        return 2
    sources = sorted(p for p in (root / "src").rglob("*") if p.suffix in SOURCE_SUFFIXES)
    if not sources:
        print(f"check_layers: no sources under {root / 'src'}", file=sys.stderr)
        return 2
    problems = []
    for path in sources:
        check_file(path, root, rules, problems)
    for problem in problems:
        print(problem)
    print(f"check_layers: {len(sources)} files, {len(problems)} broken rules")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
