#!/usr/bin/env python3
"""A small mutation fuzzer for the program `dealvem` (standard library only).

Seeds: the example parameter file examples/step-2/patch-test.prm, the
finite-strain, finite-sliding and assembly examples of examples/parameters
(made smaller: fewer cells and load steps, k = 1, so that a case stays within
its time limit under the sanitizers), the parameter files tests/app/*.prm
(among them the friction, load-step and rigid-boundary inputs
friction-rigid-steps.prm and coulomb-penalty-steps.prm), the friction,
load-step, penalty, rigid-boundary, verification, per-piece support and
finite-strain cases of the bad-input corpus tests/bad_input/*.prm (inputs one
mistake away from valid ones; the mesh files they name are copied beside each
case) and
the mesh files tests/mesh/data/* and tests/bad_input/*piece*, *hinge* (each mesh
read through a fixed parameter file).
Every case applies one to three
random mutations to one seed (flip, insert or delete characters, duplicate or
drop lines, replace a number by an extreme value or a huge count) and runs
`dealvem` on it with a time limit.

A case FAILS on
  - a crash: the program killed by a signal (segfault, abort, ...),
  - a sanitizer report (AddressSanitizer, LeakSanitizer, UBSan "runtime
    error:") in its output,
  - a hang: the time limit reached,
  - a crash string in the output ("Segmentation fault", "terminate called",
    "unknown exception", ...), whatever the exit code.
Leaks are not checked here (the sanitizer test suite does that, with the
slow unwinder OpenMPI's leaks need); memory errors and UB are.
Exiting non-zero with a message, or exiting 0, is fine: a mutation may be
harmless. The cases are drawn from a fixed seed before any runs, so a run is
deterministic and bounded. Failing cases are kept as reproducers under
OUT/failures/case-NNN/ (the mutated input, the other input files it needs and
the program's output); the script prints them and exits 1.

  scripts/fuzz.py --dealvem build-sanitize/bin/dealvem --out build-sanitize/fuzz
"""
import argparse
import concurrent.futures
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

CRASH_STRINGS = ["Segmentation fault", "AddressSanitizer", "LeakSanitizer",
                 "runtime error:", "terminate called", "unknown exception",
                 "ERROR: Sanitizer"]

# huge counts are beyond the program's run-size guard (2e7 DoFs): a count the
# guard accepts (65536 subdivisions: millions of DoFs) is a long run, not a hang
EXTREME_VALUES = ["0", "-1", "1e308", "-1e308", "nan", "inf", "-inf",
                  "4294967295", "2147483648", "-2147483649", "1e-308",
                  "18446744073709551615", "1e9", "1e12"]

# a parameter file that reads a mutated mesh file, by mesh kind
MESH_PRM = {
    ".vtk": """# fuzz: reads the (mutated) legacy VTK file
subsection Mesh
  set Type      = vtk file
  set File name = {mesh}
end
subsection Boundary conditions and loads
  set Dirichlet = 5 : xy : 0, 0
  set Traction  = 6 : 1, 0
end
subsection Output
  set Folder = output
end
""",
    ".msh": """# fuzz: reads the (mutated) gmsh file
subsection Mesh
  set Type      = gridin file
  set File name = {mesh}
end
subsection Boundary conditions and loads
  set Dirichlet = 4 : xy : 0, 0
  set Traction  = 2 : 1, 0
end
subsection Output
  set Folder = output
end
""",
}

# replacement values of a whole 'set name = value' entry
VALUES = ["", "0", "-1", "nan", "1e308", "x", "1/0", ":", ";", ",", "0, 0", "0 : xy : 0",
          "0 : xy : 0, 0; 0 : xy : 1, 1", "3 : 3", "3 : 12; 12 : 3", "0, 0 : x : 0 : 7",
          "sqrt(-1), 0", "{cycle}", "4294967295", "1e9, 1e9", "0, 0 : z : 0", "0 : ",
          "99 : 0, -1", "a=1, a=2", "p=", "3 : 0, -1 : 1e308"]

