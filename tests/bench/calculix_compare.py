#!/usr/bin/env python3
"""saasgaps against CalculiX (ccx, Debian's calculix-ccx) on the same gap problem: wall time and
contact pressure.

    python3 schemas/examples/make_ring_model.py --radial 61 --hoop 600 -o /tmp/annulus-150k.json
    python3 tests/bench/calculix_compare.py /tmp/annulus-150k.json --rounds 3

The model document is converted to a CalculiX deck: one layer of C3D8 bricks, every node held in z
(plane strain exactly; CalculiX's gap elements act only between nodes of a 3D model), the bricks on
the quadrilaterals' corner nodes (CalculiX's trilinear element, not the SAAS quadrilateral of four
triangles); the isotropic material of the first table row (E, nu, alpha);
the constraints as *BOUNDARY; nodal temperatures as *TEMPERATURE from an initial 0. Each gap element
(4 nodes: a, b across the gap, then c, d across it again) becomes GAPUNI elements between the node
pairs (a, b) and (d, c), in both layers, direction from the first to the second node, clearance their distance,
and a penalty stiffness k chosen so that the penetration is about 0.5 % of the interference (as our
converged gaps keep 99 % closure). CalculiX then solves the contact problem by its own Newton
iteration with SPOOLES, on all cores (OMP_NUM_THREADS).

saasgaps runs twice per round: with the model's own gap method (classic: the report's stress
invariance iteration, 9 refactorizations on the annulus) and with `gaps.method: "exact"` (the
contact problem solved by active sets: one factorization on a fit that closes everywhere). Both
programs run one after the other in each round (interleaved, so all see the same load); reported:
each wall time, the ratios (ccx / saasgaps: how many times faster saasgaps is), and the mean
contact pressure of each: saasgaps's gap sigma_m, CalculiX's gap forces k * penetration (from
its printed displacements of the gap nodes) over the interface length, with their relative
difference. Exits 0 without running when ccx is not installed.
"""

import argparse
import json
import math
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
BUILD = HERE.parent.parent / "build"


def deck(model, stiffness):
    """The CalculiX input deck for a plane-strain saasgaps model document, and the gap pairs.

    CalculiX's GAPUNI acts only between nodes of a 3D model (its 2D elements are expanded to 3D
    internally, away from the nodes a gap element names), so the plane-strain model becomes one layer
    of C3D8 bricks, thickness t, every node held in z: plane strain exactly. Node n sits at z = 0 and
    n + offset at z = t; each gap pair is present in both layers."""
    if model["analysis"]["type"] != "plane_strain":
        raise SystemExit("only plane-strain models convert")
    thickness = model["analysis"].get("thickness", 1.0)
    xy = {n["id"]: (n["r"], n["z"]) for n in model["nodes"]}
    offset = 10 ** len(str(max(xy)))
    lines = ["*HEADING", model.get("title", "saasgaps model"), "*NODE, NSET=NALL"]
    for z, shift in ((0.0, 0), (thickness, offset)):
        lines += [f"{n['id'] + shift}, {n['r']!r}, {n['z']!r}, {z!r}" for n in model["nodes"]]
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=SOLID")
    for e in model["elements"]:
        if len(e["nodes"]) != 4:
            raise SystemExit(f"element {e['id']}: only quadrilaterals convert")
        lines.append(f"{e['id']}, " + ", ".join(str(n) for n in e["nodes"]) + ", " +
                     ", ".join(str(n + offset) for n in e["nodes"]))
    pairs = []
    for g in model.get("gaps", {}).get("elements", []):
        a, b, c, d = g["nodes"]
        for p in ((a, b), (d, c)):
            if p not in pairs:
                pairs.append(p)
    first_gap = max(e["id"] for e in model["elements"]) + 1
    gap_lines = []
    for k, (a, b) in enumerate(pairs):
        (xa, ya), (xb, yb) = xy[a], xy[b]
        length = math.hypot(xb - xa, yb - ya)
        eid = first_gap + 2 * k
        lines += [f"*ELEMENT, TYPE=GAPUNI, ELSET=G{eid}", f"{eid}, {a}, {b}", f"{eid + 1}, {a + offset}, {b + offset}"]
        # Clearance d and direction n from the first node to the second: CalculiX closes the gap when
        # d + n . (u_second - u_first) <= 0.
        gap_lines += [f"*GAP, ELSET=G{eid}", f"{length!r}, {(xb - xa) / length!r}, {(yb - ya) / length!r}, 0., ,"
                      f" {stiffness / 2!r}"]
    material = model["materials"][0]
    row = material["table"][0]
    lines += ["*MATERIAL, NAME=M1", "*ELASTIC", f"{row['E']!r}, {row['nu']!r}",
              f"*EXPANSION, ZERO={model['analysis'].get('reference_temperature', 0.0)!r}", f"{row['alpha']!r}",
              "*SOLID SECTION, ELSET=SOLID, MATERIAL=M1"]
    lines += gap_lines
    lines += ["*BOUNDARY", "NALL, 3, 3, 0."]
    for c in model.get("constraints", []):
        for shift in (0, offset):
            if "r" in c:
                lines.append(f"{c['node'] + shift}, 1, 1, {c['r']!r}")
            if "z" in c:
                lines.append(f"{c['node'] + shift}, 2, 2, {c['z']!r}")
    temperatures = model["loads"]["temperatures"]
    lines += ["*INITIAL CONDITIONS, TYPE=TEMPERATURE", f"NALL, {model['analysis'].get('reference_temperature', 0.0)!r}"]
    gap_nodes = sorted({n for p in pairs for n in p})
    lines += ["*NSET, NSET=NGAP"] + [f"{n}," for n in gap_nodes]
    # NLGEOM: CalculiX applies gap elements only in a nonlinear step (strains here stay ~1e-3).
    lines += ["*STEP, NLGEOM, INC=100", "*STATIC", "*TEMPERATURE", f"NALL, {temperatures.get('default', 0.0)!r}"]
    for t in temperatures.get("nodal", []):
        lines += [f"{t['node']}, {t['T']!r}", f"{t['node'] + offset}, {t['T']!r}"]
    lines += ["*NODE PRINT, NSET=NGAP", "U", "*END STEP", ""]
    return "\n".join(lines), pairs


