"""What the scene fuzzer (fuzz_scenes.py) and the generator-key fuzzer
(fuzz_generator_keys.py) share: running one command under limits and
measuring it, and reading its error output (docs/verification.md, "Scene
fuzzer").
"""
import math
import os
import re
import resource
import signal
import subprocess
import tempfile
import time

# --sanitized: the fissure under test is built with AddressSanitizer, whose
# shadow memory needs terabytes of address space, so RLIMIT_AS cannot cap it;
# ASan's own limit does (allocations beyond it fail as std::bad_alloc, a
# process beyond it in resident memory is stopped with a report, both OOM).
SANITIZED = [False]

OOM_PATTERN = re.compile(r"bad_alloc|out of memory|Cannot allocate memory|std::length_error|"
                         r"cannot create std::vector larger|vector::_M_|memory allocation failed",
                         re.I)


class Limits:
    """Applied in the child before exec: address space, CPU time, no core files."""

    def __init__(self, memory_mb, cpu_seconds):
        self.memory = memory_mb * 1024 * 1024
        self.cpu = int(math.ceil(cpu_seconds))

    def __call__(self):
        if self.memory > 0 and not SANITIZED[0]:
            resource.setrlimit(resource.RLIMIT_AS, (self.memory, self.memory))
        # SIGXCPU at the limit (SIGKILL 10 s later): CPU time, not wall time,
        # so that a busy machine does not turn a slow case into a hang.
        resource.setrlimit(resource.RLIMIT_CPU, (self.cpu, self.cpu + 10))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def run_measured(args, cwd, cpu_seconds, wall_seconds, memory_mb, env_extra=None):
    """Runs `args` in `cwd` under `Limits(memory_mb, cpu_seconds)`, killing
    its process group after `wall_seconds`. Returns rc (negative: the signal),
    its output, its own CPU and wall seconds and peak resident memory (MB),
    from wait4 (so that neither the fuzzer nor other cases count), and
    `timed_out` (the CPU limit or the wall clock stopped it)."""
    start = time.monotonic()
    env = dict(os.environ, OMPI_MCA_plm="isolated", OMPI_MCA_btl="self",
               OMPI_MCA_rmaps_base_oversubscribe="1", **(env_extra or {}))
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        proc = subprocess.Popen(args, cwd=cwd, stdout=out, stderr=err, stdin=subprocess.DEVNULL,
                                preexec_fn=Limits(memory_mb, cpu_seconds),
                                start_new_session=True, env=env)
        killed = False
        delay = 0.002
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if not killed and time.monotonic() - start > wall_seconds:
                try:
                    os.killpg(proc.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                killed = True
            time.sleep(delay)
            delay = min(2 * delay, 0.05)
        proc.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        stdout = out.read().decode("utf-8", "replace")
        stderr = err.read().decode("utf-8", "replace")
    cpu = usage.ru_utime + usage.ru_stime
    # Only the CPU limit sends SIGXCPU; its SIGKILL follows 10 s later.
    timed_out = killed or proc.returncode == -signal.SIGXCPU or (
        proc.returncode == -signal.SIGKILL and cpu >= 0.9 * cpu_seconds)
    return {"args": [str(a) for a in args], "rc": proc.returncode, "timed_out": timed_out,
            "seconds": round(time.monotonic() - start, 3), "cpu_seconds": round(cpu, 3),
            "rss_mb": round(usage.ru_maxrss / 1024, 1), "stdout": stdout, "stderr": stderr}


def error_lines(stderr):
    return [l for l in stderr.splitlines() if l.strip() and not l.startswith("warning:")]


def located(stderr, scene_name):
    """Problems of `error: invalid scene` output that lack FILE:LINE:COLUMN."""
    lines = error_lines(stderr)
    if "error: invalid scene" not in lines:
        return lines or ["(no message)"]
    body = lines[lines.index("error: invalid scene") + 1:]
    prefix = re.compile(re.escape(scene_name) + r":\d+:\d+: ")
    # A flood of problems is summarized (core/scene/diagnostics.h):
    # "  ... and N more problems ..." lines follow located ones.
    summary = re.compile(r"  \.\.\. and \d+ more problems")
    bad = [l for l in body if not prefix.match(l) and not summary.match(l)]
    return bad if body else ["(no message after 'error: invalid scene')"]
