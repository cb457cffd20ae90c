#!/usr/bin/env python3
"""Accuracy per cost on NAFEMS LE1: sigma_yy at D against unknowns and wall time, quad8 and the
report's SAAS element here against CalculiX 2.20's CPS8 and CPS4 on the same meshes.

    /usr/bin/python3 tests/bench/accuracy_per_cost.py [--sizes 2,4,8,16,32,64] [--rounds 3]

Each mesh is written by schemas/examples/make_le1_model.py (the mapped meshes the CalculiX figures of
issue 30 were measured on). saasgaps: `saasgaps solve` of the model, sigma_z of node 1 (D) from
`nodes[]`, the recovered nodal stress. CalculiX: the same nodes and elements as CPS8 (quad8 meshes) or
CPS4 (the SAAS meshes' corners), the outer pressure as *DLOAD, its extrapolated and averaged nodal
SYY at node 1 from the .frd. Wall time: the whole program run (read, solve, write), the best of
`--rounds`, the programs interleaved so both see the same load. Reported per element and size:
unknowns (2 per node), sigma_yy(D) / 92.7, seconds; then the first size whose error stays within 1 %
at every finer size, with its unknowns and seconds, and the ratios of those costs against quad8's.
Exits 0 without the CalculiX columns when ccx is not installed.
"""

import argparse
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
TARGET = 92.7


def le1(n, family):
    out = subprocess.run([sys.executable, str(ROOT / "schemas/examples/make_le1_model.py"), "--n", str(n), "--type", family],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def timed(command, cwd):
    start = time.perf_counter()
    subprocess.run(command, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def ours(binary, model, folder):
    path = folder / "model.json"
    path.write_text(json.dumps(model))
    seconds = timed([str(binary), "solve", str(path), "-q", "-o", str(folder / "result.json")], folder)
    result = json.loads((folder / "result.json").read_text())
    node = next(n for n in result["nodes"] if n["id"] == 1)
    if "sigma_z" not in node:
        raise SystemExit("this build writes no recovered nodal stresses (nodes[].sigma_z)")
    return node["sigma_z"], seconds


def calculix_deck(model, element):
    lines = ["*NODE, NSET=NALL"] + [f"{n['id']}, {n['r']!r}, {n['z']!r}" for n in model["nodes"]]
    lines.append(f"*ELEMENT, TYPE={element}, ELSET=SOLID")
    faces = {}
    for e in model["elements"]:
        nodes = e["nodes"] if element == "CPS8" else e["nodes"][:4]
        lines.append(f"{e['id']}, " + ", ".join(map(str, nodes)))
        for k in range(4):
            faces[(nodes[k], nodes[(k + 1) % 4])] = (e["id"], k + 1)
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", "210000, 0.3", "*SOLID SECTION, ELSET=SOLID, MATERIAL=M",
              str(model["analysis"]["thickness"]), "*BOUNDARY"]
    for c in model["constraints"]:
        lines += [f"{c['node']}, {dof}, {dof}, 0" for key, dof in (("r", 1), ("z", 2)) if key in c]
    lines += ["*STEP", "*STATIC", "*DLOAD"]
    for p in model["loads"]["pressures"]:
        element_id, face = faces[tuple(p["nodes"])]
        lines.append(f"{element_id}, P{face}, {p['normal']!r}")
    lines += ["*NODE FILE", "S", "*END STEP"]
    return "\n".join(lines) + "\n"


def calculix(model, element, folder):
    (folder / "le1.inp").write_text(calculix_deck(model, element))
    seconds = timed(["ccx", "le1"], folder)
    inside = False
    for line in (folder / "le1.frd").read_text().splitlines():
        if line.startswith(" -4  STRESS"):
            inside = True
        elif inside and line.startswith(" -1") and int(line[3:13]) == 1:
            return float(line[25:37]), seconds
    raise SystemExit("no nodal stress at node 1 in CalculiX's .frd")


def first_within(rows, tolerance=0.01):
    """The first row from which every finer row is within tolerance of the target."""
    for k, row in enumerate(rows):
        if all(abs(r["ratio"] - 1.0) <= tolerance for r in rows[k:]):
            return row
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", default="2,4,8,16,32,64", help="elements along each side, comma separated")
    parser.add_argument("--rounds", type=int, default=3, help="runs of each program per mesh, the best kept")
    parser.add_argument("--binary", type=lambda p: pathlib.Path(p).resolve(), default=ROOT / "build/saasgaps")
    args = parser.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    has_ccx = shutil.which("ccx") is not None
    programs = [("quad8", "quad8", None), ("saas", "saas", None)]
    if has_ccx:
        programs += [("CalculiX CPS8", "quad8", "CPS8"), ("CalculiX CPS4", "saas", "CPS4")]
    table = {name: [] for name, _, _ in programs}
    with tempfile.TemporaryDirectory(prefix="saasgaps-le1-") as tmp:
        folder = pathlib.Path(tmp)
        for n in sizes:
            models = {family: le1(n, family) for family in ("quad8", "saas")}
            best = {name: (None, float("inf")) for name, _, _ in programs}
            for _ in range(args.rounds):
                for name, family, element in programs:
                    run = ours(args.binary, models[family], folder) if element is None else calculix(models[family], element, folder)
                    best[name] = (run[0], min(best[name][1], run[1]))
            for name, family, _ in programs:
                sigma, seconds = best[name]
                table[name].append({"n": n, "unknowns": 2 * len(models[family]["nodes"]), "ratio": sigma / TARGET, "seconds": seconds})
    print(f"NAFEMS LE1, sigma_yy at D / {TARGET} (best of {args.rounds} runs per program and mesh)")
    print(f"{'program':<16}{'n x n':>7}{'unknowns':>10}{'sigma/target':>14}{'seconds':>10}")
    for name, rows in table.items():
        for r in rows:
            print(f"{name:<16}{r['n']:>7}{r['unknowns']:>10}{r['ratio']:>14.4f}{r['seconds']:>10.3f}")
    print("\nfirst mesh within 1 % from there on:")
    reached = {name: first_within(rows) for name, rows in table.items()}
    base = reached["quad8"]
    for name, row in reached.items():
        if row is None:
            print(f"{name:<16} not within 1 % at the sizes run")
            continue
        extra = f", {row['unknowns'] / base['unknowns']:.2f} x quad8's unknowns, {row['seconds'] / base['seconds']:.2f} x its time" if base else ""
        print(f"{name:<16} n = {row['n']}, {row['unknowns']} unknowns, {row['seconds']:.3f} s{extra}")
    if not has_ccx:
        print("(ccx not installed: no CalculiX columns)")


if __name__ == "__main__":
    main()
