#!/usr/bin/python3
"""Mandel's problem with dolfinx 0.5 (FEniCSx), set up as Fissure solves it.

The counterpart of configs/continuum_mandel.yaml with `scheme: monolithic`,
for a side-by-side speed benchmark against Fissure's continuum solver:

  * the quarter [0,1] x [0,1] m, plane strain, N x N squares each cut into
    two triangles along a diagonal that alternates like a chessboard (the
    mesh is built from explicit vertex and cell arrays, as Fissure's);
  * Taylor-Hood triangles (P2 displacement, P1 pressure), one mixed space;
  * backward Euler, dt = 0.01 s, the symmetric monolithic u-p system;
  * rollers on the left (u_x = 0) and bottom (u_y = 0); the right side
    traction-free and drained (p = 0 from the first step on); the top a rigid
    frictionless impermeable plate: every top u_y dof is the same unknown w,
    which carries the resultant -1 MN/m;
  * the plate by a reduction: the full matrix A from dolfinx, a prolongation
    P (full dofs x reduced dofs) that sends all top u_y dofs to one column and
    the Dirichlet dofs to none, and (P^T A P) y = P^T b + F e_w, reduced in
    PETSc (PtAP) and solved by a direct LU (UMFPACK or MUMPS) factorized once
    per distinct step size;
  * an undrained start at t = 0: the same system with dt = 0, zero old state
    and no drained side.

Usage: /usr/bin/python3 dolfinx_mandel.py N STEPS [--solver umfpack|mumps|krylov]
                                          [--rhs matrix|form] [--json OUT]

--solver krylov: the steps by Fissure's Krylov set-up (KRYLOV_OPTIONS,
krylov_solver: GMRES, an upper Schur field split, BoomerAMG), the undrained
start by UMFPACK; reports the iterations per step.

--rhs matrix (default): the right-hand side's bilinear form
  b((u_n, p_n), (v, q)) = -alpha q div(u_n) dx - (1/M) p_n q dx
  is assembled once as a matrix B; each step computes b = B x_n (as Fissure
  does, with its preassembled coupling and storage matrices).
--rhs form: each step assembles the linear form L(v, q) with dolfinx's
  assemble_vector from the old state's Function.
Either way the reduction is the sparse product P^T b in PETSc.

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
import dolfinx.mesh  # noqa: E402

from dolfinx_common import direct_solver, report, timed_steps  # noqa: E402

_T_IMPORT = time.perf_counter() - _T_START

# The material and loading (SI units), as configs/continuum_mandel.yaml.
E = 1.0e9             # Young's modulus, Pa
NU = 0.2              # Poisson's ratio
ALPHA = 1.0           # Biot coefficient
BIOT_M = 2.0e9        # Biot modulus, Pa
PERMEABILITY = 1e-13  # m^2
VISCOSITY = 1e-3      # Pa s
PLATE_FORCE = -1.0e6  # N/m on the quarter's plate (downward)
DT = 0.01             # s
G = E / (2 * (1 + NU))
LAMBDA = E * NU / ((1 + NU) * (1 - 2 * NU))
MOBILITY = PERMEABILITY / VISCOSITY


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("N", type=int, help="cells per side")
    parser.add_argument("STEPS", type=int, help="time steps of 0.01 s after the undrained start")
    parser.add_argument("--solver", choices=["umfpack", "mumps", "krylov"], default="umfpack",
                        help="the LU factorization package (default umfpack)")
    parser.add_argument("--rhs", choices=["matrix", "form"], default="matrix",
                        help="right-hand side by a preassembled matrix (default) or "
                             "by assembling the linear form each step")
    parser.add_argument("--json", metavar="OUT", help="write the results to this JSON file")
    return parser.parse_args()


def chessboard_mesh(comm, n):
    """The N x N squares of the unit square, vertex (i, j) at (i/N, j/N) with
    index j (N+1) + i, cut along alternating diagonals as Fissure's mesh."""
    i, j = np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="xy")
    x = np.column_stack([i.ravel() / n, j.ravel() / n]).astype(np.float64)
    ci, cj = np.meshgrid(np.arange(n), np.arange(n), indexing="xy")
    ci, cj = ci.ravel(), cj.ravel()
    a = cj * (n + 1) + ci
    b = a + 1
    d = a + (n + 1) + 1
    e = a + (n + 1)
    even = (ci + cj) % 2 == 0
    first = np.where(even[:, None], np.column_stack([a, b, d]), np.column_stack([a, b, e]))
    second = np.where(even[:, None], np.column_stack([a, d, e]), np.column_stack([b, d, e]))
    cells = np.empty((2 * n * n, 3), dtype=np.int64)
    cells[0::2] = first
    cells[1::2] = second
    domain = ufl.Mesh(ufl.VectorElement("Lagrange", ufl.triangle, 1))
    return dolfinx.mesh.create_mesh(comm, cells, x, domain)


