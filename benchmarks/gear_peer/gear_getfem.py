#!/usr/bin/python3
"""A spur gear pair at one position solved by GetFEM on dealvem's meshes.

The peer solution of benchmarks/gear_peer/run.sh. It reads the two legacy-VTK
polygon meshes that benchmark_gear_peer_mesh writes for the pinion and the
gear (the meshes dealvem's contact run reads too), cuts every polygon into
triangles on its own vertices (hertz_peer/hertz_getfem.py's triangulate():
no new vertices, so the triangles have exactly dealvem's nodes and boundary
edges) and solves, with Lagrange P2 (or P1) displacements, GetFEM 5.4:

* plane-strain isotropic linear elasticity in both bodies (the 3D Lame
  coefficients in 2D);
* the gear's bore (boundary id 0 of its file, 10 in dealvem's run) clamped,
  the pinion's bore (id 0) turned rigidly about the pinion's centre c1 by the
  angle theta: u = (R(theta) - I)(x - c1) at its nodes (both by
  add_Dirichlet_condition_with_simplification; the P2 nodes on a straight
  bore chord get the same exact rotation); or, with --torque T, tied to a
  small rotation about c1 whose angle is an unknown and whose dual is T
  (dealvem's 'torque' mode of 'Rotation about centre');
* frictionless unilateral contact between the pinion's teeth (id 1, master)
  and the gear's teeth (id 1 of its file, slave), the integral (mortar-type)
  Alart-Curnier formulation of hertz_getfem.py written in GetFEM's weak form
  language, with a scalar P1 pressure p on the slave flank:

      int_S p (v_slave - v_master(T x)) . n  ds
      + int_S (p - pos_part(p - r g)) q  ds = 0,
      g = (T x + u_master(T x) - x - u_slave) . n,

  (hertz_getfem.py divides the second integral by r; the equations are the
  same, but GetFEM's Newton tests one norm over all rows, and with 1/r these
  rows are so small against the force rows that an iterate with a wrong
  contact set passed as converged under the torque load),

  n the slave's outward normal and T x the point of the master flank that a
  ray from x along n meets (GetFEM's raytracing interpolate transformation).
  The transformation is given a displacement that is identically zero, so
  the pairing is made once in the reference configuration: the small-sliding
  model of dealvem's node-to-node contact, and the transformation does not
  depend on the unknowns (its derivative, which GetFEM leaves out, is zero).
  Points whose ray meets no master face are open (p = 0). r = 0.1 E*/h (the
  choice hertz_getfem.py documents), h the longest slave edge within 0.5 mm
  of the pitch point. The semi-smooth system is solved by GetFEM's Newton
  (MUMPS) from a uniform pressure of 1000 MPa on the window (as
  hertz_getfem.py starts from p0): the first step closes the window where
  the gap is smallest, which also holds a pinion that is free to turn under
  a torque. Tried on run.sh's level 1 (angle): r = 0.01 and 1 E*/h move the
  peak pressure by +0.007 % and -0.006 % and the torque by less than 0.001 %
  (8 and 7 Newton iterations instead of 5); 4 or 16 pieces per edge in the
  contact quadrature instead of 8 move both by less than 0.003 %.

  The contact boundaries are the faces of the teeth within a window about the
  pitch point (slave: --slave-window, default 1 mm; master: 1.5 times that):
  the rest of the teeth is apart by the backlash and tip relief (compare.py
  reports how far from the pitch point dealvem's farthest closed pair lies).

Output (JSON): sizes, Newton iterations, timings, the contact force and its
moments about both centres (the transmitted torques), and the nodal profile
of the pressure (x, y, p, gap) on the slave window.
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "hertz_peer"))
from hertz_getfem import read_vtk, triangulate  # noqa: E402  (numpy only)

BORE, TEETH = 0, 1  # boundary ids in both files (the gear's offset of 10 is dealvem's)
# GetFEM region numbers
RG_BORE, RG_WINDOW = 10, 20


def gf_mesh(gf, points, tris):
    """A GetFEM mesh of straight triangles in the order of tris; returns the
    mesh and the map boundary edge (i, j), i < j -> (convex, face)."""
    m = gf.Mesh("empty", 2)
    cv = m.add_convex(gf.GeoTrans("GT_PK(2,1)"), np.transpose(points[tris], (2, 1, 0)))
    assert list(cv) == list(range(len(tris)))
    faces = {}
    for c, t in enumerate(tris):
        for f in range(3):  # face f is opposite vertex f
            i, j = t[(f + 1) % 3], t[(f + 2) % 3]
            faces[(min(i, j), max(i, j))] = (c, f)
    return m, faces


def set_region(m, faces, edges, region):
    cvf = np.array([faces[e] for e in edges], dtype=int).T
    m.set_region(region, cvf)
    return len(edges)


def window_edges(points, boundary, bid, centre, radius):
    """Boundary edges with id bid whose midpoint lies within radius of centre."""
    c = np.asarray(centre)
    return [e for e, b in boundary.items()
            if b == bid and np.linalg.norm(0.5 * (points[e[0]] + points[e[1]]) - c) <= radius]


def solve(a):
    import getfem as gf

    gf.util_trace_level(0)
    t_start = time.perf_counter()
    c1, c2, pitch = np.array(a.pinion_centre), np.array(a.gear_centre), np.array(a.pitch_point)

    body = {}
    for name, path in (("pinion", a.pinion), ("gear", a.gear)):
        pts, polys, bnd = read_vtk(path)
        tris, counts = triangulate(pts, polys)
        body[name] = dict(points=pts, tris=tris, boundary=bnd, counts=counts, polygons=len(polys))

    mp, fp = gf_mesh(gf, body["pinion"]["points"], body["pinion"]["tris"])
    mg, fg = gf_mesh(gf, body["gear"]["points"], body["gear"]["tris"])
    bp, bg = body["pinion"]["boundary"], body["gear"]["boundary"]
    set_region(mp, fp, [e for e, b in bp.items() if b == BORE], RG_BORE)
    set_region(mg, fg, [e for e, b in bg.items() if b == BORE], RG_BORE)
    slave_edges = window_edges(body["gear"]["points"], bg, TEETH, pitch, a.slave_window)
    master_edges = window_edges(body["pinion"]["points"], bp, TEETH, pitch, 1.5 * a.slave_window)
    set_region(mg, fg, slave_edges, RG_WINDOW)
    set_region(mp, fp, master_edges, RG_WINDOW)
    gp = body["gear"]["points"]
    h = max(float(np.linalg.norm(gp[i] - gp[j])) for i, j in slave_edges
            if np.linalg.norm(0.5 * (gp[i] + gp[j]) - pitch) <= 0.5)

    fem = gf.Fem("FEM_PK(2,%d)" % a.order)
    mfu_p, mfu_g = gf.MeshFem(mp, 2), gf.MeshFem(mg, 2)
    mfu_p.set_fem(fem)
    mfu_g.set_fem(fem)
    mfp = gf.MeshFem(mg, 1)  # the contact pressure: P1 on the slave window
    mfp.set_fem(gf.Fem("FEM_PK(2,1)"))
    im = gf.Integ("IM_TRIANGLE(%d)" % (2 * a.order))
    mim_p, mim_g = gf.MeshIm(mp, im), gf.MeshIm(mg, im)
    # the contact integrand has kinks inside the slave edges (the master's
    # edges, pos_part at the edge of the contact zone): each slave edge is
    # integrated on `pieces` pieces with a Gauss rule of degree 6 on each
    mim_contact = gf.MeshIm(mg, gf.Integ("IM_STRUCTURED_COMPOSITE(IM_TRIANGLE(6),%d)" % a.pieces))

    md = gf.Model("real")
    md.add_fem_variable("u1", mfu_p)  # pinion (master)
    md.add_fem_variable("u2", mfu_g)  # gear (slave)
    lam = a.young * a.poisson / ((1 + a.poisson) * (1 - 2 * a.poisson))
    mu = a.young / (2 * (1 + a.poisson))
    md.add_initialized_data("lambda", [lam])
    md.add_initialized_data("mu", [mu])
    md.add_isotropic_linearized_elasticity_brick(mim_p, "u1", "lambda", "mu")
    md.add_isotropic_linearized_elasticity_brick(mim_g, "u2", "lambda", "mu")

    # the bores: the gear's clamped, the pinion's turned about c1
    md.add_Dirichlet_condition_with_simplification("u2", RG_BORE)
    if a.torque is None:
        # by the angle theta, exactly: u = (R(theta) - I)(x - c1) at the nodes
        xy = mfu_p.basic_dof_nodes()  # 2 x ndof, each node twice (x and y DoF)
        ct, st = math.cos(a.angle), math.sin(a.angle)
        dx, dy = xy[0] - c1[0], xy[1] - c1[1]
        rot = np.empty(mfu_p.nbdof())
        rot[0::2] = ((ct - 1) * dx - st * dy)[0::2]
        rot[1::2] = (st * dx + (ct - 1) * dy)[1::2]
        md.add_initialized_fem_data("bore_rotation", mfu_p, rot)
        md.add_Dirichlet_condition_with_simplification("u1", RG_BORE, "bore_rotation")
    else:
        # by the torque T: the bore's trace tied (a multiplier in the trace
        # space) to the small rotation phi (-(y - c1y), x - c1x) with phi an
        # unknown, T the dual of phi (spread over the bore's length): the
        # bore turns rigidly about c1 without translating, as dealvem's
        # 'torque' mode
        md.add_variable("phi", 1)
        md.add_multiplier("tie", mfu_p, "u1", mim_p, RG_BORE)
        turn = "[-(X(2)-%r), X(1)-%r]" % (c1[1], c1[0])
        md.add_linear_term(mim_p, "tie.(Test_u1 - Test_phi*%s) + Test_tie.(u1 - phi*%s)" % (turn, turn), RG_BORE)
        bore_length = gf.asm_generic(mim_p, 0, "1", RG_BORE)
        md.add_source_term(mim_p, "%r*Test_phi" % (a.torque / bore_length), RG_BORE)

    # contact: the pairing in the reference configuration (zero displacement)
    md.add_initialized_fem_data("zero_p", mfu_p, np.zeros(mfu_p.nbdof()))
    md.add_initialized_fem_data("zero_g", mfu_g, np.zeros(mfu_g.nbdof()))
    md.add_raytracing_transformation("T", a.release_distance)
    md.add_master_contact_boundary_to_raytracing_transformation("T", mp, "zero_p", RG_WINDOW)
    md.add_slave_contact_boundary_to_raytracing_transformation("T", mg, "zero_g", RG_WINDOW)
    md.add_filtered_fem_variable("p", mfp, RG_WINDOW)
    e_star = a.young / (2 * (1 - a.poisson**2))
    r = a.r_factor * e_star / h
    md.add_initialized_data("r", [r])
    gap = "((Interpolate(X,T) + Interpolate(u1,T) - X - u2).Normal)"
    # the complementarity rows are written without hertz_peer's factor 1/r
    # (the same equations): GetFEM's Newton measures one norm over all rows,
    # and with 1/r these rows are about 1e-6 of the force rows, so that an
    # iterate with a wrong contact set could pass as converged (it did under
    # the torque load)
    md.add_nonlinear_term(mim_contact, "p*Test_p", RG_WINDOW)
    md.add_nonlinear_term(
        mim_contact,
        "Interpolate_filter(T, p*(Test_u2 - Interpolate(Test_u1,T)).Normal"
        " - pos_part(p - r*%s)*Test_p, 1)" % gap, RG_WINDOW)
    # start from a uniform pressure (as hertz_getfem.py): the first Newton
    # step then closes the window where the gap is smallest (a free pinion
    # under a torque is held), instead of pressing the flanks through each
    # other with every node open
    md.set_variable("p", a.start_pressure * np.ones(md.variable("p").size))

    t_setup = time.perf_counter()
    args = ["max_res", a.max_res, "max_iter", 50, "lsolver", a.lsolver]
    if a.verbose:
        args.append("noisy")
    nbit, converged = md.solve(*args)
    t_solve = time.perf_counter()

    # results: the force on the pinion is +p n per slave length at the master
    # point T x, on the gear -p n at x
    def integral(expr):
        return float(gf.asm_generic(mim_contact, 0, "Interpolate_filter(T, %s, 1)" % expr, RG_WINDOW, md))

    force = [integral("p*Normal(%d)" % k) for k in (1, 2)]
    def cross_n(arm):  # the 2D cross product arm x n
        return "((%s)(1)*Normal(2) - (%s)(2)*Normal(1))" % (arm, arm)

    m_pinion = integral("p*" + cross_n("Interpolate(X,T)-[%r,%r]" % tuple(c1)))
    m_gear = integral("-p*" + cross_n("X-[%r,%r]" % tuple(c2)))
    dofs = mfp.basic_dof_on_region(RG_WINDOW)
    nodes = mfp.basic_dof_nodes(dofs).T
    p_all = md.interpolation("p", mfp, RG_WINDOW)
    # the gap; 1e3 where the ray meets no master face
    g_all = md.interpolation("Interpolate_filter(T, %s, 1) + (1 - Interpolate_filter(T, 1, 1))*1e3" % gap,
                             mfp, RG_WINDOW)
    profile = np.column_stack([nodes, p_all[dofs], g_all[dofs]])
    t_end = time.perf_counter()

    return {
        "code": "GetFEM",
        "order": a.order,
        "load": "angle" if a.torque is None else "torque",
        "torque": a.torque,
        "angle": a.angle if a.torque is None else float(md.variable("phi")[0]),
        "triangles": int(len(body["pinion"]["tris"]) + len(body["gear"]["tris"])),
        "polygons": int(body["pinion"]["polygons"] + body["gear"]["polygons"]),
        "vertices": int(len(body["pinion"]["points"]) + len(body["gear"]["points"])),
        "triangulation": {k: body[k]["counts"] for k in body},
        "slave_edges": len(slave_edges),
        "master_edges": len(master_edges),
        "h": h,
        "dofs_displacement": int(mfu_p.nbdof() + mfu_g.nbdof()),
        "dofs_pressure": int(md.variable("p").size),
        "newton_iterations": int(nbit),
        "converged": bool(converged),
        "augmentation_r": r,
        "force_x": force[0],
        "force_y": force[1],
        "moment_pinion": m_pinion,
        "moment_gear": m_gear,
        "seconds_setup": t_setup - t_start,
        "seconds_solve": t_solve - t_setup,
        "seconds_total": t_end - t_start,
        "profile": profile,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--pinion", required=True, help="VTK mesh of the pinion (bore id 0, teeth id 1)")
    ap.add_argument("--gear", required=True, help="VTK mesh of the gear (bore id 0, teeth id 1)")
    ap.add_argument("--pinion-centre", type=float, nargs=2, default=(0.0, 0.0))
    ap.add_argument("--gear-centre", type=float, nargs=2, required=True)
    ap.add_argument("--pitch-point", type=float, nargs=2, required=True)
    load = ap.add_mutually_exclusive_group(required=True)
    load.add_argument("--angle", type=float, help="rotation of the pinion's bore (rad, ccw)")
    load.add_argument("--torque", type=float, help="torque on the pinion's bore (ccw; its angle an unknown)")
    ap.add_argument("--start-pressure", type=float, default=1000.0,
                    help="the uniform pressure the Newton iteration starts from")
    ap.add_argument("--young", type=float, default=210000.0)
    ap.add_argument("--poisson", type=float, default=0.3)
    ap.add_argument("--order", type=int, choices=(1, 2), default=2)
    ap.add_argument("--slave-window", type=float, default=1.0, help="contact window radius about the pitch point")
    ap.add_argument("--release-distance", type=float, default=0.5, help="raytracing release distance")
    ap.add_argument("--r-factor", type=float, default=0.1, help="augmentation r = factor * E* / h")
    ap.add_argument("--pieces", type=int, default=8, help="pieces per slave edge of the contact quadrature")
    # GetFEM's Newton measures the residual relative to the first one; on these
    # meshes it stalls at about 7e-8 (round-off) once the contact set is found
    ap.add_argument("--max-res", type=float, default=1e-6, help="Newton target of the relative residual")
    ap.add_argument("--lsolver", default="mumps")
    ap.add_argument("--json", required=True)
    ap.add_argument("--profile", required=True, help="CSV x,y,pressure,gap at the pressure nodes")
    ap.add_argument("--verbose", action="store_true")
    a = ap.parse_args()

    res = solve(a)
    np.savetxt(a.profile, res.pop("profile"), delimiter=",", header="x,y,pressure,gap", comments="", fmt="%.15g")
    with open(a.json, "w") as f:
        json.dump(res, f, indent=1)
    print("GetFEM P%d: %d displacement DoFs + %d pressure DoFs, %d Newton iterations%s, angle %.6g, torque %.2f "
          "(pinion) %.2f (gear), solve %.2f s, total %.2f s"
          % (a.order, res["dofs_displacement"], res["dofs_pressure"], res["newton_iterations"],
             "" if res["converged"] else " (NOT CONVERGED)", res["angle"], res["moment_pinion"],
             res["moment_gear"], res["seconds_solve"], res["seconds_total"]))
    return 0 if res["converged"] else 1


if __name__ == "__main__":
    sys.exit(main())
