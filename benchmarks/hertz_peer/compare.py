#!/usr/bin/python3
"""The report of benchmarks/hertz_peer/run.sh: dealvem and GetFEM on Hertz.

Reads the files that run.sh leaves in its work directory and writes one
Markdown report. Every error is computed here, by one function for both
codes, from the nodal pressures each code wrote:

* dealvem: output/dealvem-L-kK-interface.csv (a row per contact pair: x,
  active, the raw nodal pressure lumped_pressure = -lambda/weight, the
  recovered pressure) and output/dealvem-L-kK.json (DoFs, active-set
  iterations, the total contact force, timings);
* GetFEM: getfem-L-pK.csv (x, y, the multiplier and the gap at its nodes
  on the arc) and getfem-L-pK.json (see hertz_getfem.py);
* the fine reference: getfem-ref.csv/json, GetFEM P2 on the finest level
  refined uniformly (the arc kept on the circle);
* *.time: the output of /usr/bin/time -v of each process (wall time, peak
  memory); machine.txt: the header; mesh/step3.log: the table
  that step-3 --study printed, appended for reference.

Errors, as in examples/step-3/step-3.cc (evaluate()): the peak pressure's
error max(p)/p0 - 1; the half-width a_h (midway between the outermost
closed and the first open node on either side) as (a_h - a)/h with h the
local contact edge length (and against the reference's a_h); the max and rms of the nodal errors at the nodes
with |x| < 0.8a, in % of p0, against Hertz's p0 sqrt(1 - x^2/a^2) and against
the fine reference (its P1 pressure interpolated in x).
"""

import argparse
import json
import math
import os
import re
import sys

import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hertz_getfem import A, P, P0, hertz_pressure  # noqa: E402  (numpy only, no GetFEM)


def errors(x, p, closed, h, reference=None):
    """The step-3 measures of one nodal pressure profile; reference: None or
    {"profile": [[x, p], ...] sorted by x, "a": its half-width}."""
    x, p, closed = np.asarray(x, float), np.asarray(p, float), np.asarray(closed, bool)
    out = {"p0_err": 100.0 * (p.max() / P0 - 1.0)}
    x_min = min(0.0, x[closed].min()) if closed.any() else 0.0
    x_max = max(0.0, x[closed].max()) if closed.any() else 0.0
    right = x[~closed & (x > x_max)]
    left = x[~closed & (x < x_min)]
    if len(right) and len(left):
        a_h = 0.25 * (x_max + right.min() - x_min - left.max())
        out["a_h"] = a_h
        out["a_err"] = (a_h - A) / h
        if reference is not None and reference.get("a") is not None:
            out["a_err_ref"] = (a_h - reference["a"]) / h
    inside = np.abs(x) < 0.8 * A
    e = np.abs(p[inside] - hertz_pressure(x[inside]))
    out.update(max_hertz=100 * e.max() / P0, rms_hertz=100 * math.sqrt(np.mean(e**2)) / P0)
    if reference is not None:
        ref = reference["profile"]
        e = np.abs(p[inside] - np.interp(x[inside], ref[:, 0], ref[:, 1]))
        out.update(max_ref=100 * e.max() / P0, rms_ref=100 * math.sqrt(np.mean(e**2)) / P0)
    out["n_inside"] = int(inside.sum())
    return out


def read_time(path):
    """Wall seconds and peak resident MB from /usr/bin/time -v."""
    wall = peak = float("nan")
    if os.path.exists(path):
        text = open(path).read()
        m = re.search(r"Elapsed \(wall clock\) time.*?: (?:(\d+):)?(\d+):([\d.]+)", text)
        if m:
            wall = int(m.group(1) or 0) * 3600 + int(m.group(2)) * 60 + float(m.group(3))
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        if m:
            peak = int(m.group(1)) / 1024.0
    return wall, peak


def read_csv(path):
    """A CSV with a header line as {column: numpy array} (numbers or strings)."""
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


