#!/usr/bin/python3
"""The report of benchmarks/gear_peer/run.sh: dealvem and GetFEM on a gear pair.

Reads the work directory of run.sh and writes one Markdown report. The same
functions evaluate both codes:

* dealvem: output/dealvem-L.json (DoFs, timings, the contact force, the
  reaction moment of the turned bore about the pinion's centre, the reaction
  of the clamped bore about the gear's centre) and
  output/dealvem-L-interface.csv (per node pair: position, normal, active,
  the recovered pressure and the raw nodal pressure -lambda/weight);
* GetFEM: getfem-L.json and getfem-L.csv (gear_getfem.py: x, y, the P1
  pressure and the gap at its nodes on the contact window);
* *.time: /usr/bin/time -v of each process; machine.txt: the header.

Quantities: the peak contact pressure p_max (dealvem: the largest recovered
pressure and the largest raw nodal value; GetFEM: the largest nodal value of
its multiplier); the torques about the two centres the contact forces
transmit (dealvem: the reaction moments of the bores; GetFEM: the moments of
its contact forces, which the discrete equilibrium makes equal to them) and
the mesh stiffness T1/theta; the contact width: the closed nodes projected on
the flank's tangent (perpendicular to the code's total contact force), the
zone's ends midway between the outermost closed node and the next open one
(as in hertz_peer); Hertz's p0 and width for two cylinders with the flanks'
radii of curvature at the pitch point r_i sin(alpha) under each code's normal
force.
"""

import argparse
import json
import math
import os
import re
import sys

import numpy as np

sys.dont_write_bytecode = True

# the gear pair of run.sh (examples/parameters/gear-pair.prm)
R1, R2, ALPHA = 40.0, 62.0, math.radians(20.0)
E, NU = 210000.0, 0.3
PITCH = np.array([40.0, 0.0])


def hertz(force):
    """Hertz's half-width and peak pressure for the normal force per length."""
    rho1, rho2 = R1 * math.sin(ALPHA), R2 * math.sin(ALPHA)
    radius = rho1 * rho2 / (rho1 + rho2)
    e_star = E / (2 * (1 - NU**2))
    a = math.sqrt(4 * force * radius / (math.pi * e_star))
    return a, 2 * force / (math.pi * a)


def width(xy, closed, force):
    """The contact width along the flank tangent (perpendicular to force)."""
    f = np.asarray(force) / np.linalg.norm(force)
    t = np.array([f[1], -f[0]])
    s = (np.asarray(xy) - PITCH) @ t
    closed = np.asarray(closed, bool)
    if not closed.any():
        return float("nan"), float("nan")
    lo, hi = s[closed].min(), s[closed].max()
    right, left = s[~closed & (s > hi)], s[~closed & (s < lo)]
    if not len(right) or not len(left):
        return float("nan"), hi - lo
    return 0.5 * (hi + right.min()) - 0.5 * (lo + left.max()), hi - lo


def read_time(path):
    """Wall seconds, peak resident MB and CPU seconds (user + system) of a
    process from /usr/bin/time -v."""
    wall = peak = cpu = float("nan")
    if os.path.exists(path):
        text = open(path).read()
        u = re.search(r"User time \(seconds\): ([\d.]+)", text)
        s = re.search(r"System time \(seconds\): ([\d.]+)", text)
        if u and s:
            cpu = float(u.group(1)) + float(s.group(1))
        m = re.search(r"Elapsed \(wall clock\) time.*?: (?:(\d+):)?(\d+):([\d.]+)", text)
        if m:
            wall = int(m.group(1) or 0) * 3600 + int(m.group(2)) * 60 + float(m.group(3))
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        if m:
            peak = int(m.group(1)) / 1024.0
    return wall, peak, cpu


def read_csv(path):
    with open(path) as f:
        names = f.readline().strip().split(",")
        rows = [line.strip().split(",") for line in f if line.strip()]
    cols = {}
    for i, n in enumerate(names):
        vals = [r[i] for r in rows]
        try:
            cols[n] = np.array(vals, dtype=float)
        except ValueError:
            cols[n] = np.array(vals)
    return cols


