#!/usr/bin/python3
"""NAFEMS Hertz contact solved by GetFEM on the meshes of dealvem's step-3.

A peer solution for benchmarks/hertz_peer/run.sh. It reads the two legacy-VTK
polygon meshes that `step-3 --study` writes (hertz-block-L.vtk and
hertz-cylinder-L.vtk), cuts every polygon into triangles without adding
vertices, and solves the same problem as examples/step-3/step-3.cc with
Lagrange P1 or P2 displacements (GetFEM 5.4, Debian's python3-getfem):

* plane-strain isotropic linear elasticity in both bodies
  (add_isotropic_linearized_elasticity_brick with the 3D Lame coefficients,
  which is plane strain in 2D);
* the block's bottom (boundary id 2) fixed, nodally
  (add_Dirichlet_condition_with_simplification);
* the cylinder's flat cut y = 50 (id 1) is a rigid plate, as dealvem's
  "Rigid boundary = 11 : 0, -P": its trace is tied to a rigid motion
  u = (-theta (y - 50), w + theta x) by a multiplier in the trace space of
  the displacement (exact nodal tie); w and theta form one global
  2-vector variable "rig", and the load enters as the work -P w (P is the
  dual of w). The horizontal translation of the plate is left out, which is
  dealvem's point constraint u_x = 0 at the cut's centre (0, 50);
* frictionless unilateral contact between the block's top (id 3, master)
  and the cylinder's arc (id 0, slave), written in GetFEM's weak form
  language: a P1 multiplier p on the whole arc (the contact pressure, per
  unit length of the flat master surface) and the integral (mortar-type)
  Alart-Curnier formulation

      - int_arc w p (v_slave,y - v_master,y(x)) ds
      + int_arc (w / r) (p - pos_part(p - r g)) q ds = 0,

  with w = |n_y| (so that w ds = dx: p is a pressure on the master),
  the gap g = y + u_slave,y - u_master,y(x), and the master's values taken
  at the point (x, 0) straight below the slave point: the master surface is
  the flat line y = 0 with the normal (0, 1), so this vertical projection is
  the (small-sliding, reference-configuration) normal projection. The
  transformation is GetFEM's add_interpolate_transformation_from_expression.
  r = 0.1 E* / h is the augmentation parameter. Tried on level 1, P1, with
  r = 0.01, 0.1, 1, 10, 100 times E*/h: up to E*/h the pressure inside the
  contact zone hardly changes (by < 0.01 % of p0), a smaller r leaves
  smaller oscillations of the multiplier just outside the zone, and 0.1
  took the fewest Newton iterations (6; 11 with E*/h, 35 with 100 E*/h).
  The semi-smooth system is solved by GetFEM's Newton solver (md.solve).

The contact term is written out in the weak form language rather than taken
from one of GetFEM's contact bricks (add_integral_contact_between_
nonmatching_meshes_brick and relatives, which were not tried here): so the
formulation is visible in this file, and its projection is the same
small-sliding, reference-configuration one that dealvem uses.

Output: a JSON file with sizes, Newton iterations, timings and the force
check, and a CSV file with the multiplier at its nodes on the arc
(x, y, pressure, gap) -- the raw nodal values, compared with Hertz's formula
by compare.py, which counts a node as closed where the Alart-Curnier
indicator p - r g is positive. --refine N refines the triangulation
uniformly N times (the new vertices on the arc are moved onto the circle)
for a fine reference.

The module's mesh and Hertz helpers are used by compare.py too, so GetFEM is
imported only inside solve().
"""

import argparse
import json
import math
import os
import sys
import time

import numpy as np

# The Hertz problem (examples/step-3/step-3.cc, namespace Hertz).
R = 50.0
E_CYL = 70000.0
E_BLOCK = 210000.0
NU = 0.3
P = 35000.0
E_STAR = 1.0 / ((1 - NU**2) / E_CYL + (1 - NU**2) / E_BLOCK)
A = math.sqrt(4 * P * R / (math.pi * E_STAR))
P0 = 2 * P / (math.pi * A)
CENTRE = (0.0, R)  # centre of the cylinder; the cut is y = R