def step3_h(work, level):
    """h of the level (the longest contact edge near the contact zone), from the
    GetFEM run of the level, which measures it on the same meshes."""
    for order in (1, 2):
        path = os.path.join(work, "getfem-%d-p%d.json" % (level, order))
        if os.path.exists(path):
            return json.load(open(path))["h"]
    from hertz_getfem import ARC, BLOCK_TOP, local_edge_length, read_vtk

    b = read_vtk(os.path.join(work, "mesh", "hertz-block-%d.vtk" % level))
    c = read_vtk(os.path.join(work, "mesh", "hertz-cylinder-%d.vtk" % level))
    return max(local_edge_length(b[0], b[2], BLOCK_TOP), local_edge_length(c[0], c[2], ARC))


def dealvem_row(work, level, k, reference):
    base = os.path.join(work, "output", "dealvem-%d-k%d" % (level, k))
    if not os.path.exists(base + ".json"):
        return None
    js = json.load(open(base + ".json"))
    csv = read_csv(base + "-interface.csv")
    h = step3_h(work, level)
    x, closed = csv["x"], csv["active"] > 0.5
    row = {"code": "dealvem", "level": level, "order": k, "h": h}
    row.update(errors(x, csv["lumped_pressure"], closed, h, reference))
    rec = errors(x, csv["pressure"], closed, h, reference)
    row["recovered"] = rec
    wall, peak = read_time(os.path.join(work, "dealvem-%d-k%d.time" % (level, k)))
    t = js["timings"]
    force = math.hypot(js["contact"]["total_force_x"], js["contact"]["total_force_y"])
    row.update(dofs=js["dofs"], mult=js["multipliers"], iterations=js["contact"]["active_set_iterations"],
               force_err=force / P - 1, solve=t.get("assembly", 0) + t.get("solve", 0), total=wall,
               peak=peak, cells=js["cells"], pairs_x=x)
    return row


def getfem_row(work, name, reference, label_level, order, pairs_x=None):
    path = os.path.join(work, name)
    if not os.path.exists(path + ".json"):
        return None
    js = json.load(open(path + ".json"))
    prof = np.loadtxt(path + ".csv", delimiter=",", skiprows=1, ndmin=2)
    x, p, gap = prof[:, 0], prof[:, 2], prof[:, 3]
    row = {"code": "GetFEM", "level": label_level, "order": order, "h": js["h"]}
    # closed: the Alart-Curnier indicator p - r g of the node is positive
    # (the multiplier alone oscillates about zero outside the contact zone)
    row.update(errors(x, p, p - js["augmentation_r"] * gap > 0, js["h"], reference))
    if pairs_x is not None:
        # the P1 multiplier is linear in x along each straight arc edge, so
        # interpolating the nodal values in x gives the field at these points
        pp = np.interp(pairs_x, x, p)
        inside = np.abs(pairs_x) < 0.8 * A
        e = np.abs(pp[inside] - hertz_pressure(pairs_x[inside]))
        row["at_pairs"] = {"max_hertz": 100 * e.max() / P0, "rms_hertz": 100 * math.sqrt(np.mean(e**2)) / P0}
        if reference is not None:
            ref = reference["profile"]
            e = np.abs(pp[inside] - np.interp(pairs_x[inside], ref[:, 0], ref[:, 1]))
            row["at_pairs"].update(max_ref=100 * e.max() / P0, rms_ref=100 * math.sqrt(np.mean(e**2)) / P0)
    wall, peak = read_time(path + ".time")
    row.update(dofs=js["dofs_displacement"], mult=js["dofs_pressure"], iterations=js["newton_iterations"],
               converged=js["converged"], force_err=js["force"] / P - 1, solve=js["seconds_solve"],
               total=wall, peak=peak, triangles=js["triangles"], json=js)
    return row