def dealvem_row(work, name, angle):
    base = os.path.join(work, "output", name)
    if not os.path.exists(base + ".json"):
        return None
    js = json.load(open(base + ".json"))
    csv = read_csv(base + "-interface.csv")
    force = np.array([js["contact"]["total_force_x"], js["contact"]["total_force_y"]])
    xy = np.column_stack([csv["x"], csv["y"]])
    closed = csv["active"] > 0.5
    w, extent = width(xy, closed, force)
    t = js["timings"]
    wall, peak, cpu = read_time(os.path.join(work, name + ".time"))
    rot = js["rotations"]["rotation_0"]
    # the moment the bore takes about the centre: the reaction of a
    # prescribed angle, the applied torque otherwise
    t1 = abs(rot["moment_about_centre"])
    t2 = abs(js["reactions"]["boundary_10"]["moment"])
    fn = float(np.linalg.norm(force))
    far = float(np.max(np.linalg.norm(xy[closed] - PITCH, axis=1))) if closed.any() else float("nan")
    return {
        "code": "dealvem k = 2", "dofs": js["dofs"], "mult": js["multipliers"], "cells": js["cells"],
        "iterations": js["contact"]["active_set_iterations"],
        "p_max": float(csv["pressure"][closed].max()), "p_max_raw": float(csv["lumped_pressure"][closed].max()),
        "t1": t1, "t2": t2, "fn": fn, "width": w, "extent": extent, "closed": int(closed.sum()),
        "farthest_closed": far,
        "solve": t.get("node insertion", 0) + t.get("assembly", 0) + t.get("solve", 0),
        "total": wall, "cpu": cpu, "peak": peak, "angle": rot["angle"], "solver": js.get("solver", ""),
    }


def getfem_row(work, name):
    path = os.path.join(work, name)
    if not os.path.exists(path + ".json"):
        return None
    js = json.load(open(path + ".json"))
    prof = np.loadtxt(path + ".csv", delimiter=",", skiprows=1, ndmin=2)
    xy, p, gap = prof[:, :2], prof[:, 2], prof[:, 3]
    # closed: the Alart-Curnier indicator p - r g is positive
    closed = p - js["augmentation_r"] * gap > 0
    force = np.array([js["force_x"], js["force_y"]])
    w, extent = width(xy, closed, force)
    wall, peak, cpu = read_time(path + ".time")
    return {
        "code": "GetFEM P%d" % js["order"], "dofs": js["dofs_displacement"], "mult": js["dofs_pressure"],
        "cells": js["triangles"], "iterations": js["newton_iterations"], "converged": js["converged"],
        "p_max": float(p.max()), "p_max_raw": float(p.max()),
        "t1": abs(js["moment_pinion"]), "t2": abs(js["moment_gear"]), "fn": float(np.linalg.norm(force)),
        "width": w, "extent": extent, "closed": int(closed.sum()),
        "solve": js["seconds_solve"], "setup": js["seconds_setup"], "total": wall, "cpu": cpu, "peak": peak,
        "angle": js["angle"], "json": js,
    }


def fmt(v, spec=".2f"):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "-"
    return format(v, spec)