# Boundary ids in the VTK files (before dealvem's offset of 10 on the cylinder).
BLOCK_BOTTOM, BLOCK_TOP = 2, 3
ARC, CUT = 0, 1
# GetFEM has no region number 0: a boundary id b is region b + REGION_OFFSET
REGION_OFFSET = 100


def hertz_pressure(x):
    """Hertz's pressure p0 sqrt(1 - x^2/a^2) (zero outside |x| < a)."""
    x = np.asarray(x, dtype=float)
    return P0 * np.sqrt(np.clip(1.0 - (x / A) ** 2, 0.0, None))


# ---------------------------------------------------------------------------
# Meshes


def read_vtk(path):
    """Read a legacy-VTK polygon mesh as written by dealvem's MeshIO::write_vtk.

    Returns (points [n x 2], polygons [list of vertex lists, counter-clockwise],
    boundary {(i, j) with i < j: boundary id}) -- the boundary ids sit on the
    line cells (VTK type 3) in the CELL_DATA field boundary_id.
    """
    with open(path) as f:
        tok = f.read().split()
    pos = tok.index("POINTS")
    n = int(tok[pos + 1])
    xyz = np.array(tok[pos + 3 : pos + 3 + 3 * n], dtype=float).reshape(n, 3)
    pos = tok.index("CELLS")
    n_cells = int(tok[pos + 1])
    i = pos + 3
    cells = []
    for _ in range(n_cells):
        k = int(tok[i])
        cells.append([int(v) for v in tok[i + 1 : i + 1 + k]])
        i += k + 1
    assert tok[i] == "CELL_TYPES"
    types = [int(t) for t in tok[i + 2 : i + 2 + n_cells]]
    i += 2 + n_cells
    fields = {}
    while i < len(tok):
        if tok[i] == "SCALARS":
            name = tok[i + 1]
            j = tok.index("LOOKUP_TABLE", i) + 2
            fields[name] = [int(float(v)) for v in tok[j : j + n_cells]]
            i = j + n_cells
        else:
            i += 1
    polygons = [c for c, t in zip(cells, types) if t != 3]
    ids = fields.get("boundary_id", [0] * n_cells)
    boundary = {}
    for c, t, b in zip(cells, types, ids):
        if t == 3:
            boundary[(min(c), max(c))] = b
    return xyz[:, :2].copy(), polygons, boundary


def _area2(p, a, b, c):
    """Twice the signed area of the triangle (a, b, c)."""
    return (p[b, 0] - p[a, 0]) * (p[c, 1] - p[a, 1]) - (p[c, 0] - p[a, 0]) * (p[b, 1] - p[a, 1])


def _ear_clip(p, poly):
    """Ear clipping of a simple counter-clockwise polygon; straight (180
    degree) vertices are never the tip of an ear, so no triangle is flat."""
    v = list(poly)
    tris = []
    while len(v) > 3:
        n = len(v)
        best = None
        for i in range(n):
            a, b, c = v[i - 1], v[i], v[(i + 1) % n]
            ar = _area2(p, a, b, c)
            if ar <= 1e-12 * _scale2(p, poly):
                continue
            inside = False
            for q in v:
                if q in (a, b, c):
                    continue
                if (_area2(p, a, b, q) >= 0 and _area2(p, b, c, q) >= 0 and _area2(p, c, a, q) >= 0):
                    inside = True
                    break
            if not inside and (best is None or ar > best[0]):
                best = (ar, i)
        if best is None:
            raise RuntimeError("ear clipping failed on polygon %s" % poly)
        i = best[1]
        tris.append((v[i - 1], v[i], v[(i + 1) % n]))
        del v[i]
    tris.append(tuple(v))
    return tris


def _scale2(p, poly):
    q = p[poly]
    d = q.max(axis=0) - q.min(axis=0)
    return float(d @ d)