def fmt(v, spec=".2f"):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "-"
    return format(v, spec)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", required=True, help="the work directory of run.sh")
    ap.add_argument("--levels", default="0 1 2")
    ap.add_argument("--out", required=True, help="the Markdown report")
    o = ap.parse_args()
    work = o.work
    levels = [int(v) for v in o.levels.split()]

    ref_row = None
    reference = None
    if os.path.exists(os.path.join(work, "getfem-ref.csv")):
        prof = np.loadtxt(os.path.join(work, "getfem-ref.csv"), delimiter=",", skiprows=1, ndmin=2)
        rjs = json.load(open(os.path.join(work, "getfem-ref.json")))
        ref_level = int(re.search(r"hertz-block-(\d+)", rjs["block"]).group(1))
        ref_row = getfem_row(work, "getfem-ref", None, "%d+%dr" % (ref_level, rjs["refine"]), 2)
        reference = {"profile": prof[:, [0, 2]], "a": ref_row.get("a_h")}

    rows = []
    for level in levels:
        for k in (1, 2):
            d = dealvem_row(work, level, k, reference)
            g = getfem_row(work, "getfem-%d-p%d" % (level, k), reference, level, k,
                           d["pairs_x"] if d else None)
            rows += [r for r in (d, g) if r]
    if ref_row:
        rows.append(ref_row)

    L = []
    machine = open(os.path.join(work, "machine.txt")).read().strip() if os.path.exists(
        os.path.join(work, "machine.txt")) else ""
    L.append("# Hertz contact: dealvem and GetFEM on the same meshes\n")
    L.append("NAFEMS Hertz problem of examples/step-3 (half cylinder R = 50, E = 70000 on a block "
             "E = 210000, nu = 0.3, plane strain, P = 35000 N/mm through a rigid flat cut, frictionless). "
             "Hertz: a = %.4f mm, p0 = %.1f MPa. Both codes read the meshes that `step-3 --study` writes "
             "(levels %s) and run one after the other in the same script (benchmarks/hertz_peer/run.sh).\n"
             % (A, P0, ", ".join(map(str, levels))))
    if machine:
        L.append("```\n" + machine + "\n```\n")

    # the lead: dealvem k = 2 against GetFEM P2, level by level
    L.append("## dealvem k = 2 against GetFEM P2\n")
    pairs = []
    for level in levels:
        d = next((r for r in rows if r["code"] == "dealvem" and r["level"] == level and r["order"] == 2), None)
        g = next((r for r in rows if r["code"] == "GetFEM" and r["level"] == level and r["order"] == 2), None)
        if d and g:
            pairs.append((level, d, g))
    if pairs:
        level, d, g = pairs[-1]
        which = "rms_ref" if "rms_ref" in d and "rms_ref" in g else "rms_hertz"
        L.append("**Level %d, %d (dealvem k = 2) and %d (GetFEM P2) displacement DoFs: rms raw nodal pressure "
                 "error %s %.2f %% of p0 for dealvem, %.2f %% for GetFEM (against Hertz's formula: %.2f %% and "
                 "%.2f %%); dealvem's solve takes %.2f s, GetFEM's %.2f s (ratio %.2f).**\n"
                 % (level, d["dofs"], g["dofs"], "against the fine reference" if which == "rms_ref" else
                    "against Hertz", d[which], g[which], d["rms_hertz"], g["rms_hertz"], d["solve"], g["solve"],
                    d["solve"] / g["solve"]))
    L.append("Raw nodal pressures (dealvem: -lambda/weight at every pair, vertices and edge midpoints; "
             "GetFEM: the P1 multiplier at its nodes), nodes with |x| < 0.8a, in % of p0; solve = "
             "the nonlinear contact solve with its assemblies (dealvem: assembly + active-set solve "
             "from its JSON timings; GetFEM: md.solve).\n")
    L.append("| level | DoFs dealvem / GetFEM | rms err vs Hertz dealvem / GetFEM | rms err vs fine ref. "
             "dealvem / GetFEM | max err vs Hertz dealvem / GetFEM | solve s dealvem / GetFEM | solve time "
             "ratio dealvem : GetFEM |")
    L.append("|---|---|---|---|---|---|---|")
    for level, d, g in pairs:
        L.append("| %d | %d / %d | %s / %s | %s / %s | %s / %s | %s / %s | %s |" % (
            level, d["dofs"], g["dofs"], fmt(d["rms_hertz"]), fmt(g["rms_hertz"]), fmt(d.get("rms_ref")),
            fmt(g.get("rms_ref")), fmt(d["max_hertz"]), fmt(g["max_hertz"]), fmt(d["solve"]), fmt(g["solve"]),
            fmt(d["solve"] / g["solve"]) if g["solve"] > 0 else "-"))
    L.append("")

    L.append("## All runs\n")
    L.append("DoFs: displacement DoFs (dealvem's count includes the nodes inserted on the interface); "
             "mult.: contact multipliers (dealvem: pairs; GetFEM: P1 pressure nodes on the arc). "
             "it.: dealvem's active-set iterations, GetFEM's Newton iterations. Errors in % of p0 at the "
             "nodes with |x| < 0.8a, from the raw nodal values; p0 err from the largest raw nodal value. "
             "a_ref: the half-width of the fine reference by the same rule (known to half its h). "
             "total s: wall time of the process (/usr/bin/time), peak MB: its peak resident memory.\n")
    L.append("| level | code | order | h | DoFs | mult. | it. | p0 err % | (a_h-a)/h | (a_h-a_ref)/h | "
             "max err vs Hertz | rms err vs Hertz | max err vs fine ref. | rms err vs fine ref. | F/P - 1 | "
             "solve s | total s | peak MB |")
    L.append("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        name = r["code"] + ("" if r.get("converged", True) else " (not converged)")
        L.append("| %s | %s | %s | %.3f | %d | %d | %d | %s | %s | %s | %s | %s | %s | %s | %.1e | %s | %s | %s |"
                 % (r["level"], name, ("k = %d" if r["code"] == "dealvem" else "P%d") % r["order"], r["h"],
            r["dofs"], r["mult"], r["iterations"], fmt(r["p0_err"]), fmt(r.get("a_err")), fmt(r.get("a_err_ref")),
            fmt(r["max_hertz"]), fmt(r["rms_hertz"]), fmt(r.get("max_ref")), fmt(r.get("rms_ref")),
            r["force_err"], fmt(r["solve"]), fmt(r["total"], ".1f"), fmt(r["peak"], ".0f")))
    L.append("")

    L.append("## Smoothed and interpolated pressures\n")
    L.append("dealvem's recovered pressure (ContactPressure::recover: a least-squares fit of degree k to the nodal forces over a patch of sub-edges) at its pairs, and "
             "GetFEM's P1 pressure field evaluated at dealvem's pair locations of the same level and "
             "order (|x| < 0.8a, % of p0).\n")
    L.append("| level | order | dealvem recovered: p0 err % | max / rms vs Hertz | max / rms vs fine ref. | "
             "GetFEM at dealvem's pairs: max / rms vs Hertz | max / rms vs fine ref. |")
    L.append("|---|---|---|---|---|---|---|")
    for level in levels:
        for k in (1, 2):
            d = next((r for r in rows if r["code"] == "dealvem" and r["level"] == level and r["order"] == k), None)
            g = next((r for r in rows if r["code"] == "GetFEM" and r["level"] == level and r["order"] == k), None)
            if not d:
                continue
            rec, ap_ = d["recovered"], (g or {}).get("at_pairs", {})
            L.append("| %d | %d | %s | %s / %s | %s / %s | %s / %s | %s / %s |" % (
                level, k, fmt(rec["p0_err"]), fmt(rec["max_hertz"]), fmt(rec["rms_hertz"]),
                fmt(rec.get("max_ref")), fmt(rec.get("rms_ref")), fmt(ap_.get("max_hertz")), fmt(ap_.get("rms_hertz")),
                fmt(ap_.get("max_ref")), fmt(ap_.get("rms_ref"))))
    L.append("")

    L.append("## How the two codes solve it\n")
    g_any = next((r for r in rows if r["code"] == "GetFEM"), None)
    tri = g_any["json"]["triangulation"] if g_any else {}
    L.append("* dealvem: `build/bin/dealvem` on the parameter file of step-3's parameters() (virtual "
             "elements of order k on the polygons; node insertion makes the surfaces match; node-to-node "
             "unilateral constraints, primal-dual active set with the accelerated update, Solver/Type = automatic: the Cholesky factorization (CHOLMOD) of the stiffness condensed by the active constraints). Raw "
             "nodal pressure: lumped_pressure = -lambda/weight of the interface CSV.")
    L.append("* GetFEM (hertz_getfem.py): each polygon is cut into triangles by a fan from one of its own "
             "vertices (no vertex added; the apex is chosen so that no triangle is flat at the hanging "
             "vertices; ear clipping for a polygon no fan can cut, used on %s polygons), FEM_PK(2,1) or "
             "FEM_PK(2,2) displacements, plane-strain linear elasticity, block bottom fixed nodally. The "
             "cut is a rigid plate: its trace is tied (multiplier in the trace space) to a rigid motion "
             "(w, theta) about (0, 50) with the horizontal translation fixed (dealvem's point constraint); "
             "the load is the work -P w. Contact: a P1 multiplier on the whole arc for both P1 and P2 "
             "displacements, the integral (mortar-type) non-symmetric Alart-Curnier formulation in GetFEM's "
             "weak form language, the master values at the point straight below the slave point "
             "(interpolate transformation; the master is the flat y = 0), r = 0.1 E*/h, each arc edge "
             "integrated on 8 pieces; GetFEM's Newton with MUMPS, max_res 1e-9. A GetFEM node counts as "
             "closed where its Alart-Curnier indicator p - r g is positive (r = 0.1 E*/h), a dealvem pair "
             "where its constraint is active."
             % (sum(v.get("ear_clipping", 0) for v in tri.values()) if tri else "-"))
    if ref_row:
        L.append("* Fine reference: GetFEM P2 on the level-%s triangulation refined uniformly %d time(s) "
                 "(new arc vertices moved onto the circle), %d displacement DoFs, h = %.4f. Its own errors "
                 "against Hertz (row `%s` above: peak %+.2f %%, rms %.2f %% of p0) are the model error "
                 "that every run shares: the cylinder of R = 50 on a 200 x 100 block is not Hertz's pair "
                 "of half-spaces, and its pressure lies about 0.5 %% of p0 above Hertz's in the middle. "
                 "The columns 'vs fine ref.' remove it."
                 % (ref_row["level"].split("+")[0], ref_row["json"]["refine"], ref_row["dofs"], ref_row["h"],
                    ref_row["level"], ref_row["p0_err"], ref_row["rms_hertz"]))
        check = os.path.join(work, "getfem-ref-check")
        if os.path.exists(check + ".csv"):
            cjs = json.load(open(check + ".json"))
            fine = np.loadtxt(check + ".csv", delimiter=",", skiprows=1, ndmin=2)
            ref = reference["profile"]
            inside = np.abs(ref[:, 0]) < 0.8 * A
            e = np.abs(np.interp(ref[inside, 0], fine[:, 0], fine[:, 2]) - ref[inside, 1])
            wall, peak = read_time(check + ".time")
            L.append("* Check of the reference: refined once more (%d displacement DoFs, %d Newton iterations, "
                     "solve %.0f s, peak %.0f MB), the reference's nodal pressures at |x| < 0.8a move by at "
                     "most %.3f %% of p0 (rms %.3f %%)."
                     % (cjs["dofs_displacement"], cjs["newton_iterations"], cjs["seconds_solve"], peak,
                        100 * e.max() / P0, 100 * math.sqrt(np.mean(e**2)) / P0))
    L.append("* Timings are single-threaded runs one after the other (DEAL_II_NUM_THREADS = "
             "OMP_NUM_THREADS = 1); solve s of both codes includes the assembly work of the nonlinear "
             "loop, total s includes start-up, mesh reading (and, for GetFEM, the Python triangulation).")
    L.append("")

    step3 = os.path.join(work, "mesh", "step3.log")
    if os.path.exists(step3):
        lines = [l.rstrip() for l in open(step3) if re.match(r"\s*(level \||\d+ \|)", l)]
        if lines:
            L.append("## step-3 --study's own table (same meshes, one process, recovered and raw pressures)\n")
            L.append("```\n" + "\n".join(lines) + "\n```\n")

    text = "\n".join(L)
    with open(o.out, "w") as f:
        f.write(text + "\n")
    print(text)


if __name__ == "__main__":
    main()