NUMBER = re.compile(r"(?<![A-Za-z_])[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


# the examples of the newer paths, each with the replacements that make it
# small (a seed's mutations then reach finite strain, finite sliding and
# assemblies of many bodies at the cost of a small run)
SMALL_EXAMPLES = [
    ("finite-strain-cook.prm", [("Subdivisions   = 16, 16", "Subdivisions   = 4, 4"),
                                ("Order = 2", "Order = 1"), ("Number of steps = 10", "Number of steps = 2")]),
    ("finite-strain-rotation.prm", [("Number of cells = 64", "Number of cells = 12"),
                                    ("Order = 2", "Order = 1"), ("Number of steps = 6", "Number of steps = 2")]),
    # (two steps on 4 x 2 and 2 x 2 cells: three steps on 6 x 2 and 3 x 3
    # took 20 s at -O0 with the sanitizers, the fuzzer's time limit)
    ("finite-sliding-block.prm", [("Subdivisions        = 12, 4", "Subdivisions        = 4, 2"),
                                  ("Subdivisions       = 5, 5", "Subdivisions       = 2, 2"),
                                  ("Order = 2", "Order = 1"), ("Number of steps = 12", "Number of steps = 2"),
                                  ("Final time      = 1.3", "Final time      = 0.3")]),
    ("assembly-tower.prm", []),
    ("assembly-wall.prm", []),
]


def seeds():
    """(name, kind, text) of every seed; kind is 'prm' or a mesh suffix."""
    out = []
    for name, replacements in SMALL_EXAMPLES:
        path = os.path.join(ROOT, "examples", "parameters", name)
        with open(path, encoding="utf-8", errors="replace") as fh:
            text = fh.read()
        for a, b in replacements:
            if a not in text:
                raise SystemExit("fuzz.py: %s no longer contains %r; update SMALL_EXAMPLES" % (path, a))
            text = text.replace(a, b)
        out.append((os.path.relpath(path, ROOT), "prm", text))
    files = [os.path.join(ROOT, "examples", "step-2", "patch-test.prm")]
    app = os.path.join(ROOT, "tests", "app")
    files += sorted(os.path.join(app, f) for f in os.listdir(app) if f.endswith(".prm"))
    # of the bad-input corpus, the friction, load-step, penalty and
    # rigid-boundary inputs: one mistake away from valid ones
    bad = os.path.join(ROOT, "tests", "bad_input")
    for f in sorted(os.listdir(bad)):
        if f.endswith(".prm"):
            with open(os.path.join(bad, f), encoding="utf-8", errors="replace") as fh:
                text = fh.read()
            # ... and the verification, per-piece support and finite-strain
            # inputs (their mesh files are copied beside each case, see
            # write_case())
            if re.search(r"coulomb|Load steps|Rigid boundary|Penalty|Verification|piece|hinge|"
                         r"Finite strain", text):
                files.append(os.path.join(bad, f))
    for f in files:
        with open(f, encoding="utf-8", errors="replace") as fh:
            out.append((os.path.relpath(f, ROOT), "prm", fh.read()))
    # mesh files: the valid ones, and the rejected gmsh files of the
    # bad-input corpus (an interior physical line, a zero-area triangle, a
    # duplicated cell, ...), each one mutation away from other mistakes
    mesh_files = []
    data = os.path.join(ROOT, "tests", "mesh", "data")
    mesh_files += [os.path.join(data, f) for f in sorted(os.listdir(data))]
    mesh_files += [os.path.join(bad, f) for f in sorted(os.listdir(bad))
                   if f.endswith(".msh") or re.search(r"piece|hinge", f)]
    for path in mesh_files:
        suffix = os.path.splitext(path)[1]
        if suffix in MESH_PRM:
            with open(path, encoding="utf-8", errors="replace") as fh:
                out.append((os.path.relpath(path, ROOT), suffix, fh.read()))
    return out


def mutate(text, rng):
    """One random mutation of text; returns (new text, description)."""
    lines = text.split("\n")
    # numbers and values reach deeper than broken names, so they come more often
    op = rng.choice(["flip", "insert", "delete", "dup-line", "drop-line", "swap-lines",
                     "number", "number", "number", "number", "number", "value", "value"])
    if op == "value":
        spots = [i for i, line in enumerate(lines) if re.match(r"\s*set [^=]+=", line)]
        if spots:
            i = rng.choice(spots)
            v = rng.choice(VALUES)
            lines[i] = lines[i].split("=", 1)[0] + "= " + v
            return "\n".join(lines), "line %d value -> %r" % (i + 1, v)
        op = "number"
    if op == "flip" and text:
        i = rng.randrange(len(text))
        c = chr(rng.randrange(32, 127)) if rng.random() < 0.8 else rng.choice("\t\n\0\x7f\xe9")
        return text[:i] + c + text[i + 1:], f"flip char {i} to {c!r}"
    if op == "insert":
        i = rng.randrange(len(text) + 1)
        s = "".join(chr(rng.randrange(32, 127)) for _ in range(rng.randint(1, 8)))
        if rng.random() < 0.2:
            s = rng.choice([":", ";", ",", "{cycle}", "end\n", "subsection Mesh\n", "=", "\\\n"])
        return text[:i] + s + text[i:], f"insert {s!r} at {i}"
    if op == "delete" and text:
        i = rng.randrange(len(text))
        n = rng.randint(1, 12)
        return text[:i] + text[i + n:], f"delete {n} chars at {i}"
    if op == "dup-line" and lines:
        i = rng.randrange(len(lines))
        k = rng.choice([1, 1, 2, 50])
        return "\n".join(lines[:i + 1] + [lines[i]] * k + lines[i + 1:]), f"duplicate line {i + 1} x{k}"
    if op == "drop-line" and lines:
        i = rng.randrange(len(lines))
        return "\n".join(lines[:i] + lines[i + 1:]), f"drop line {i + 1}"
    if op == "swap-lines" and len(lines) > 1:
        i, j = rng.sample(range(len(lines)), 2)
        lines[i], lines[j] = lines[j], lines[i]
        return "\n".join(lines), f"swap lines {i + 1} and {j + 1}"
    # replace a number (not in a comment) by an extreme value or a huge count
    spots = []
    for ln, line in enumerate(lines):
        code = line.split("#", 1)[0]
        offset = sum(len(l) + 1 for l in lines[:ln])
        spots += [(offset + m.start(), offset + m.end()) for m in NUMBER.finditer(code)]
    if not spots:
        return text + "\n" + rng.choice(EXTREME_VALUES), "append a number"
    a, b = rng.choice(spots)
    v = rng.choice(EXTREME_VALUES)
    return text[:a] + v + text[b:], f"number {text[a:b]!r} at {a} -> {v}"


def make_cases(n_cases, seed):
    rng = random.Random(seed)
    pool = seeds()
    cases = []
    for index in range(n_cases):
        name, kind, text = pool[index % len(pool)] if index < len(pool) else rng.choice(pool)
        log = []
        for _ in range(rng.choice([1, 1, 2, 3])):
            text, what = mutate(text, rng)
            log.append(what)
        cases.append({"index": index, "seed_file": name, "kind": kind, "text": text,
                      "mutations": log})
    return cases


def write_case(case, folder):
    """Write the case's input files into folder; returns the parameter file."""
    os.makedirs(folder, exist_ok=True)
    if case["kind"] == "prm":
        prm = os.path.join(folder, "input.prm")
        with open(prm, "w", encoding="utf-8", errors="replace") as fh:
            fh.write(case["text"])
        # the mesh files a seed names ('File name = ...' beside the seed)
        seed_dir = os.path.join(ROOT, os.path.dirname(case["seed_file"]))
        for name in re.findall(r"File name\s*=\s*(\S+)", case["text"]):
            source = os.path.join(seed_dir, os.path.basename(name))
            if os.path.isfile(source):
                shutil.copy(source, os.path.join(folder, os.path.basename(name)))
    else:
        mesh = "mesh" + case["kind"]
        with open(os.path.join(folder, mesh), "w", encoding="utf-8", errors="replace") as fh:
            fh.write(case["text"])
        prm = os.path.join(folder, "input.prm")
        with open(prm, "w", encoding="utf-8") as fh:
            fh.write(MESH_PRM[case["kind"]].format(mesh=mesh))
    return prm


def run_case(case, dealvem, out, timeout):
    folder = os.path.join(out, "cases", "case-%03d" % case["index"])
    shutil.rmtree(folder, ignore_errors=True)
    prm = write_case(case, folder)
    # an Open MPI session folder of its own: cases run concurrently, and a
    # finalizing process removes the shared <tmp>/ompi.<host>.<uid> while
    # another one creates its folder in it (MPI_Init fails, about one start
    # in 450); the path stays short, Open MPI puts Unix sockets there
    session = tempfile.mkdtemp(prefix="dealvem-fuzz-")
    env = dict(os.environ, OMPI_MCA_orte_tmpdir_base=session)
    start = time.time()
    proc = subprocess.Popen([dealvem, prm], cwd=folder, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True, env=env)
    verdict = None
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        stdout, stderr = proc.communicate()
        verdict = "hang (no end within %g s)" % timeout
    seconds = time.time() - start
    shutil.rmtree(session, ignore_errors=True)
    text = stdout.decode("utf-8", "replace") + stderr.decode("utf-8", "replace")
    rc = proc.returncode
    if verdict is None and rc < 0:
        verdict = "killed by signal %s" % signal.Signals(-rc).name
    if verdict is None:
        hits = [s for s in CRASH_STRINGS if s in text]
        if hits:
            verdict = "exit %d with %s in the output" % (rc, ", ".join(repr(h) for h in hits))
    with open(os.path.join(folder, "output.txt"), "w", encoding="utf-8") as fh:
        fh.write("seed: %s\nmutations: %s\nexit: %s\ntime: %.1f s\n\n%s" % (
            case["seed_file"], "; ".join(case["mutations"]), rc, seconds, text))
    return {"index": case["index"], "verdict": verdict, "rc": rc, "seconds": seconds,
            "folder": folder}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--dealvem", default=os.path.join(ROOT, "build-sanitize", "bin", "dealvem"))
    ap.add_argument("--out", default=None, help="work and reproducer folder (default: <build>/fuzz)")
    ap.add_argument("--cases", type=int, default=150)
    ap.add_argument("--seed", type=int, default=20240611)
    ap.add_argument("--timeout", type=float, default=20.0, help="seconds per case")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--keep", action="store_true", help="keep the folders of passing cases")
    args = ap.parse_args()

    dealvem = os.path.abspath(args.dealvem)
    if not os.access(dealvem, os.X_OK):
        sys.exit("fuzz: no program %s (build it first)" % dealvem)
    out = os.path.abspath(args.out or os.path.join(os.path.dirname(os.path.dirname(dealvem)), "fuzz"))
    shutil.rmtree(os.path.join(out, "cases"), ignore_errors=True)
    shutil.rmtree(os.path.join(out, "failures"), ignore_errors=True)
    os.makedirs(out, exist_ok=True)

    # one MPI process per case; sanitizer allocations beyond a few GB fail
    # (std::bad_alloc, which the program reports) instead of eating the machine
    env = os.environ
    if "ASAN_OPTIONS" not in env:
        # the suppression files and options of scripts/sanitize.sh
        dump = subprocess.run(["bash", "-c", 'source "$0" && env -0',
                               os.path.join(ROOT, "scripts", "sanitizer-env.sh")],
                              check=True, stdout=subprocess.PIPE).stdout
        for item in dump.split(b"\0"):
            key, _, value = item.decode().partition("=")
            if key.endswith("SAN_OPTIONS") or key.startswith("OMPI_MCA_"):
                env[key] = value
    env.setdefault("OMP_NUM_THREADS", "1")
    # Leaks are the test suite's business (scripts/sanitize.sh): the leak
    # check at exit, with the symbolization of OpenMPI's suppressed leaks,
    # doubles the time of a short run. Here: memory errors and UB, no leak
    # check.
    opts = dict(o.split("=", 1) for o in env.get("ASAN_OPTIONS", "").split(":") if "=" in o)
    opts.update({"detect_leaks": "0", "fast_unwind_on_malloc": "1",
                 "allocator_may_return_null": "1", "max_allocation_size_mb": "4096",
                 "soft_rss_limit_mb": "6144"})
    opts.pop("malloc_context_size", None)
    env["ASAN_OPTIONS"] = ":".join("%s=%s" % kv for kv in opts.items())

    cases = make_cases(args.cases, args.seed)
    start = time.time()
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [pool.submit(run_case, c, dealvem, out, args.timeout) for c in cases]
        for f in concurrent.futures.as_completed(futures):
            results.append(f.result())
    results.sort(key=lambda r: r["index"])

    failures = [r for r in results if r["verdict"]]
    for r in results:
        if r["verdict"]:
            dest = os.path.join(out, "failures", os.path.basename(r["folder"]))
            shutil.move(r["folder"], dest)
            r["folder"] = dest
        elif not args.keep:
            shutil.rmtree(r["folder"], ignore_errors=True)
    n_zero = sum(1 for r in results if r["rc"] == 0)
    slowest = max(results, key=lambda r: r["seconds"])
    summary = ("fuzz: %d cases (seed %d), %d exited 0, %d rejected the input, %d failed; "
               "%.0f s, slowest case-%03d %.1f s" % (
                   len(results), args.seed, n_zero, len(results) - n_zero - len(failures),
                   len(failures), time.time() - start, slowest["index"], slowest["seconds"]))
    with open(os.path.join(out, "summary.txt"), "w", encoding="utf-8") as fh:
        fh.write(summary + "\n")
        for r in results:
            fh.write("case-%03d exit %s %.1f s %s %s\n" % (
                r["index"], r["rc"], r["seconds"], cases[r["index"]]["seed_file"],
                r["verdict"] or "ok"))
    print(summary)
    if failures:
        for r in failures:
            c = cases[r["index"]]
            print("FAIL case-%03d: %s\n  seed %s, mutations: %s\n  reproducer: %s "
                  "(run: cd %s && %s input.prm; output in output.txt)" % (
                      r["index"], r["verdict"], c["seed_file"], "; ".join(c["mutations"]),
                      r["folder"], r["folder"], dealvem))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
