#!/usr/bin/python3
"""Heat conduction in a square with dolfinx 0.5 (FEniCSx), set up as
Fissure's thermal process solves benchmarks/continuum_vs_fenicsx/heat_scene.yaml.

  * the square [0, 1 m]^2, lambda = 3 W/(m K), rho c = 2.4e6 J/(m^3 K),
    initially at T0 = 100 degC, the four sides held at 0 degC from the first
    step on;
  * the mesh: Fissure's own (its nodes and triangles read from the
    results.h5 of a Fissure run, `--mesh fissure --h5 FILE`), or dolfinx's
    create_rectangle with about NODES nodes (`--mesh rectangle --nodes N`,
    for the start-up comparison);
  * P1 Lagrange, backward Euler with dt = 1000 s: (C/dt + K) T1 = C/dt T0,
    the capacity C lumped (vertex quadrature: rho c A / 3 per node, as
    Fissure's `capacity: lumped`) or consistent (as `capacity: consistent`);
  * the matrix C/dt + K assembled once with the Dirichlet rows and columns
    replaced by the identity (dolfinx's assemble_matrix with bcs) and
    factorized once (PETSc KSP preonly; CHOLMOD, MUMPS Cholesky, or PETSc's
    own LU with nested-dissection ordering);
  * the right-hand side each step, dolfinx's usual lifting either way
    (apply_lifting, ghost update, set_bc):
      --rhs form    assemble_vector of L(v) = rho c / dt T_old v dx
                    (dolfinx's usual loop; T_old a Function);
      --rhs matvec  b = (C/dt) T_old with C/dt assembled once.

Reports (printed, and as JSON with --json) the start-up (import, mesh, forms
and matrices), the first step (with the factorization), the mean of the
later steps, the peak resident memory and the temperature at the centre
(the P1 function evaluated at (0.5, 0.5), as Fissure's monitor); with
--h5 and --mesh fissure also the largest difference of the nodal
temperatures from those of the last frame of the Fissure run (which must
have taken the same steps).

Usage: /usr/bin/python3 dolfinx_heat.py STEPS (--h5 results.h5 | --mesh rectangle --nodes N)
           [--rhs form|matvec] [--solver cholmod|mumps|petsc] [--capacity lumped|consistent]
           [--json OUT]

Serial only (one MPI process), as the benchmark compares single-core runs.
"""
import time

_T_START = time.perf_counter()

import argparse  # noqa: E402
import resource  # noqa: E402
import sys  # noqa: E402

import numpy as np  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402
import ufl  # noqa: E402
import dolfinx  # noqa: E402
import dolfinx.fem  # noqa: E402
import dolfinx.fem.petsc  # noqa: E402
import dolfinx.geometry  # noqa: E402
import dolfinx.mesh  # noqa: E402

from dolfinx_common import direct_solver, report, timed_steps  # noqa: E402

_T_IMPORT = time.perf_counter() - _T_START

# As heat_scene.yaml (SI units).
LENGTH = 1.0            # m
CONDUCTIVITY = 3.0      # W/(m K)
HEAT_CAPACITY = 2.4e6   # J/(m^3 K)
T_INITIAL = 100.0       # degC
T_SIDES = 0.0           # degC
DT = 1000.0             # s


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("STEPS", type=int, help="time steps of 1000 s")
    parser.add_argument("--mesh", choices=["fissure", "rectangle"], default="fissure")
    parser.add_argument("--h5", help="Fissure's results.h5 (its thermal mesh; with --mesh "
                                     "fissure required)")
    parser.add_argument("--nodes", type=float, default=1e4,
                        help="--mesh rectangle: about this many nodes")
    parser.add_argument("--rhs", choices=["form", "matvec"], default="form")
    parser.add_argument("--solver", choices=["cholmod", "mumps", "petsc"], default="cholmod")
    parser.add_argument("--capacity", choices=["lumped", "consistent"], default="lumped")
    parser.add_argument("--json", metavar="OUT", help="write the results to this JSON file")
    return parser.parse_args()


def read_fissure_mesh(path):
    """Fissure's thermal nodes (frame 0, N x 2) and triangles (T x 3), and
    the last frame's temperatures (N) and time."""
    import h5py
    with h5py.File(path, "r") as f:
        frames = sorted(f["frames"])
        nodes = np.array(f["frames"][frames[0]]["thermal"]["nodes"], dtype=np.float64)
        triangles = np.array(f["mesh"]["thermal_triangles"], dtype=np.int64)
        last = f["frames"][frames[-1]]
        temperature = np.array(last["thermal"]["temperature"], dtype=np.float64)
        t_last = float(last.attrs["time"]) if "time" in last.attrs else None
    return nodes, triangles, temperature, t_last


def solver(a, package):
    """Cholesky (CHOLMOD, MUMPS), or PETSc's own LU in nested dissection."""
    if package == "petsc":
        return direct_solver(a, PETSc.PC.Type.LU, package, PETSc.Mat.OrderingType.ND)
    return direct_solver(a, PETSc.PC.Type.CHOLESKY, package)