def prolongation(n_full, dirichlet, plate):
    """P (n_full x n_reduced), AIJ: each free dof not on the plate its own
    column (in dof order), all plate dofs the last column, Dirichlet dofs none.
    Returns P and the plate's column."""
    column = np.zeros(n_full, dtype=np.int32)
    column[dirichlet] = -1
    column[plate] = -2
    own = column == 0
    n_own = int(np.count_nonzero(own))
    column[own] = np.arange(n_own, dtype=np.int32)
    w = n_own
    column[plate] = w
    has = column >= 0
    indptr = np.zeros(n_full + 1, dtype=np.int32)
    indptr[1:] = np.cumsum(has)
    indices = column[has].astype(np.int32)
    data = np.ones(indices.size, dtype=PETSc.ScalarType)
    p = PETSc.Mat().createAIJ(size=(n_full, n_own + 1), csr=(indptr, indices, data),
                              comm=PETSc.COMM_SELF)
    p.assemble()
    return p, w


def lu_solver(a_reduced, package):
    return direct_solver(a_reduced, PETSc.PC.Type.LU, package)


# Fissure's Krylov set-up of the monolithic system (core/linear/
# distributed_system.cpp, continuum/poroelasticity/continuum_linear_solver.cpp):
# right-preconditioned GMRES(100) to 1e-12, an upper Schur field split with
# one BoomerAMG V-cycle per block, the Schur preconditioner S + dt H + B_FS.
KRYLOV_OPTIONS = {
    "ksp_type": "gmres", "ksp_gmres_restart": 100, "ksp_pc_side": "right",
    "ksp_rtol": 1e-12, "ksp_atol": 1e-300, "ksp_max_it": 2000,
    "pc_type": "fieldsplit", "pc_fieldsplit_type": "schur",
    "pc_fieldsplit_schur_fact_type": "upper",
    "fieldsplit_0_ksp_type": "preonly", "fieldsplit_0_pc_type": "hypre",
    "fieldsplit_0_pc_hypre_type": "boomeramg",
    "fieldsplit_0_pc_hypre_boomeramg_strong_threshold": 0.7,
    "fieldsplit_0_pc_hypre_boomeramg_coarsen_type": "HMIS",
    "fieldsplit_0_pc_hypre_boomeramg_interp_type": "ext+i",
    "fieldsplit_0_pc_hypre_boomeramg_agg_nl": 1,
    "fieldsplit_0_pc_hypre_boomeramg_P_max": 4,
    "fieldsplit_1_ksp_type": "preonly", "fieldsplit_1_pc_type": "hypre",
    "fieldsplit_1_pc_hypre_type": "boomeramg",
}