def ccx_displacements(dat_path):
    """Node -> (u, v) from the last displacement block of a .dat file."""
    u = {}
    block = False
    for line in pathlib.Path(dat_path).read_text().splitlines():
        if line.strip().startswith("displacements"):
            block, u = True, {}
            continue
        parts = line.split()
        if block and len(parts) == 4:
            try:
                u[int(parts[0])] = (float(parts[1]), float(parts[2]))
            except ValueError:
                block = False
    return u


def ccx_pressure(model, pairs, u, stiffness):
    """Mean contact pressure: the sum of gap forces k * penetration over the interface length."""
    xy = {n["id"]: (n["r"], n["z"]) for n in model["nodes"]}
    force = 0.0
    for a, b in pairs:
        (xa, ya), (xb, yb) = xy[a], xy[b]
        length = math.hypot(xb - xa, yb - ya)
        nx, ny = (xb - xa) / length, (yb - ya) / length
        closing = (u[a][0] - u[b][0]) * nx + (u[a][1] - u[b][1]) * ny
        force += stiffness * max(0.0, closing - length)
    # Interface length: the gap elements' mid-line, one segment per gap.
    interface = 0.0
    for g in model["gaps"]["elements"]:
        a, b, c, d = g["nodes"]
        mid1 = ((xy[a][0] + xy[b][0]) / 2, (xy[a][1] + xy[b][1]) / 2)
        mid2 = ((xy[c][0] + xy[d][0]) / 2, (xy[c][1] + xy[d][1]) / 2)
        interface += math.hypot(mid2[0] - mid1[0], mid2[1] - mid1[1])
    return force / (interface * model["analysis"].get("thickness", 1.0))