def main():
    args = parse_arguments()
    comm = MPI.COMM_WORLD
    if comm.size != 1:
        sys.exit("dolfinx_heat.py runs on one process")
    steps = args.STEPS

    # --- the mesh ------------------------------------------------------------
    t0 = time.perf_counter()
    fissure_t = None
    if args.mesh == "fissure":
        if not args.h5:
            sys.exit("--mesh fissure needs --h5 (a Fissure run's results.h5)")
        x, cells, fissure_t, fissure_time = read_fissure_mesh(args.h5)
        t_read = time.perf_counter() - t0
        t0 = time.perf_counter()
        domain = ufl.Mesh(ufl.VectorElement("Lagrange", ufl.triangle, 1))
        mesh = dolfinx.mesh.create_mesh(comm, cells, x, domain)
    else:
        t_read = 0.0
        n = max(1, int(round(np.sqrt(args.nodes))) - 1)
        mesh = dolfinx.mesh.create_rectangle(comm, [np.zeros(2), np.full(2, LENGTH)], [n, n],
                                             dolfinx.mesh.CellType.triangle)
    t_mesh = time.perf_counter() - t0

    # --- forms, boundary, matrices ------------------------------------------
    t0 = time.perf_counter()
    V = dolfinx.fem.FunctionSpace(mesh, ("Lagrange", 1))
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    T = dolfinx.fem.Function(V)      # the step's end
    T_old = dolfinx.fem.Function(V)  # its start
    T_old.x.array[:] = T_INITIAL
    if args.capacity == "lumped":
        # The vertex rule on P1: the diagonal rho c A / 3, Fissure's lumping.
        dx_c = ufl.dx(metadata={"quadrature_rule": "vertex", "quadrature_degree": 1})
    else:
        dx_c = ufl.dx
    c_dt = HEAT_CAPACITY / DT
    a_form = dolfinx.fem.form(c_dt * u * v * dx_c
                              + CONDUCTIVITY * ufl.inner(ufl.grad(u), ufl.grad(v)) * ufl.dx)
    tdim = mesh.topology.dim
    mesh.topology.create_connectivity(tdim - 1, tdim)
    sides = dolfinx.mesh.exterior_facet_indices(mesh.topology)
    bc = dolfinx.fem.dirichletbc(PETSc.ScalarType(T_SIDES),
                                 dolfinx.fem.locate_dofs_topological(V, tdim - 1, sides), V)
    A = dolfinx.fem.petsc.assemble_matrix(a_form, bcs=[bc])
    A.assemble()
    if args.rhs == "form":
        L_form = dolfinx.fem.form(c_dt * T_old * v * dx_c)
        b = dolfinx.fem.petsc.create_vector(L_form)
    else:
        C = dolfinx.fem.petsc.assemble_matrix(dolfinx.fem.form(c_dt * u * v * dx_c))
        C.assemble()
        b = A.createVecLeft()
    t_setup = time.perf_counter() - t0
    n_dofs = V.dofmap.index_map.size_local

    # --- the steps -----------------------------------------------------------
    ksp = solver(A, args.solver)

    def step():
        if args.rhs == "form":
            with b.localForm() as local:
                local.set(0.0)
            dolfinx.fem.petsc.assemble_vector(b, L_form)
        else:
            C.mult(T_old.vector, b)
        dolfinx.fem.petsc.apply_lifting(b, [a_form], bcs=[[bc]])
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        dolfinx.fem.petsc.set_bc(b, [bc])
        ksp.solve(b, T.vector)
        T.x.scatter_forward()
        T_old.x.array[:] = T.x.array

    t_first, t_step_mean = timed_steps(steps, ksp, step)  # the first factorizes
    factor_nz = None
    try:
        info = ksp.getPC().getFactorMatrix().getInfo()
        factor_nz = int(info.get("nz_used", 0)) or None
    except Exception:  # not told by this package
        pass

    # --- the centre, and the nodal values against Fissure's -----------------
    centre = np.array([[LENGTH / 2, LENGTH / 2, 0.0]])
    tree = dolfinx.geometry.BoundingBoxTree(mesh, tdim)
    candidates = dolfinx.geometry.compute_collisions(tree, centre)
    cell = dolfinx.geometry.compute_colliding_cells(mesh, candidates, centre).links(0)[0]
    t_centre = float(T.eval(centre, np.array([cell], dtype=np.int32))[0])
    difference = None
    if fissure_t is not None and steps > 0:
        # P1 on a P1 geometry: cell by cell, the function's dofs and the
        # geometry's nodes come in the same order; the geometry's nodes know
        # their index in the input (Fissure's node numbers).
        geometry = mesh.geometry.dofmap.array.reshape(-1, 3)
        dofs = V.dofmap.list.array.reshape(-1, 3)
        node_of_dof = np.empty(n_dofs, dtype=np.int64)
        node_of_dof[dofs.ravel()] = np.asarray(mesh.geometry.input_global_indices)[
            geometry.ravel()]
        mine = T.x.array[:n_dofs]
        theirs = fissure_t[node_of_dof]
        scale = np.max(np.abs(theirs))
        difference = {"max_abs": float(np.max(np.abs(mine - theirs))),
                      "max_relative_to_max": float(np.max(np.abs(mine - theirs)) / scale),
                      "fissure_time": fissure_time}

    result = {
        "code": "dolfinx %s" % dolfinx.__version__,
        "petsc": "%d.%d.%d" % PETSc.Sys.getVersion(),
        "mesh": args.mesh,
        "nodes": int(mesh.geometry.x.shape[0]),
        "triangles": int(mesh.topology.index_map(tdim).size_local),
        "unknowns": n_dofs,
        "steps": steps,
        "t_end": steps * DT,
        "solver": args.solver,
        "rhs": args.rhs,
        "capacity": args.capacity,
        "time_import": _T_IMPORT,
        "time_read_mesh": t_read,
        "time_mesh": t_mesh,
        "time_setup": t_setup,
        "time_first_step": t_first,
        "time_step_mean": t_step_mean,
        "time_total": time.perf_counter() - _T_START,
        "peak_rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss,
        "factor_nz": factor_nz,
        "T_centre": t_centre,
        "fissure_difference": difference,
    }
    report(result, args.json, 22)


if __name__ == "__main__":
    main()
