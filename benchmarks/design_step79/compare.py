#!/usr/bin/env python3
# The comparison table of benchmarks/design_step79/run.sh: step-79's line
# "DEALVEM_STEP79 ..." (its log), dealvem's design_step79.csv and
# design_step79_eval.csv, as Markdown on stdout.
#
# Usage: compare.py --step79-log LOG --ours CSV --eval CSV [--step79-wall S]
#                   [--step79-rss KB] [--ours-rss KB]
import argparse
import csv
import sys


def step79_result(path):
    for line in open(path):
        if line.startswith("DEALVEM_STEP79 "):
            items = line.split()[1:]
            return {items[i]: float(items[i + 1]) for i in range(0, len(items) - 1, 2)}
    sys.exit("compare.py: no DEALVEM_STEP79 line in " + path)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--step79-log", required=True)
    ap.add_argument("--ours", required=True)
    ap.add_argument("--eval", required=True)
    ap.add_argument("--step79-wall", default="")
    args = ap.parse_args()

    s = step79_result(args.step79_log)
    ours = list(csv.DictReader(open(args.ours)))
    J0, T0 = s["compliance"], s["time"]

    def f(x, d=3):
        return "%.*f" % (d, x)

    print("| code, mesh | cells | k | displacement DoFs | method | iterations | compliance | ours / step-79 "
          "| volume | grey | time (s) | time / step-79 | per iteration (ms) |")
    print("|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    print("| **step-79, quads 48x8** | %d | Q1 | %d | SAND, interior point | %d Newton (%d barrier) | %s | 1 "
          "| %s | %s | %s | 1 | %s |" % (s["cells"], s["displacement_dofs"], s["newton_steps"], s["barrier_steps"],
                                         f(J0), f(s["volume"], 4), f(s["grey"]), f(T0, 2),
                                         f(1e3 * T0 / s["newton_steps"], 1)))

    def row(r, bold=False):
        t = float(r["setup_time"]) + float(r["time"])
        it = int(r["iterations"])
        name = "dealvem, " + r["mesh"]
        if bold:
            name = "**" + name + "**"
        conv = "" if r["converged"] == "1" else " (limit)"
        print("| %s | %s | %s | %s | %s | %d%s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, r["cells"], r["k"], r["dofs"], r["optimizer"] + ", nested", it, conv, f(float(r["compliance"])),
            f(float(r["compliance"]) / J0, 4), f(float(r["volume"]), 4), f(float(r["grey"])), f(t, 2),
            "%.2g" % (t / T0), f(1e3 * float(r["time"]) / max(it, 1), 1)))

    lead = [r for r in ours if r["mesh"].startswith("quads") and r["k"] == "1" and r["optimizer"] == "MMA"]
    for r in lead:
        row(r, True)
    for r in ours:
        if r not in lead:
            row(r)
    print()
    print("step-79: compliance f^T u = %.8g (boundary integral of t . u: %.8g), force %.3g on a loaded length "
          "%.3g, filtered densities in [%.3g, %.4g], unfiltered volume %.4f; time = wall time of run() "
          "(its setup included, no VTU output)%s." % (
              J0, s["compliance_integral"], -s["force"], s["loaded_length"], s["min_density"], s["max_density"],
              s["unfiltered_volume"], ", process wall " + args.step79_wall if args.step79_wall else ""))
    print("dealvem: time = setup (mesh, DoFs, problem) + optimizer wall time; iterations = evaluations of the state "
          "(one linear solve each, as step-79's Newton steps are one KKT solve each).")
    ev = list(csv.DictReader(open(args.eval)))
    if ev:
        print()
        print("step-79's final design evaluated by dealvem on the same 48x8 quads (s = rho^3, s_min = 1e-9): "
              "the discretizations on one design")
        print()
        print("| dealvem k | DoFs | compliance | / step-79's own (Q1) |")
        print("|---:|---:|---:|---:|")
        for e in ev:
            print("| %s | %s | %s | %s |" % (e["k"], e["dofs"], f(float(e["compliance"])),
                                             f(float(e["compliance"]) / J0, 4)))


if __name__ == "__main__":
    main()