def saasgaps_pressure(result):
    """Mean contact pressure of the gaps (sigma_m is negative in compression)."""
    values = [-g["sigma_m"] for g in result["gaps"]]
    return sum(values) / len(values)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("model", help="a plane-strain model document of quadrilaterals and gaps")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--saasgaps", default=str(BUILD / "saasgaps"))
    parser.add_argument("--penetration", type=float, default=0.005,
                        help="CalculiX gap penetration aimed at, as a share of the interference")
    parser.add_argument("--keep", help="keep the deck and outputs in this directory")
    args = parser.parse_args()
    if shutil.which("ccx") is None:
        print("ccx is not installed (Debian: apt-get install calculix-ccx): nothing to compare")
        return 0
    model = json.loads(pathlib.Path(args.model).read_text())
    # The penalty: the Lame pressure estimate of the model's description is not at hand in general,
    # so take the interference-free estimate p ~ E alpha dT / 3 and aim at the penetration share.
    row = model["materials"][0]["table"][0]
    nodal = model["loads"]["temperatures"].get("nodal", [])
    hot = max((t["T"] for t in nodal), default=0.0)
    pressure_guess = row["E"] * row["alpha"] * hot / 3.0
    n_gaps = len(model["gaps"]["elements"])
    first = model["gaps"]["elements"][0]["nodes"]
    xy = {n["id"]: (n["r"], n["z"]) for n in model["nodes"]}
    segment = math.hypot(xy[first[3]][0] - xy[first[0]][0], xy[first[3]][1] - xy[first[0]][1])
    interference = 0.002 if n_gaps == 0 else max(1e-6, row["alpha"] * hot * 1.5 - 0.002)
    stiffness = pressure_guess * segment / (args.penetration * interference)

    work = pathlib.Path(args.keep) if args.keep else pathlib.Path(tempfile.mkdtemp(prefix="saasgaps-ccx-"))
    work.mkdir(parents=True, exist_ok=True)
    text, pairs = deck(model, stiffness)
    (work / "deck.inp").write_text(text)
    exact_model = json.loads(json.dumps(model))
    exact_model["gaps"]["method"] = "exact"
    (work / "exact.json").write_text(json.dumps(exact_model))
    runs = {"classic": [args.saasgaps, "solve", args.model, "-q", "-o", str(work / "classic.json")],
            "exact": [args.saasgaps, "solve", str(work / "exact.json"), "-q", "-o", str(work / "exact-result.json")]}
    env = dict(os.environ)
    env.setdefault("OMP_NUM_THREADS", str(os.cpu_count() or 1))
    env.setdefault("CCX_NPROC_EQUATION_SOLVER", env["OMP_NUM_THREADS"])
    ours_s = {name: [] for name in runs}
    theirs_s = []
    print(f"model {args.model}: {len(model['nodes'])} nodes, {len(model['elements'])} elements, {n_gaps} gaps "
          f"({len(pairs)} GAPUNI pairs, k = {stiffness:.4g})")
    print(f"{'round':>5} {'classic s':>10} {'exact s':>8} {'ccx s':>8} {'ccx/classic':>12} {'ccx/exact':>10}")
    for round_ in range(1, args.rounds + 1):
        for name, command in runs.items():
            start = time.monotonic()
            subprocess.run(command, check=True)
            ours_s[name].append(time.monotonic() - start)
        start = time.monotonic()
        done = subprocess.run(["ccx", "-i", "deck"], cwd=work, env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True)
        theirs_s.append(time.monotonic() - start)
        if done.returncode != 0 or "Job finished" not in done.stdout:
            print(done.stdout[-3000:], file=sys.stderr)
            raise SystemExit("ccx failed")
        classic, exact = ours_s["classic"][-1], ours_s["exact"][-1]
        print(f"{round_:>5} {classic:>10.2f} {exact:>8.2f} {theirs_s[-1]:>8.2f} {theirs_s[-1] / classic:>12.2f} "
              f"{theirs_s[-1] / exact:>10.2f}")
    theirs_p = ccx_pressure(model, pairs, ccx_displacements(work / "deck.dat"), stiffness)
    for name, result in (("classic", "classic.json"), ("exact", "exact-result.json")):
        ratio = statistics.median(t / o for t, o in zip(theirs_s, ours_s[name]))
        ours_p = saasgaps_pressure(json.loads((work / result).read_text()))
        print(f"{name}: median ccx / saasgaps wall time {ratio:.2f} over {args.rounds} rounds; mean contact "
              f"pressure saasgaps {ours_p:.1f}, CalculiX {theirs_p:.1f}, difference "
              f"{100.0 * (ours_p - theirs_p) / theirs_p:+.2f} %")
    if not args.keep:
        shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
