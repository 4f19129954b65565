#!/usr/bin/env python3
"""ParaView reads the results of the example scenes (docs/output.md,
"results.xdmf"): runs the `# CI:` line of each named config in configs/
(--no-plots) into OUTPUT_DIR/<config stem>, and checks each results.xdmf with
scripts/check_xdmf_paraview.py under pvpython. Then breaks a copy of the first
output's index (an attribute pointed at another dataset, a unit left out)
and requires the check to fail on it: the check can fail.

Usage: check_paraview_reads_configs.py FISSURE SOURCE_DIR OUTPUT_DIR PVPYTHON CONFIG...

Exit status: 0 passed, 1 failed, 77 skipped (PVPYTHON is empty or not found:
ParaView is not installed; Debian: apt-get install paraview).
"""
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

SKIPPED = 77


def ci_line(config):
    """The config's first `# CI:` line."""
    for line in config.read_text().splitlines():
        if line.startswith("# CI:"):
            return shlex.split(line.split(":", 1)[1])
    return None


def check(pvpython, checker, outdir):
    """(exit code, output) of the ParaView check of one output folder."""
    r = subprocess.run([pvpython, str(checker), str(outdir)], capture_output=True, text=True)
    return r.returncode, r.stdout + r.stderr


def broken_copy(outdir, broken):
    """A copy of `outdir` whose results.xdmf names the wrong dataset for the
    first triangle stress sxx (syy's) and lacks the unit of the first
    attribute. Returns what was broken."""
    shutil.rmtree(broken, ignore_errors=True)
    shutil.copytree(outdir, broken)
    xdmf = broken / "results.xdmf"
    text = xdmf.read_text()
    text, swapped = re.subn(r"(/frames/\d+/)sxx<", r"\1syy<", text, count=1)
    text, dropped = re.subn(r'\s*<Information Name="unit" Value="[^"]*"/>', "", text, count=1)
    xdmf.write_text(text)
    return swapped + dropped


def main():
    if len(sys.argv) < 6:
        print(__doc__, file=sys.stderr)
        return 2
    app, source, output, pvpython = sys.argv[1], pathlib.Path(sys.argv[2]), \
        pathlib.Path(sys.argv[3]), sys.argv[4]
    configs = sys.argv[5:]
    if not pvpython or pvpython.endswith("NOTFOUND") or shutil.which(pvpython) is None:
        print("check_paraview_reads_configs.py: SKIPPED: pvpython not found (Debian: apt-get "
              "install paraview, then configure again); ParaView's reading of results.xdmf is "
              "not checked")
        return SKIPPED
    checker = source / "scripts" / "check_xdmf_paraview.py"
    failures, checked = [], []
    for stem in configs:
        words = ci_line(source / "configs" / f"{stem}.yaml")
        if not words or words[:2] != ["fissure", "run"]:
            failures.append(f"{stem}: no '# CI: fissure run' line")
            continue
        outdir = output / stem
        shutil.rmtree(outdir, ignore_errors=True)
        run = subprocess.run([app] + words[1:] + ["--no-plots", "-o", str(outdir)], cwd=source,
                             capture_output=True, text=True)
        if run.returncode != 0:
            failures.append(f"{stem}: '{' '.join(words)}' exited {run.returncode}\n{run.stderr}")
            continue
        code, text = check(pvpython, checker, outdir)
        if code == SKIPPED:
            print(text)
            return SKIPPED
        print(f"{stem}: {text.strip().splitlines()[-1]}")
        if code != 0:
            failures.append(f"{stem}: the ParaView check failed (exit {code}):\n{text}")
        checked.append(outdir)
    # The check can fail: a broken index must not pass.
    if checked:
        broken = output / "broken_index"
        if broken_copy(checked[0], broken) != 2:
            failures.append(f"{checked[0]}: found no sxx and unit to break")
        code, text = check(pvpython, checker, broken)
        found = "FAIL blocks: sxx of the frame" in text and "has a unit" in text
        print(f"broken index of {checked[0].name}: exit {code}"
              + (", both faults found" if found else ""))
        if code != 1 or not found:
            failures.append(f"the check did not report the broken index {broken} (exit {code}):\n"
                            f"{text}")
    for f in failures:
        print(f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
