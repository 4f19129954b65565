#!/usr/bin/env python3
"""Runs every command of a tutorial page (docs/tutorial.md) as written.

The page marks what runs (its source says so at the top):

* every line of a fenced ```sh block is a command, run in order with bash
  from a scratch folder that stands for the repository root: `configs/` is a
  copy of the repository's, `scripts/` a link to it, and `build/app/fissure`
  a link to the executable under test; `python3` is the system's
  (/usr/bin first in PATH). So `build/app/fissure run
  configs/brick_wall.yaml` runs as a reader types it, and its output goes to
  the scratch folder's out/. A line ending in `\\` continues on the next;
  lines starting with `#` are comments. Commands do not share a shell (no
  `cd`, no variables from one line to the next);
* a ```sh block right after the comment `<!-- fails -->` shows refused
  input: each of its commands must exit with a non-zero code and print an
  error located in a file (`NAME.yaml:LINE:COLUMN:`);
* a fenced block right after the comment `<!-- file: NAME -->` is written to
  NAME in the scratch folder (a scene the reader writes) before the
  commands that follow it run.

Fails when a command fails (or a refused one succeeds), when a marker has no
fenced block after it, or when the page has no command. Prints each command
with its exit code and wall time.

Usage: run_tutorial_commands.py FISSURE_EXECUTABLE SOURCE_DIR SCRATCH_DIR [--page PAGE]
  PAGE defaults to SOURCE_DIR/docs/tutorial.md.
"""
import argparse
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

FENCE = re.compile(r"^```(\S*)\s*$")
MARKER = re.compile(r"^<!--\s*(fails|file:\s*(\S+))\s*-->\s*$")
LOCATED = re.compile(r"\.ya?ml:\d+:\d+: ")
TIMEOUT = 600  # seconds per command: generous; the page's commands take seconds


def steps(text):
    """The page's steps in order: ("run", commands, fails, line) for a ```sh
    block, ("file", name, content, line) for a marked block; raises
    ValueError for a marker without its block or an unclosed fence."""
    lines = text.splitlines()
    out = []
    marker = None  # (kind, name, line) of the last marker, waiting for its block
    i = 0
    while i < len(lines):
        m = MARKER.match(lines[i].strip())
        f = FENCE.match(lines[i])
        if m:
            if marker:
                raise ValueError(f"{marker[2]}: marker without a fenced block after it")
            marker = ("fails", None, i + 1) if m.group(1) == "fails" else ("file", m.group(2), i + 1)
            i += 1
            continue
        if f:
            start, lang = i + 1, f.group(1)
            i += 1
            body = []
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            if i == len(lines):
                raise ValueError(f"{start}: fenced block not closed")
            i += 1
            if marker and marker[0] == "file":
                out.append(("file", marker[1], "\n".join(body) + "\n", start))
            elif lang == "sh":
                out.append(("run", commands(body), marker is not None, start))
            elif marker:
                raise ValueError(f"{marker[2]}: <!-- fails --> before a ```{lang} block, not ```sh")
            marker = None
            continue
        if marker and lines[i].strip():
            raise ValueError(f"{marker[2]}: marker without a fenced block right after it")
        i += 1
    if marker:
        raise ValueError(f"{marker[2]}: marker without a fenced block after it")
    return out


def commands(body):
    """The commands of a ```sh block: continued lines joined, comments and
    blank lines left out."""
    out, current = [], ""
    for line in body:
        if not current and (not line.strip() or line.lstrip().startswith("#")):
            continue
        if line.rstrip().endswith("\\"):
            current += line.rstrip()[:-1] + " "
            continue
        out.append((current + line).strip())
        current = ""
    if current:
        out.append(current.strip())
    return out


def prepare(scratch, source, fissure):
    """An empty scratch folder that stands for the repository root."""
    shutil.rmtree(scratch, ignore_errors=True)
    scratch.mkdir(parents=True)
    shutil.copytree(source / "configs", scratch / "configs")
    (scratch / "scripts").symlink_to(source / "scripts", target_is_directory=True)
    (scratch / "build" / "app").mkdir(parents=True)
    (scratch / "build" / "app" / "fissure").symlink_to(fissure)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("fissure")
    p.add_argument("source")
    p.add_argument("scratch")
    p.add_argument("--page")
    a = p.parse_args()
    source = pathlib.Path(a.source).resolve()
    page = pathlib.Path(a.page) if a.page else source / "docs" / "tutorial.md"
    scratch = pathlib.Path(a.scratch).resolve()
    try:
        plan = steps(page.read_text())
    except ValueError as e:
        print(f"{page}:{e}", file=sys.stderr)
        return 1
    if not any(s[0] == "run" and s[1] for s in plan):
        print(f"{page}: no ```sh command to run", file=sys.stderr)
        return 1
    prepare(scratch, source, pathlib.Path(a.fissure).resolve())
    env = dict(os.environ, LC_ALL="C")
    # The page's `python3` is the system's, which has the Debian packages
    # `make` installs (h5py, matplotlib; scripts/install-deps.sh), as on a
    # reader's machine; a python3 of another installation may come first in
    # PATH here.
    if pathlib.Path("/usr/bin/python3").is_file():
        env["PATH"] = "/usr/bin:" + env.get("PATH", "")
    failures = []
    began = time.monotonic()
    for step in plan:
        if step[0] == "file":
            _, name, content, line = step
            target = scratch / name
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(content)
            print(f"{page.name}:{line}: wrote {name}")
            continue
        _, cmds, fails, line = step
        for cmd in cmds:
            t0 = time.monotonic()
            try:
                r = subprocess.run(["bash", "-o", "pipefail", "-c", cmd], cwd=scratch, env=env,
                                   capture_output=True, text=True, timeout=TIMEOUT)
                code, out, err = r.returncode, r.stdout, r.stderr
            except subprocess.TimeoutExpired:
                code, out, err = None, "", f"no exit within {TIMEOUT} s"
            dt = time.monotonic() - t0
            if fails:
                ok = code not in (0, None) and LOCATED.search(err + out) is not None
                what = "refused with a located error" if ok else "NOT refused with a located error"
            else:
                ok = code == 0
                what = "ok" if ok else "FAILED"
            print(f"{page.name}:{line}: {cmd}  -> exit {code}, {dt:.1f} s, {what}", flush=True)
            if not ok:
                failures.append(f"{page}:{line}: '{cmd}' exited {code} ({what})\n"
                                f"{out[-2000:]}{err[-2000:]}")
    print(f"{len([s for s in plan if s[0] == 'run'])} blocks in {time.monotonic() - began:.1f} s")
    for f in failures:
        print(f, file=sys.stderr)
    if failures:
        print(f"{len(failures)} command(s) of {page} failed", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
