#!/usr/bin/env python3
"""Runs the `# CI:` line of every scene in configs/ (style.md 5).

Each config starts with a header holding `# Run:` lines (the full run) and
`# CI:` lines (a short variant that CI executes). This script checks that
every config has both, replaces the leading `fissure` of each CI line with the
built executable, adds an output folder under the build tree, and runs it
from the repository root. Any non-zero exit code fails the test.

Usage: run_config_ci_lines.py FISSURE_EXECUTABLE SOURCE_DIR OUTPUT_DIR
"""
import pathlib
import shlex
import subprocess
import sys


def main():
    app, source, output = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    configs = sorted((source / "configs").glob("*.yaml"))
    failures = []
    for config in configs:
        header = [l for l in config.read_text().splitlines() if l.startswith("#")]
        runs = [l.split(":", 1)[1].strip() for l in header if l.startswith("# Run:")]
        cis = [l.split(":", 1)[1].strip() for l in header if l.startswith("# CI:")]
        if not runs or not cis:
            failures.append(f"{config.name}: header needs '# Run:' and '# CI:' lines")
            continue
        for k, line in enumerate(cis):
            words = shlex.split(line)
            if words[0] != "fissure":
                failures.append(f"{config.name}: CI line does not start with 'fissure': {line}")
                continue
            words[0] = app
            if "-o" not in words and "--output" not in words:
                words += ["-o", str(output / f"{config.stem}_{k}")]
            result = subprocess.run(words, cwd=source, capture_output=True, text=True)
            status = "ok" if result.returncode == 0 else f"FAILED (exit {result.returncode})"
            print(f"{config.name}: {line} -> {status}")
            if result.returncode != 0:
                failures.append(f"{config.name}: '{line}' exited {result.returncode}\n"
                                f"{result.stdout[-2000:]}\n{result.stderr[-2000:]}")
    if not configs:
        failures.append("no configs found")
    for f in failures:
        print(f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