def rel(a, b):
    return 100.0 * (a / b - 1.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", required=True)
    ap.add_argument("--levels", default="0 1 2 3")
    ap.add_argument("--angle", type=float, required=True)
    ap.add_argument("--torque", type=float, default=9400.0)
    ap.add_argument("--out", required=True)
    o = ap.parse_args()
    work, angle = o.work, o.angle
    levels = [int(v) for v in o.levels.split()]

    runs = []
    for level in levels:
        d = dealvem_row(work, "dealvem-%d" % level, angle)
        g = getfem_row(work, "getfem-%d" % level)
        direct = dealvem_row(work, "dealvem-direct-%d" % level, angle)
        runs.append((level, d, g, direct))
    torque_runs = []
    for level in levels:
        d = dealvem_row(work, "dealvem-torque-%d" % level, angle)
        g = getfem_row(work, "getfem-torque-%d" % level)
        if d and g:
            torque_runs.append((level, d, g))

    L = []
    L.append("# Spur gear pair at the pitch point: dealvem and GetFEM on the same meshes\n")
    L.append("The gear pair of examples/parameters/gear-pair.prm (z1 = 20, z2 = 31, m = 4 mm, alpha = 20 deg, "
             "backlash allowance 0.1 mm, tip relief 0.01 mm, sectors of three teeth, E = 210000 MPa, nu = 0.3, "
             "plane strain per mm of face width, frictionless, small strain) with the counter-clockwise flanks "
             "of both teeth 0 touching unloaded at the pitch point (40, 0). The pinion's bore is turned by "
             "theta = %g rad about (0, 0), the gear's bore is clamped. benchmarks/gear_peer/run.sh.\n" % angle)
    machine = os.path.join(work, "machine.txt")
    if os.path.exists(machine):
        L.append("```\n" + open(machine).read().strip() + "\n```\n")

    L.append("## dealvem k = 2 against GetFEM P2\n")
    for level, d, g, _ in runs:
        if d and g:
            L.append("**Level %d: solve time dealvem : GetFEM = %.2f (%.2f s : %.2f s; %d and %d displacement "
                     "DoFs, %.2f : 1 per DoF; process CPU time %.2f : 1); p_max differs by %+.2f %% (dealvem's "
                     "recovered pressure against GetFEM's multiplier; raw nodal values %+.2f %%), the torque by "
                     "%+.2f %% (pinion) and %+.2f %% (gear), the contact width by %+.1f %%.**\n"
                     % (level, d["solve"] / g["solve"], d["solve"], g["solve"], d["dofs"], g["dofs"],
                        (d["solve"] / d["dofs"]) / (g["solve"] / g["dofs"]), d["cpu"] / g["cpu"],
                        rel(d["p_max"], g["p_max"]),
                        rel(d["p_max_raw"], g["p_max_raw"]), rel(d["t1"], g["t1"]), rel(d["t2"], g["t2"]),
                        rel(d["width"], g["width"])))
    L.append("iterations: dealvem's active-set iterations (each a Cholesky factorization of the condensed "
             "stiffness), GetFEM's Newton iterations (each an LU factorization by MUMPS of the whole system). "
             "Widths: GetFEM's closed nodes are the vertices of the slave flank, dealvem's the node pairs "
             "(vertices, edge midpoints and inserted nodes of both flanks), so the two widths are measured on "
             "different grids.\n")
    L.append("With the angle prescribed the transmission error is the angle itself in both codes; the "
             "figure that compares is the torque that angle takes, i.e. the mesh stiffness k = T1/theta "
             "(the transmission error under a given torque T is T/k).\n")
    L.append("| level | code | DoFs | contact unknowns | p_max (MPa) | p_max raw (MPa) | Hertz p0 (MPa) | "
             "T1 pinion (N mm/mm) | T2 gear (N mm/mm) | k = T1/theta (N mm/mm/rad) | F_n (N/mm) | "
             "width (mm) | Hertz 2a (mm) | closed nodes | iterations | solve (s) | ratio dealvem : GetFEM | "
             "total (s) | process CPU (s) | peak MB |")
    L.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for level, d, g, _ in runs:
        for r in (d, g):
            if not r:
                continue
            a_h, p0 = hertz(r["fn"])
            ratio = fmt(d["solve"] / g["solve"]) if (d and g and r is d) else ""
            name = r["code"] + ("" if r.get("converged", True) else " (not converged)")
            L.append("| %d | %s | %d | %d | %.1f | %.1f | %.1f | %.1f | %.1f | %.4g | %.2f | %.4f | %.4f | %d | %d | "
                     "%s | %s | %s | %s | %s |"
                     % (level, name, r["dofs"], r["mult"], r["p_max"], r["p_max_raw"], p0, r["t1"], r["t2"],
                        r["t1"] / angle, r["fn"], r["width"], 2 * a_h, r["closed"], r["iterations"],
                        fmt(r["solve"]), ratio,
                        fmt(r["total"], ".1f"), fmt(r["cpu"], ".1f"), fmt(r["peak"], ".0f")))
    L.append("")
    L.append("Differences dealvem / GetFEM - 1 and against Hertz:\n")
    L.append("| level | p_max | p_max raw | T1 | T2 | k | width | dealvem p_max / Hertz p0 - 1 | "
             "GetFEM p_max / Hertz p0 - 1 | dealvem width / 2a - 1 | GetFEM width / 2a - 1 |")
    L.append("|---|---|---|---|---|---|---|---|---|---|---|")
    for level, d, g, _ in runs:
        if d and g:
            (ad, pd), (ag, pg) = hertz(d["fn"]), hertz(g["fn"])
            L.append("| %d | %+.2f %% | %+.2f %% | %+.3f %% | %+.3f %% | %+.3f %% | %+.1f %% | %+.2f %% | %+.2f %% | "
                     "%+.1f %% | %+.1f %% |"
                     % (level, rel(d["p_max"], g["p_max"]), rel(d["p_max_raw"], g["p_max_raw"]),
                        rel(d["t1"], g["t1"]), rel(d["t2"], g["t2"]), rel(d["t1"], g["t1"]),
                        rel(d["width"], g["width"]), rel(d["p_max"], pd), rel(g["p_max"], pg),
                        rel(d["width"], 2 * ad), rel(g["width"], 2 * ag)))
    L.append("")

    if torque_runs:
        L.append("## Under the torque T1 = %g N mm/mm: the transmission error\n" % o.torque)
        L.append("The pinion's bore loaded by the torque, its angle an unknown (it turns rigidly about its "
                 "centre); the angle is the transmission error (no other compliance in the model). "
                 "Delta = dealvem / GetFEM - 1.\n")
        L.append("| level | DoFs dealvem / GetFEM | angle dealvem / GetFEM (rad) | Delta angle | p_max dealvem "
                 "(raw) / GetFEM (MPa) | Delta p_max | T2 dealvem / GetFEM | width dealvem / GetFEM (mm) | "
                 "iterations | solve dealvem / GetFEM (s) | ratio | process CPU (s) | CPU ratio |")
        L.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for level, d, g in torque_runs:
            L.append("| %d | %d / %d | %.6g / %.6g | %+.3f %% | %.1f (%.1f) / %.1f | %+.2f %% | %.1f / %.1f | "
                     "%.4f / %.4f | %d / %d | %.2f / %.2f | %.2f | %.1f / %.1f | %.2f |"
                     % (level, d["dofs"], g["dofs"], d["angle"], g["angle"], rel(d["angle"], g["angle"]),
                        d["p_max"], d["p_max_raw"], g["p_max"], rel(d["p_max"], g["p_max"]), d["t2"], g["t2"],
                        d["width"], g["width"], d["iterations"], g["iterations"], d["solve"], g["solve"],
                        d["solve"] / g["solve"], d["cpu"], g["cpu"], d["cpu"] / g["cpu"]))
        L.append("")

    L.append("## Notes\n")
    for level, d, g, direct in runs:
        if d:
            L.append("* Level %d, dealvem: %d polygons, %d node pairs, %d active-set iterations, %d closed pairs, "
                     "the farthest %.3f mm from the pitch point; solver: %s. Solve = node insertion + assembly + "
                     "active-set solve (the program's timings), total = the process's wall time."
                     % (level, d["cells"], d["mult"], d["iterations"], d["closed"], d["farthest_closed"],
                        d["solver"]))
        if g:
            js = g["json"]
            tri = js["triangulation"]
            L.append("* Level %d, GetFEM: the %d polygons cut into %d triangles on their own %d vertices "
                     "(fans; ear clipping for %d non-convex polygons), P2 displacements, P1 pressure on %d slave "
                     "edges (the teeth's edges within 1 mm of the pitch point; master: %d edges within 1.5 mm), "
                     "r = %.3g, %d Newton iterations; solve = md.solve (assembly, contact search, MUMPS), setup "
                     "(Python: mesh reading, triangulation, model) %.2f s."
                     % (level, js["polygons"], js["triangles"], js["vertices"],
                        sum(v.get("ear_clipping", 0) for v in tri.values()), js["slave_edges"],
                        js["master_edges"], js["augmentation_r"], js["newton_iterations"], js["seconds_setup"]))
        if d and direct:
            L.append("* Level %d, check: dealvem on the gears meshed in the run (Type = spur gear) instead of the "
                     "VTK files: %d DoFs (%d from the files), p_max %.4f (%.4f), T1 %.4f (%.4f)."
                     % (level, direct["dofs"], d["dofs"], direct["p_max"], d["p_max"], direct["t1"], d["t1"]))
    L.append("* One thread per process, the runs one after the other in one script; the machine may be shared "
             "(the load averages above): then the wall times stretch, and the process CPU time (user + system "
             "of /usr/bin/time, start-up and mesh reading included; for GetFEM the Python import too) is the "
             "steadier figure.")
    L.append("")
    text = "\n".join(L)
    with open(o.out, "w") as f:
        f.write(text + "\n")
    print(text)


if __name__ == "__main__":
    main()
