#!/usr/bin/env python3
"""A must-fail test: runs a command that has to fail in a known way.

    expect_failure.py EXIT_CODE [--expect TEXT]... -- COMMAND [ARG]...

Passes when COMMAND exits with EXIT_CODE and every TEXT (a plain substring;
runs of white space match any white space, since CMake wraps its messages)
appears in its output (stdout and stderr together); anything else, a crash
or a failure for the wrong reason included, fails and says why.
"""
import subprocess
import sys


def main(argv):
    split = argv.index("--") if "--" in argv else 0
    if split < 2 or split == len(argv) - 1:
        print(__doc__, file=sys.stderr)
        return 2
    options, command = argv[1:split], argv[split + 1:]
    expected_code = int(options[0])
    expected = [options[i + 1] for i, option in enumerate(options) if option == "--expect"]
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(result.stdout)
    output = " ".join(result.stdout.split())
    failures = []
    if result.returncode != expected_code:
        failures.append(f"exit code {result.returncode}, expected {expected_code}")
    failures += [f"missing from the output: {text!r}" for text in expected
                 if " ".join(text.split()) not in output]
    for failure in failures:
        print(f"expect_failure: {failure}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