def krylov_solver(a_reduced, pressure_rows, schur):
    """Fissure's set-up on the reduced system: the flow rows negated (the
    Schur complement positive), both sides scaled by 1/sqrt|diagonal| (the
    pressure rows by the Schur preconditioner's). Returns the KSP and the
    scaling vectors (row factor, column factor) to apply to b and y."""
    n = a_reduced.getSize()[0]
    diagonal = a_reduced.getDiagonal().getArray().copy()
    diagonal[pressure_rows] = schur.getDiagonal().getArray()
    scale = np.where(np.abs(diagonal) > 0, 1 / np.sqrt(np.abs(diagonal)), 1.0)
    sign = np.ones(n)
    sign[pressure_rows] = -1
    left, right = a_reduced.createVecs()
    left.setArray(sign * scale)
    right.setArray(scale)
    a_reduced.diagonalScale(left, right)
    s_p = PETSc.Vec().createWithArray(scale[pressure_rows].copy(), comm=PETSc.COMM_SELF)
    schur.diagonalScale(s_p, s_p)
    is_u = PETSc.IS().createGeneral(np.setdiff1d(np.arange(n, dtype=np.int32), pressure_rows),
                                    comm=PETSc.COMM_SELF)
    is_p = PETSc.IS().createGeneral(pressure_rows.astype(np.int32), comm=PETSc.COMM_SELF)
    options = PETSc.Options()
    for key, value in KRYLOV_OPTIONS.items():
        options["mandel_" + key] = value
    ksp = PETSc.KSP().create(PETSc.COMM_SELF)
    ksp.setOptionsPrefix("mandel_")
    ksp.setOperators(a_reduced)
    pc = ksp.getPC()
    pc.setType(PETSc.PC.Type.FIELDSPLIT)
    pc.setFieldSplitIS(("0", is_u), ("1", is_p))
    pc.setFieldSplitSchurPreType(PETSc.PC.SchurPreType.USER, schur)
    ksp.setFromOptions()
    ksp.setInitialGuessNonzero(True)
    return ksp, left, right


def factor_size(ksp, package):
    """The LU factor's size where the package tells it, else None."""
    out = {}
    try:
        f = ksp.getPC().getFactorMatrix()
        if package == "mumps":
            # INFOG(20): estimated entries in the factors (negative: millions);
            # INFOG(29): effective entries in the factors (negative: millions).
            for k in (20, 29):
                v = int(f.getMumpsInfog(k))
                out["infog%d" % k] = v
                out["infog%d_entries" % k] = v if v >= 0 else -v * 1_000_000
        else:
            info = f.getInfo()
            if info.get("nz_used", 0) > 0:
                out["nz_used"] = int(info["nz_used"])
    except Exception:  # not accessible through this package
        pass
    return out or None