def triangulate(points, polygons):
    """Cut every polygon into triangles on its own vertices.

    The polygons are quadrilaterals from deal.II with hanging vertices on
    some sides (straight angles). A fan from one vertex is used: the apex is
    the vertex whose fan has the largest smallest triangle, which is
    always positive for a convex polygon if the apex is chosen well (a
    hanging vertex, or a corner not on a side with a hanging vertex). A
    polygon on which no fan has only positive triangles (not convex) is
    cut by ear clipping instead. Returns (triangles [m x 3], counts).
    """
    tris = []
    n_fan = n_ear = 0
    for poly in polygons:
        n = len(poly)
        if n == 3:
            tris.append(tuple(poly))
            n_fan += 1
            continue
        best = None
        for s in range(n):
            fan = [(poly[s], poly[(s + j) % n], poly[(s + j + 1) % n]) for j in range(1, n - 1)]
            smallest = min(_area2(points, *t) for t in fan)
            if best is None or smallest > best[0]:
                best = (smallest, fan)
        if best[0] > 1e-8 * _scale2(points, poly):
            tris.extend(best[1])
            n_fan += 1
        else:
            tris.extend(_ear_clip(points, poly))
            n_ear += 1
    return np.array(tris, dtype=int), {"fan": n_fan, "ear_clipping": n_ear}


def refine_uniformly(points, tris, boundary, arc_id=None):
    """Split every triangle into four at its edge midpoints. Boundary edges
    pass their id on to their halves; midpoints of edges with id arc_id are
    moved onto the circle of radius R about CENTRE."""
    index = {}
    new_points = list(map(tuple, points))

    def midpoint(i, j):
        key = (min(i, j), max(i, j))
        if key not in index:
            m = 0.5 * (points[i] + points[j])
            if arc_id is not None and boundary.get(key) == arc_id:
                d = m - np.array(CENTRE)
                m = np.array(CENTRE) + R * d / np.linalg.norm(d)
            index[key] = len(new_points)
            new_points.append(tuple(m))
        return index[key]

    new_tris = []
    for a, b, c in tris:
        ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
        new_tris += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    new_boundary = {}
    for (i, j), b in boundary.items():
        m = index[(i, j)]
        new_boundary[(min(i, m), max(i, m))] = b
        new_boundary[(min(j, m), max(j, m))] = b
    return np.array(new_points), np.array(new_tris, dtype=int), new_boundary


def local_edge_length(points, boundary, bid, s=A + 1.0):
    """Longest boundary edge with id bid whose midpoint has |x| <= s (the h of
    step-3's table)."""
    h = 0.0
    for (i, j), b in boundary.items():
        if b == bid and abs(0.5 * (points[i, 0] + points[j, 0])) <= s:
            h = max(h, float(np.linalg.norm(points[i] - points[j])))
    return h


# ---------------------------------------------------------------------------
# The GetFEM model


def getfem_mesh(gf, points, tris, boundary, ids):
    """A GetFEM mesh of straight triangles and the boundary regions
    id + REGION_OFFSET of the boundary ids in ids. The convexes keep the order of tris and
    the vertex order inside each; face f of a triangle is the side opposite
    its vertex f."""
    m = gf.Mesh("empty", 2)
    # all triangles at once: coordinates x vertices x triangles
    cv = m.add_convex(gf.GeoTrans("GT_PK(2,1)"), np.transpose(points[tris], (2, 1, 0)))
    assert len(cv) == len(tris) and list(cv) == list(range(len(tris)))
    faces = {}
    for c, t in enumerate(tris):
        for f in range(3):
            i, j = t[(f + 1) % 3], t[(f + 2) % 3]
            faces[(min(i, j), max(i, j))] = (c, f)
    for bid in ids:
        cvf = np.array([faces[e] for e, b in boundary.items() if b == bid], dtype=int).T
        m.set_region(bid + REGION_OFFSET, cvf)
    return m


