#!/usr/bin/env python3
"""Runs the `# CI:` line of every scene in configs/ and compares
its results with the stored reference (tests/configs/README.md).

Each config starts with a header holding `# Run:` lines (the full run) and
`# CI:` lines (a short variant that CI executes). This script checks that
every config has both, replaces the leading `fissure` of each CI line with the
built executable, adds an output folder under the build tree
(OUTPUT_DIR/<config stem>_<k> for the k-th CI line, emptied first), and runs
it from the repository root. Any non-zero exit code fails the test.

After a successful run the output folder is compared with
tests/configs/references/<config stem>_<k>/ (compare_with_reference.py, with
the tolerances of references/tolerances.json); a mismatch, a missing
reference, or a reference without a CI line fails the test. Where the system's
python3 can draw (h5py, matplotlib), every `fissure run` line must also leave
its picture, final_state.png (docs/output.md), unless it says --no-plots.
A run that prints a warning on stderr fails too: the shipped scenes run
without warnings.

Usage: run_config_ci_lines.py FISSURE_EXECUTABLE SOURCE_DIR OUTPUT_DIR [--update] [--no-compare]
  --update      store every run's results as its reference instead of comparing
                (after an intended change of results; review the diff)
  --no-compare  only run the CI lines (exit codes)
"""
import pathlib
import shlex
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import compare_with_reference  # noqa: E402


def system_python_can_plot():
    """True when /usr/bin/python3 has the modules of the plot scripts."""
    try:
        return subprocess.run(["/usr/bin/python3", "-c", "import h5py, matplotlib, numpy"],
                              capture_output=True).returncode == 0
    except OSError:
        return False


def cpu():
    """The CPU and its widest vector unit: a reference's spread depends on them
    (README.md, "Measured spread"), so a failure names the machine."""
    try:
        info = pathlib.Path("/proc/cpuinfo").read_text()
    except OSError:
        return "unknown"
    model = next((l.split(":", 1)[1].strip() for l in info.splitlines() if l.startswith("model name")), "unknown")
    cpu_flags = next((l.split(":", 1)[1].split() for l in info.splitlines() if l.startswith("flags")), [])
    unit = next((u for f, u in (("avx512f", "AVX-512"), ("avx2", "AVX2")) if f in cpu_flags), "SSE2")
    return f"{model}, {unit}"


def main():
    flags = [a for a in sys.argv[1:] if a.startswith("--")]
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) != 3 or set(flags) - {"--update", "--no-compare"}:
        print(__doc__, file=sys.stderr)
        return 2
    update, check = "--update" in flags, "--no-compare" not in flags
    print(f"CPU: {cpu()}", flush=True)
    app, source, output = args[0], pathlib.Path(args[1]), pathlib.Path(args[2])
    configs = sorted((source / "configs").glob("*.yaml"))
    failures = []
    names = set()
    can_plot = system_python_can_plot()
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
            name = f"{config.stem}_{k}"
            names.add(name)
            for option in ("-o", "--output"):
                if option in words:
                    folder = source / words[words.index(option) + 1]
                    break
            else:
                folder = output / name
                # No files of an earlier run: a file the run no longer writes must be missed.
                shutil.rmtree(folder, ignore_errors=True)
                words += ["-o", str(folder)]
            result = subprocess.run(words, cwd=source, capture_output=True, text=True)
            status = "ok" if result.returncode == 0 else f"FAILED (exit {result.returncode})"
            if result.returncode == 0 and update:
                files = compare_with_reference.update(folder, name)
                status += f", reference updated ({', '.join(files)})"
            elif result.returncode == 0 and check:
                mismatches = compare_with_reference.compare(folder, name)
                status += ", matches the reference" if not mismatches else ", DIFFERS from the reference"
                failures += mismatches
            if (result.returncode == 0 and can_plot and words[1] == "run"
                    and "--no-plots" not in words and not (folder / "final_state.png").is_file()):
                failures.append(f"{config.name}: '{line}' left no final_state.png\n"
                                f"{result.stdout[-2000:]}")
            # A shipped scene runs without warnings (issue 34): a warning is a
            # flaw of the scene (a monitor off the network, say) or of the code.
            warnings = [w for w in result.stderr.splitlines() if "warning" in w.lower()]
            if warnings:
                status += f", {len(warnings)} WARNING(S)"
                failures.append(f"{config.name}: '{line}' printed warnings (a shipped scene must "
                                f"run without):\n" + "\n".join(warnings[:10]))
            print(f"{config.name}: {line} -> {status}")
            if result.returncode != 0:
                failures.append(f"{config.name}: '{line}' exited {result.returncode}\n"
                                f"{result.stdout[-2000:]}\n{result.stderr[-2000:]}")
    if not configs:
        failures.append("no configs found")
    if check or update:
        references = compare_with_reference.DEFAULT_REFERENCES
        for stale in sorted(p.name for p in references.iterdir() if p.is_dir() and p.name not in names):
            failures.append(f"{stale}: reference {references / stale} has no CI line (delete it, or restore the line)")
    for f in failures:
        print(f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
