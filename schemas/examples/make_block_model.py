#!/usr/bin/env python3
"""Writes a model of any size: a square block cut at mid height by a row of gap elements.

    python3 schemas/examples/make_block_model.py 120 > block.json    # 120 x 120 elements + 120 gaps
    python3 schemas/examples/make_block_model.py 120 --increments 30 > slow.json  # loads in 30 increments

An n x n plane-strain block of unit side, steel (E = 30e6, nu = 0.3), cut at mid height by a gap of
1 % of an element's height, bridged by n gap elements (M along z). The bottom row of nodes is held; the
upper half is pressed down (1000) on the left quarter of its top and pulled up (200) on the right
quarter, so it tilts onto the lower half: gaps close on the left and open on the right, and the
tensile schedule (50, 20, 10, 5, 2, 1) takes several iterations to relax the open ones. Units: in,
lbf, psi. The size sets the work per iteration: about 2 n^2 unknowns.

--increments K applies the loads in one load step of K increments (a run K times as long, long
enough to cancel by hand).
"""

import argparse
import json
import sys


def grid(n, rows, z0, h, first_node, first_element, nodes, elements):
    """Nodes of an (n + 1) x (rows + 1) grid from height z0, and its n x rows elements; node ids by row."""
    ids = [[first_node + j * (n + 1) + i for i in range(n + 1)] for j in range(rows + 1)]
    for j in range(rows + 1):
        for i in range(n + 1):
            nodes.append({"id": ids[j][i], "r": round(i * h, 12), "z": round(z0 + j * h, 12)})
    for j in range(rows):
        for i in range(n):
            elements.append({"id": first_element + j * n + i, "material": 1,
                             "nodes": [ids[j][i], ids[j][i + 1], ids[j + 1][i + 1], ids[j + 1][i]]})
    return ids


def model(n, increments=0):
    half = n // 2
    h = 1.0 / n
    nodes, elements = [], []
    lower = grid(n, half, 0.0, h, 1, 1, nodes, elements)
    upper = grid(n, n - half, half * h + 0.01 * h, h, len(nodes) + 1, len(elements) + 1, nodes, elements)
    gaps = [{"id": len(elements) + 1 + i, "angle": 90.0,
             "nodes": [lower[half][i], lower[half][i + 1], upper[0][i + 1], upper[0][i]]} for i in range(n)]
    top = upper[n - half]
    pressures = []
    for i in range(n // 4):
        pressures.append({"nodes": [top[i], top[i + 1]], "normal": 1000.0})
        pressures.append({"nodes": [top[n - 1 - i], top[n - i]], "normal": -200.0})
    return {
        "schema_version": 1,
        "title": f"Tilted block on a row of gaps, {n} x {n}",
        "description": __doc__.split("\n\n")[2].replace("\n", " ").strip(),
        "units": {"length": "in", "force": "lbf", "stress": "psi"},
        "analysis": {"type": "plane_strain"},
        "nodes": nodes,
        "materials": [{"id": 1, "name": "steel", "elastic": "isotropic",
                       "table": [{"T": 0.0, "E": 30.0e6, "nu": 0.3, "alpha": 0.0}]}],
        "elements": elements,
        "gaps": {"initial_modulus": 100.0, "tensile_schedule": [50.0, 20.0, 10.0, 5.0, 2.0, 1.0],
                 "elements": gaps},
        # The bottom row held in r and z; one corner of the upper half held in r (it may not slide off).
        "constraints": [{"node": node, "r": 0.0, "z": 0.0} for node in lower[0]] + [{"node": top[0], "r": 0.0}],
        "loads": {"pressures": pressures},
        "solver": {"max_iterations": 40},
        "output": {"watch_gaps": [gaps[0]["id"], gaps[-1]["id"]]},
    } | ({"steps": [{"name": "load", "increments": increments}]} if increments > 0 else {})


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("n", type=int, nargs="?", default=40, help="elements along each side (even, >= 4)")
    parser.add_argument("--increments", type=int, default=0,
                        help="apply the loads in one step of this many increments (default: no steps)")
    args = parser.parse_args()
    n = args.n
    if n < 4 or n % 2:
        parser.error(f"n must be an even number >= 4, got {n}")
    if args.increments < 0:
        parser.error(f"--increments must be >= 0, got {args.increments}")
    json.dump(model(n, args.increments), sys.stdout, separators=(",", ":"))
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