def solve(block_file, cylinder_file, order, refine=0, max_res=1e-9, lsolver="mumps", verbose=False,
          pieces=8, r_factor=0.1):
    """Solve one case; returns a dict of results with the nodal profile."""
    import getfem as gf

    gf.util_trace_level(0)  # no assembly traces on the terminal

    t_start = time.perf_counter()
    bodies = {}
    tri_report = {}
    for name, path, arc in (("block", block_file, None), ("cylinder", cylinder_file, ARC)):
        pts, polys, bnd = read_vtk(path)
        tris, counts = triangulate(pts, polys)
        tri_report[name] = dict(counts, polygons=len(polys), vertices=len(pts))
        for _ in range(refine):
            pts, tris, bnd = refine_uniformly(pts, tris, bnd, arc)
        bodies[name] = (pts, tris, bnd)
    h = max(local_edge_length(*bodies["block"][::2], BLOCK_TOP),
            local_edge_length(*bodies["cylinder"][::2], ARC))

    mb = getfem_mesh(gf, *bodies["block"], (BLOCK_BOTTOM, BLOCK_TOP))
    mc = getfem_mesh(gf, *bodies["cylinder"], (ARC, CUT))
    rg_bottom, rg_top = BLOCK_BOTTOM + REGION_OFFSET, BLOCK_TOP + REGION_OFFSET
    rg_arc, rg_cut = ARC + REGION_OFFSET, CUT + REGION_OFFSET

    fem = gf.Fem("FEM_PK(2,%d)" % order)
    mfu_b = gf.MeshFem(mb, 2)
    mfu_b.set_fem(fem)
    mfu_c = gf.MeshFem(mc, 2)
    mfu_c.set_fem(fem)
    mfp = gf.MeshFem(mc, 1)  # the contact pressure: P1 on the arc
    mfp.set_fem(gf.Fem("FEM_PK(2,1)"))
    im = gf.Integ("IM_TRIANGLE(%d)" % (2 * order))
    mim_b, mim_c = gf.MeshIm(mb, im), gf.MeshIm(mc, im)
    # The contact integral holds master basis functions that have kinks
    # inside the slave edges and the kink of pos_part at the edge of the
    # contact zone: each arc edge is integrated on `pieces` pieces, with the
    # Gauss rule of degree 6 on each.
    mim_contact = gf.MeshIm(mc, gf.Integ("IM_STRUCTURED_COMPOSITE(IM_TRIANGLE(6),%d)" % pieces))

    # the geometry read back from GetFEM, as a check of the regions
    arc_length = gf.asm_generic(mim_contact, 0, "1", rg_arc)
    arc_dx = gf.asm_generic(mim_contact, 0, "abs(Normal(2))", rg_arc)
    cut_length = gf.asm_generic(mim_c, 0, "1", rg_cut)
    top_length = gf.asm_generic(mim_b, 0, "1", rg_top)
    assert abs(cut_length - 2 * R) < 1e-9 and abs(top_length - 200) < 1e-9, (cut_length, top_length)
    assert abs(arc_dx - 2 * R) < 1e-9 and abs(arc_length / (math.pi * R) - 1) < 1e-3, (arc_dx, arc_length)

    md = gf.Model("real")
    md.add_fem_variable("u1", mfu_b)  # block (master)
    md.add_fem_variable("u2", mfu_c)  # cylinder (slave)

    def lame(E):
        return E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))

    for body, E, mim in (("1", E_BLOCK, mim_b), ("2", E_CYL, mim_c)):
        lam, mu = lame(E)
        md.add_initialized_data("lambda" + body, [lam])
        md.add_initialized_data("mu" + body, [mu])
        md.add_isotropic_linearized_elasticity_brick(mim, "u" + body, "lambda" + body, "mu" + body)
    md.add_Dirichlet_condition_with_simplification("u1", rg_bottom)

    # the rigid plate on the cut: rig = (w, theta) about (0, 50)
    md.add_variable("rig", 2)
    md.add_multiplier("tie", mfu_c, "u2", mim_c, rg_cut)
    rigid = "[-rig(2)*(X(2)-%r), rig(1)+rig(2)*X(1)]" % R
    test_rigid = "[-Test_rig(2)*(X(2)-%r), Test_rig(1)+Test_rig(2)*X(1)]" % R
    md.add_linear_term(mim_c, "tie.(Test_u2 - %s) + Test_tie.(u2 - %s)" % (test_rigid, rigid), rg_cut)
    # the resultant (0, -P) on the plate, spread over the cut's length 2R
    md.add_source_term(mim_c, "%r*Test_rig(1)" % (-P / (2 * R)), rg_cut)

    # contact: P1 pressure on the arc, integral Alart-Curnier
    md.add_filtered_fem_variable("p", mfp, rg_arc)
    md.add_interpolate_transformation_from_expression("below", mc, mb, "[X(1), 0]")
    r = r_factor * E_STAR / h
    md.add_initialized_data("r", [r])
    w = "abs(Normal(2))"
    gap = "(X(2) + u2(2) - Interpolate(u1, below)(2))"
    md.add_nonlinear_term(
        mim_contact,
        "-%s*p*(Test_u2(2) - Interpolate(Test_u1, below)(2))"
        " + (%s/r)*(p - pos_part(p - r*%s))*Test_p" % (w, w, gap),
        rg_arc,
    )
    # start from a uniform pressure p0: the first Newton step then closes the
    # arc near the origin, where the gap is smallest, and the cylinder is held
    md.set_variable("p", P0 * np.ones(md.variable("p").size))

    t_setup = time.perf_counter()
    args = ["max_res", max_res, "max_iter", 50, "lsolver", lsolver]
    if verbose:
        args.append("noisy")
    nbit, converged = md.solve(*args)
    t_solve = time.perf_counter()

    # the nodal values of the multiplier (the raw pressure) on the arc
    dofs = mfp.basic_dof_on_region(rg_arc)
    xy = mfp.basic_dof_nodes(dofs).T
    p_all = md.interpolation("p", mfp, rg_arc)
    g_all = md.interpolation(gap, mfp, rg_arc)
    order_x = np.argsort(xy[:, 0])
    profile = np.column_stack([xy[order_x], p_all[dofs][order_x], g_all[dofs][order_x]])
    force = gf.asm_generic(mim_contact, 0, "%s*p" % w, rg_arc, md)
    rig = md.variable("rig")
    t_end = time.perf_counter()

    return {
        "code": "GetFEM",
        "order": order,
        "refine": refine,
        "triangulation": tri_report,
        "triangles": int(len(bodies["block"][1]) + len(bodies["cylinder"][1])),
        "h": h,
        "dofs_displacement": int(mfu_b.nbdof() + mfu_c.nbdof()),
        "dofs_pressure": int(md.variable("p").size),
        "dofs_tie": int(md.variable("tie").size),
        "newton_iterations": int(nbit),
        "converged": bool(converged),
        "force": float(force),
        "plate_w": float(rig[0]),
        "plate_theta": float(rig[1]),
        "augmentation_r": r,
        "contact_quadrature_pieces": pieces,
        "seconds_setup": t_setup - t_start,
        "seconds_solve": t_solve - t_setup,
        "seconds_total": t_end - t_start,
        "profile": profile,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--block", required=True, help="hertz-block-L.vtk")
    ap.add_argument("--cylinder", required=True, help="hertz-cylinder-L.vtk")
    ap.add_argument("--order", type=int, choices=(1, 2), required=True, help="P1 or P2 displacements")
    ap.add_argument("--refine", type=int, default=0, help="uniform refinements of the triangulation")
    ap.add_argument("--max-res", type=float, default=1e-9, help="Newton residual target")
    ap.add_argument("--lsolver", default="mumps", help="GetFEM linear solver (superlu crashed on this model)")
    ap.add_argument("--json", required=True, help="output: run summary")
    ap.add_argument("--profile", required=True, help="output: CSV x,y,pressure,gap at the multiplier nodes")
    ap.add_argument("--pieces", type=int, default=8, help="pieces per arc edge of the contact quadrature")
    ap.add_argument("--r-factor", type=float, default=0.1, help="augmentation r = factor * E* / h")
    ap.add_argument("--verbose", action="store_true", help="GetFEM's Newton prints its residuals")
    o = ap.parse_args()

    res = solve(o.block, o.cylinder, o.order, o.refine, o.max_res, o.lsolver, o.verbose, o.pieces, o.r_factor)
    np.savetxt(o.profile, res.pop("profile"), delimiter=",", header="x,y,pressure,gap", comments="", fmt="%.15g")
    res.update(block=os.path.abspath(o.block), cylinder=os.path.abspath(o.cylinder))
    with open(o.json, "w") as f:
        json.dump(res, f, indent=1)
    print("GetFEM P%d%s: %d displacement DoFs + %d pressure DoFs, %d Newton iterations%s, "
          "F/P - 1 = %.1e, solve %.2f s, total %.2f s"
          % (o.order, " (refined %dx)" % o.refine if o.refine else "", res["dofs_displacement"],
             res["dofs_pressure"], res["newton_iterations"], "" if res["converged"] else " (NOT CONVERGED)",
             res["force"] / P - 1, res["seconds_solve"], res["seconds_total"]))
    return 0 if res["converged"] else 1


if __name__ == "__main__":
    sys.exit(main())
