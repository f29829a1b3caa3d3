#!/usr/bin/env python3
# The statics of the wall of examples/parameters/assembly-wall-1000.prm,
# from its resultants CSV (one line per interface): run by
# tests/app/thousand_bodies.test.cmake. Body 0 is the base; bodies 1 to 1020
# the blocks, course by course from the bottom (even courses 25 blocks,
# odd courses 26), each 0.5 high, unit weight per area. With the node
# pairs' CSV and a friction coefficient mu as further arguments, also
# Coulomb's law |tau| <= mu p at every closed pair (1e-10 of the largest p).
import csv
import sys

courses, per_course = 40, 25
course_of = {0: -1}
weight_of_course = []
b = 1
for c in range(courses):
    n = per_course if c % 2 == 0 else per_course + 1
    for _ in range(n):
        course_of[b] = c
        b += 1
    weight_of_course.append(0.5 * per_course)  # 25 x 0.5 of length 1
weight = sum(weight_of_course)

rows = list(csv.DictReader(open(sys.argv[1])))
failures = []
expected = 25 + 50 * 39 + 20 * 24 + 20 * 25
if len(rows) != expected:
    failures.append(f"{len(rows)} interfaces, expected {expected}")
bodies = {int(r[k]) for r in rows for k in ("master_body", "slave_body")}
if bodies != set(range(1021)):
    failures.append(f"the interfaces touch {len(bodies)} bodies, expected all 1021")

# bed joints: force on the upper side, summed per course below
vertical = [0.0] * (courses + 1)     # index c + 1: joints on top of course c (c = -1: the base)
horizontal = [0.0] * (courses + 1)
for r in rows:
    m, s = int(r["master_body"]), int(r["slave_body"])
    cm, cs = course_of[m], course_of[s]
    if cm == cs:
        continue  # a head joint
    if abs(cm - cs) != 1:
        failures.append(f"interface {r['interface']} joins courses {cm} and {cs}")
        continue
    # force_x, force_y act on the slave body: on the upper side if the slave is above
    sign = 1.0 if cs > cm else -1.0
    lower = min(cm, cs)
    vertical[lower + 1] += sign * float(r["force_y"])
    horizontal[lower + 1] += sign * float(r["force_x"])

above = weight
worst = 0.0
for c in range(-1, courses - 1):
    # the joints on top of course c carry the courses c + 1 ... (upward force on them)
    err = abs(vertical[c + 1] - above) / weight
    worst = max(worst, err, abs(horizontal[c + 1]) / weight)
    if err > 1e-9 or abs(horizontal[c + 1]) > 1e-9 * weight:
        failures.append(f"bed joints on course {c}: vertical {vertical[c + 1]:.12g} (expected {above:.12g}), "
                        f"horizontal {horizontal[c + 1]:.3g} (expected 0)")
    above -= weight_of_course[c + 1]

if len(sys.argv) > 3:
    mu = float(sys.argv[3])
    pairs = list(csv.DictReader(open(sys.argv[2])))
    p_max = max(float(r["lumped_pressure"]) for r in pairs)
    excess = max(abs(float(r["tangential_traction"])) - mu * float(r["lumped_pressure"])
                 for r in pairs if r["status"] != "open")
    counts = {s: sum(1 for r in pairs if r["status"] == s) for s in ("open", "stick", "slip")}
    print(f"Coulomb, mu = {mu}: {counts['open']} open / {counts['stick']} stick / {counts['slip']} slip pairs; "
          f"largest |tau| - mu p: {excess:.2e} (p up to {p_max:.3g})")
    if excess > 1e-10 * p_max:
        failures.append(f"|tau| exceeds mu p by {excess:.3g}")
    if counts["slip"] == 0:
        failures.append("no pair slips: the test does not exercise Coulomb's law")

print(f"{len(rows)} interfaces between {len(bodies)} bodies; weight {weight}; base carries "
      f"{vertical[0]:.12g}; largest error of the bed joints' resultants {worst:.2e} of the weight")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
