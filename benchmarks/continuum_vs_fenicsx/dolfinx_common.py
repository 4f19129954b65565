"""What dolfinx_mandel.py and dolfinx_heat.py share: the direct solver, the
timed steps and the report."""
import json
import time

import numpy as np
from petsc4py import PETSc


def direct_solver(a, factorization, package, ordering=None):
    """A KSP that only applies a factorization (PETSc's `lu` or
    `cholesky`) of `a` by `package` (umfpack, mumps, cholmod, petsc), in
    `ordering` where given."""
    ksp = PETSc.KSP().create(PETSc.COMM_SELF)
    ksp.setOperators(a)
    ksp.setType(PETSc.KSP.Type.PREONLY)
    pc = ksp.getPC()
    pc.setType(factorization)
    if ordering:
        pc.setFactorOrdering(ordering)
    pc.setFactorSolverType(package)
    return ksp


def timed_steps(steps, ksp, step):
    """Runs `step` `steps` times, the KSP set up (factorized) in the first:
    the first step's time and the later steps' mean (None without them)."""
    later = []
    first = None
    for k in range(steps):
        t0 = time.perf_counter()
        if k == 0:
            ksp.setUp()
        step()
        elapsed = time.perf_counter() - t0
        if k == 0:
            first = elapsed
        else:
            later.append(elapsed)
    return first, float(np.mean(later)) if later else None


def report(result, json_path, width):
    """The results printed a key per line, and written as JSON when asked."""
    for key, value in result.items():
        if isinstance(value, float):
            print("%-*s %.15g" % (width, key, value))
        else:
            print("%-*s %s" % (width, key, value))
    if json_path:
        with open(json_path, "w") as out:
            json.dump(result, out, indent=2)
            out.write("\n")
