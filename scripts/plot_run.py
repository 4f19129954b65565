#!/usr/bin/env python3
"""Draw the two pictures of a Fissure run (docs/output.md, "Pictures").

    scripts/plot_run.py OUTDIR

Runs scripts/plot_monitors.py and scripts/plot_final_state.py on OUTDIR in
one python process: what `fissure run` calls after a run
(coupling/plot_script.cpp). Each script on its own imports matplotlib again,
about 1 s of CPU a run. A picture one script cannot draw does not stop the
other; the exit status is the first non-zero one.
"""
import sys
import traceback
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import plot_final_state  # noqa: E402
import plot_monitors  # noqa: E402


def run(script, outdir):
    """Exit status of `script`'s main on OUTDIR, as if run alone."""
    sys.argv = [script.__file__, outdir]
    try:
        return script.main() or 0
    except SystemExit as e:
        if e.code not in (None, 0):
            print(e.code, file=sys.stderr)
            return e.code if isinstance(e.code, int) else 1
        return 0
    except Exception:  # a script's failure leaves the other picture to be drawn
        traceback.print_exc()
        return 1


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    outdir = sys.argv[1]
    codes = [run(plot_monitors, outdir), run(plot_final_state, outdir)]
    return next((c for c in codes if c != 0), 0)


if __name__ == "__main__":
    sys.exit(main())
