#!/usr/bin/env python3
"""README.md's commands run as written: every line of a ```sh block that
starts with `$B ` (the README sets B=build/release/shadelab), its trailing
`# comment` stripped, runs through bash with B set to the binary under test,
in README order, in a fresh temporary folder laid out as the README assumes
of the repository root (assets/, docs/ and tests/ linked, out/ made, ../shared/assets
linked to the real shared assets). Each must exit 0 and none may write into
the repository (`git status --porcelain` in REPO_ROOT unchanged).
  test_readme_commands.py README SHADELAB_BINARY REPO_ROOT
Prints one line per command with its time; exits 1 listing every failed
command with its output."""
import os
import re
import subprocess
import sys
import tempfile
import time

# Commands not run, each with the reason; matched on the subcommand (the word
# after $B) or on the whole command as the README writes it.
SKIP_SUBCOMMANDS = {
    "view": "opens a window; the viewer tests (shadelab_viewer_tests, under Xvfb) cover it",
    "bench": "takes minutes; the CLI tests cover bench with short runs",
}
# Past the 30 s a command may take in a debug build, or too close to it for
# the whole test to stay near a minute: wall time of the release binary on the
# shared 2-core machine (load 3.7; twice as long at load 7), times about 3 for
# debug (Debug: unoptimised, the validation layer on; not measured, there was
# no debug build at hand, and the C++ ray tracer likely slows more). The rest of
# the README takes about 55 s in that release build. Each is covered by a
# faster test.
SKIP_COMMANDS = {
    "$B render -o out/a.png --frames 300":
        "6.2 s release, ~20-40 s debug; frame statistics: shadelab_cli_tests with 12 frames",
    "$B trace whitted -o out/ref.png --spp 16":
        "6.5 s release, ~20-40 s debug; the traced whitted golden "
        "in shadelab_image_tests",
    "$B render -o out/a.png --quality 0.05":
        "11.8 s release, ~35-70 s debug; --quality: shadelab_cli_tests with known answers",
    "$B study impostor-parallax -o out/ip":
        "3.4 s release, ~10-30 s debug (CPU loops over 7 atlases); the same measurement "
        "at 12 views: "
        "ImpostorTest.ParallaxStaysWithinTheBoundAndShrinksWithMoreCells",
    "$B trace whitted -o out/ref.png --fresnel off":
        "8.1 s release, ~25-50 s debug; Fresnel on and off: "
        "test_trace_fresnel.cpp in shadelab_unit_tests",
}
TIMEOUT_SECONDS = 300  # a hung command fails instead of stalling ctest

SHARED = "../shared/"


def readme_commands(readme):
    """(line number, command) for each `$B ` line of a ```sh block."""
    commands = []
    in_sh = False
    with open(readme, encoding="utf-8") as file:
        for number, line in enumerate(file, 1):
            stripped = line.strip()
            if stripped.startswith("```"):
                in_sh = not in_sh and stripped[3:].strip() == "sh"
                continue
            if in_sh and stripped.startswith("$B "):
                command = re.sub(r"\s+#.*$", "", stripped)
                commands.append((number, command))
    return commands


def subcommands(command):
    """The word after each $B of the command (`$B --help ; $B render --help`)."""
    return [match.group(1) for match in re.finditer(r"\$B\s+(\S+)", command)]


def skip_reason(command, shared_assets):
    if command in SKIP_COMMANDS:
        return SKIP_COMMANDS[command]
    for word in subcommands(command):
        if word in SKIP_SUBCOMMANDS:
            return SKIP_SUBCOMMANDS[word]
    if SHARED in command and shared_assets is None:
        return ("reads ../shared/assets, which is absent "
                "(set SHADELAB_SHARED_ASSETS to the shared assets folder)")
    return None


def find_shared_assets(repo):
    overridden = os.environ.get("SHADELAB_SHARED_ASSETS")
    candidate = overridden if overridden else os.path.join(repo, "..", "shared", "assets")
    return os.path.realpath(candidate) if os.path.isdir(candidate) else None


def git_status(repo):
    result = subprocess.run(["git", "-C", repo, "status", "--porcelain"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"git status failed in {repo}: {result.stderr.strip()}")
    return result.stdout


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    readme, binary, repo = (os.path.abspath(arg) for arg in argv[1:])
    commands = readme_commands(readme)
    if not commands:
        print(f"FAILED: no `$B ` commands in ```sh blocks of {readme}")
        return 1
    shared_assets = find_shared_assets(repo)
    status_before = git_status(repo)

    failures = []
    ran = skipped = 0
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="shadelab-readme-") as root:
        # cwd is root/repo so that ../shared is root/shared, inside the folder.
        cwd = os.path.join(root, "repo")
        os.makedirs(os.path.join(cwd, "out"))
        for name in ("assets", "docs", "tests"):
            os.symlink(os.path.join(repo, name), os.path.join(cwd, name))
        if shared_assets is not None:
            os.makedirs(os.path.join(root, "shared"))
            os.symlink(shared_assets, os.path.join(root, "shared", "assets"))
        environment = dict(os.environ, B=binary)
        # One folder for the whole README, in order, as a reader would run
        # them: `render my.json` reads what `scenes --print ... > my.json` wrote.
        for number, command in commands:
            reason = skip_reason(command, shared_assets)
            if reason is not None:
                skipped += 1
                print(f"skip          README.md:{number}: {command}  ({reason})", flush=True)
                continue
            ran += 1
            begin = time.monotonic()
            try:
                result = subprocess.run(["bash", "-c", command], cwd=cwd, env=environment,
                                        stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True,
                                        timeout=TIMEOUT_SECONDS)
                code, output = result.returncode, result.stdout
            except subprocess.TimeoutExpired as error:
                code = f"timeout after {TIMEOUT_SECONDS} s"
                output = error.stdout.decode(errors="replace") if error.stdout else ""
            seconds = time.monotonic() - begin
            failed = len(failures)
            if code != 0:
                failures.append((number, command, f"exit code {code}", output))
            status_after = git_status(repo)
            if status_after != status_before:
                failures.append((number, command, "wrote into the repository "
                                 "(git status --porcelain changed)",
                                 f"before:\n{status_before}after:\n{status_after}"))
                status_before = status_after
            verdict = "ok  " if len(failures) == failed else "FAIL"
            print(f"{verdict} {seconds:7.2f} s  README.md:{number}: {command}", flush=True)

    total = time.monotonic() - started
    print(f"{ran} run, {skipped} skipped, {len(failures)} failed, {total:.1f} s")
    if failures:
        failed = len({number for number, *_ in failures})
        print(f"\n{failed} of {ran} commands failed:")
        for number, command, what, output in failures:
            print(f"\nFAILED: README.md:{number}: {command}\n  {what}")
            for line in output.rstrip().splitlines()[-40:]:
                print(f"  | {line}")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