def main():
    args = parse_arguments()
    comm = MPI.COMM_WORLD
    if comm.size != 1:
        sys.exit("dolfinx_mandel.py runs on one process")
    n, steps = args.N, args.STEPS

    # --- the mesh ---------------------------------------------------------
    t0 = time.perf_counter()
    mesh = chessboard_mesh(comm, n)
    t_mesh = time.perf_counter() - t0

    # --- set-up: spaces, forms, the steps' matrix and its reduction ---------
    t0 = time.perf_counter()
    cell = mesh.ufl_cell()
    taylor_hood = ufl.MixedElement([ufl.VectorElement("Lagrange", cell, 2),
                                    ufl.FiniteElement("Lagrange", cell, 1)])
    W = dolfinx.fem.FunctionSpace(mesh, taylor_hood)
    n_full = W.dofmap.index_map.size_local * W.dofmap.index_map_bs

    u, p = ufl.TrialFunctions(W)
    v, q = ufl.TestFunctions(W)
    old = dolfinx.fem.Function(W)  # (u_n, p_n)
    u_n, p_n = ufl.split(old)
    dt = dolfinx.fem.Constant(mesh, PETSc.ScalarType(DT))

    def eps(w):
        return ufl.sym(ufl.grad(w))

    def effective_stress(w):
        return 2 * G * eps(w) + LAMBDA * ufl.tr(eps(w)) * ufl.Identity(2)

    a_form = dolfinx.fem.form(
        ufl.inner(effective_stress(u), eps(v)) * ufl.dx
        - ALPHA * p * ufl.div(v) * ufl.dx - ALPHA * q * ufl.div(u) * ufl.dx
        - (1 / BIOT_M) * p * q * ufl.dx
        - dt * MOBILITY * ufl.inner(ufl.grad(p), ufl.grad(q)) * ufl.dx)
    # The old state's part: b = B x_n, or L assembled from the Function.
    b_form = dolfinx.fem.form(-ALPHA * q * ufl.div(u) * ufl.dx - (1 / BIOT_M) * p * q * ufl.dx)
    L_form = dolfinx.fem.form(-ALPHA * q * ufl.div(u_n) * ufl.dx - (1 / BIOT_M) * p_n * q * ufl.dx)

    # The boundaries' dofs (in W's numbering).
    fdim = mesh.topology.dim - 1

    def side(marker):
        return dolfinx.mesh.locate_entities_boundary(mesh, fdim, marker)

    left = side(lambda x: np.isclose(x[0], 0.0))
    bottom = side(lambda x: np.isclose(x[1], 0.0))
    right = side(lambda x: np.isclose(x[0], 1.0))
    top = side(lambda x: np.isclose(x[1], 1.0))
    ux, uy, pw = W.sub(0).sub(0), W.sub(0).sub(1), W.sub(1)
    fixed_u = np.union1d(dolfinx.fem.locate_dofs_topological(ux, fdim, left),
                         dolfinx.fem.locate_dofs_topological(uy, fdim, bottom))
    drained = dolfinx.fem.locate_dofs_topological(pw, fdim, right)
    plate = dolfinx.fem.locate_dofs_topological(uy, fdim, top)
    fixed_steps = np.union1d(fixed_u, drained)

    A = dolfinx.fem.petsc.assemble_matrix(a_form)
    A.assemble()
    P, w_steps = prolongation(n_full, fixed_steps, plate)
    A_steps = A.PtAP(P)
    n_reduced = A_steps.getSize()[0]
    if args.rhs == "matrix":
        B = dolfinx.fem.petsc.assemble_matrix(b_form)
        B.assemble()
        b_full = B.createVecLeft()
    else:
        b_full = dolfinx.fem.petsc.create_vector(L_form)
    f_steps, y_steps = A_steps.createVecs()
    f_steps.zeroEntries()
    f_steps.setValue(w_steps, PLATE_FORCE)
    f_steps.assemble()
    b_steps = f_steps.duplicate()
    x = old.vector  # the full state (u, p), updated in place each step
    t_setup = time.perf_counter() - t0

    # --- the monitors' vertex dofs: p at (0,0) and (0.5,0), u_x at (0.5,0) ---
    Q, _ = W.sub(1).collapse()
    Vx, _ = W.sub(0).sub(0).collapse()

    def dof_at(sub, collapsed, point):
        def marker(xx):
            return np.isclose(xx[0], point[0]) & np.isclose(xx[1], point[1])
        dofs = dolfinx.fem.locate_dofs_geometrical((sub, collapsed), marker)[0]
        if len(dofs) != 1:
            sys.exit("no vertex dof at %s (N must be even)" % (point,))
        return int(dofs[0])

    monitors = [dof_at(pw, Q, (0.0, 0.0)), dof_at(pw, Q, (0.5, 0.0)), dof_at(ux, Vx, (0.5, 0.0))]

    # --- the undrained start: dt = 0, zero old state, no drained side ------
    t0 = time.perf_counter()
    dt.value = 0.0
    A0 = dolfinx.fem.petsc.assemble_matrix(a_form)
    A0.assemble()
    P0, w0 = prolongation(n_full, fixed_u, plate)
    A0_reduced = A0.PtAP(P0)
    n_reduced_undrained = A0_reduced.getSize()[0]
    start_solver = "umfpack" if args.solver == "krylov" else args.solver  # a direct start
    ksp0 = lu_solver(A0_reduced, start_solver)
    ksp0.setUp()
    b0, y0 = A0_reduced.createVecs()
    b0.zeroEntries()  # P^T b with b = 0 (zero old state), plus the plate's force
    b0.setValue(w0, PLATE_FORCE)
    b0.assemble()
    ksp0.solve(b0, y0)
    P0.mult(y0, x)
    old.x.scatter_forward()
    t_undrained = time.perf_counter() - t0
    values = x.getArray(readonly=True)
    undrained = {"p_centre": float(values[monitors[0]]), "p_half": float(values[monitors[1]]),
                 "ux_half": float(values[monitors[2]])}
    factor_undrained = factor_size(ksp0, start_solver)
    ksp0.destroy()
    A0_reduced.destroy()
    A0.destroy()
    dt.value = DT

    # --- the steps ---------------------------------------------------------
    if args.solver == "krylov":
        # The reduced rows of the pressure dofs, and the Schur
        # preconditioner S + dt H + B_FS on them (beta_FS = alpha^2 / K_dr,
        # K_dr = lambda + G).
        indicator = A.createVecRight()
        indicator.zeroEntries()
        pressure_full = np.array(W.sub(1).collapse()[1], dtype=np.int32)
        indicator.setValues(pressure_full, np.ones(pressure_full.size))
        indicator.assemble()
        on_pressure = A_steps.createVecRight()
        P.multTranspose(indicator, on_pressure)
        pressure_rows = np.flatnonzero(on_pressure.getArray() > 0.5).astype(np.int32)
        beta = ALPHA ** 2 / (LAMBDA + G)
        schur_form = dolfinx.fem.form(
            (1 / BIOT_M + beta) * p * q * ufl.dx
            + dt * MOBILITY * ufl.inner(ufl.grad(p), ufl.grad(q)) * ufl.dx)
        S_full = dolfinx.fem.petsc.assemble_matrix(schur_form)
        S_full.assemble()
        S_reduced = S_full.PtAP(P)
        is_pressure = PETSc.IS().createGeneral(pressure_rows, comm=PETSc.COMM_SELF)
        schur = S_reduced.createSubMatrix(is_pressure, is_pressure)
        ksp, row_scale, column_scale = krylov_solver(A_steps, pressure_rows, schur)
        iterations = []
    else:
        ksp = lu_solver(A_steps, args.solver)
    z_steps = y_steps.duplicate()
    z_steps.zeroEntries()

    def step():
        if args.rhs == "matrix":
            B.mult(x, b_full)
        else:
            with b_full.localForm() as local:
                local.set(0.0)
            dolfinx.fem.petsc.assemble_vector(b_full, L_form)
        P.multTranspose(b_full, b_steps)
        b_steps.axpy(1.0, f_steps)
        if args.solver == "krylov":
            b_steps.pointwiseMult(b_steps, row_scale)
            ksp.solve(b_steps, z_steps)  # z: the previous step's, the first guess
            iterations.append(ksp.getIterationNumber())
            y_steps.pointwiseMult(z_steps, column_scale)
        else:
            ksp.solve(b_steps, y_steps)
        P.mult(y_steps, x)
        if args.rhs == "form":
            old.x.scatter_forward()

    # The first step factorizes, once for dt = 0.01 s.
    t_first, t_step_mean = timed_steps(steps, ksp, step)
    factor_steps = (factor_size(ksp, args.solver) if steps > 0 and args.solver != "krylov"
                    else None)

    values = x.getArray(readonly=True)
    p_centre, p_half, ux_half = (float(values[i]) for i in monitors)

    result = {
        "code": "dolfinx %s" % dolfinx.__version__,
        "petsc": "%d.%d.%d" % PETSc.Sys.getVersion(),
        "N": n,
        "steps": steps,
        "t_end": steps * DT,
        "solver": args.solver,
        "rhs": args.rhs,
        "unknowns_reduced": n_reduced,
        "unknowns_reduced_undrained": n_reduced_undrained,
        "dofs_full": n_full,
        "time_import": _T_IMPORT,
        "time_mesh": t_mesh,
        "time_setup": t_setup,
        "time_undrained": t_undrained,
        "time_first_step": t_first,
        "time_step_mean": t_step_mean,
        "time_total": time.perf_counter() - _T_START,
        "peak_rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss,
        "undrained_p_centre": undrained["p_centre"],
        "undrained_p_half": undrained["p_half"],
        "undrained_ux_half": undrained["ux_half"],
        "p_centre": p_centre,
        "p_half": p_half,
        "ux_half": ux_half,
        "factor_undrained": factor_undrained,
        "factor_steps": factor_steps,
    }
    if args.solver == "krylov":
        result["iterations_per_step"] = float(np.mean(iterations[1:])) if len(iterations) > 1 \
            else None
    report(result, args.json, 28)


if __name__ == "__main__":
    main()
