#!/usr/bin/env python3
"""Writes NAFEMS benchmark LE1 (the elliptic membrane) as a model document.

    /usr/bin/python3 schemas/examples/make_le1_model.py --n 8 --type quad8 -o /tmp/le1-quad8-8.json

A quarter of an elliptic membrane in plane stress, (r, z) = (x, y), thickness 0.1 mm, E = 210000 MPa,
nu = 0.3: between the ellipses (x/2)^2 + y^2 = 1 and (x/3.25)^2 + (y/2.75)^2 = 1, a uniform outward
pressure of 10 MPa on the outer edge, y = 0 held in y and x = 0 held in x. The target is sigma_yy =
92.7 MPa at D = (2, 0) (NAFEMS, "The Standard NAFEMS Benchmarks", 1990).

The mesh is mapped: n x n elements between lines of the same ellipse parameter theta (uniform in
theta, straight from the inner to the outer ellipse) and the blends (1 - s) inner + s outer (uniform
in s). Every node of a quadratic element lies on the map, so the mid-side nodes of the inner and outer
edges lie on the true ellipses. D is node 1.
"""

import argparse
import json
import math
import sys

E, NU, THICKNESS, PRESSURE = 210000.0, 0.3, 0.1, 10.0
TARGET_SIGMA_YY_AT_D = 92.7


def point(s, t):
    """The map from the unit square: s from the inner to the outer ellipse, t from y = 0 to x = 0."""
    theta = 0.5 * math.pi * t
    inner = (2.0 * math.cos(theta), 1.0 * math.sin(theta))
    outer = (3.25 * math.cos(theta), 2.75 * math.sin(theta))
    return ((1.0 - s) * inner[0] + s * outer[0], (1.0 - s) * inner[1] + s * outer[1])


def model(n, family):
    quadratic = family in ("quad8", "quad9")
    m = 2 * n if quadratic else n  # lattice intervals per side
    ids = {}
    nodes = []
    for j in range(m + 1):
        for i in range(m + 1):
            if family == "quad8" and i % 2 == 1 and j % 2 == 1:
                continue  # quad8 has no centre node
            ids[(i, j)] = len(nodes) + 1
            x, y = point(i / m, j / m)
            # Exact zeros on the axes, so the constraints and D sit on them.
            nodes.append({"id": ids[(i, j)], "r": 0.0 if j == m else x, "z": 0.0 if j == 0 else y})
    step = 2 if quadratic else 1
    elements, pressures = [], []
    for j in range(n):
        for i in range(n):
            I, J = step * i, step * j
            corners = [(I, J), (I + step, J), (I + step, J + step), (I, J + step)]
            lattice = corners
            if quadratic:
                lattice = corners + [(I + 1, J), (I + 2, J + 1), (I + 1, J + 2), (I, J + 1)]
                if family == "quad9":
                    lattice.append((I + 1, J + 1))
            element = {"id": len(elements) + 1, "nodes": [ids[p] for p in lattice], "material": 1}
            if family in ("saas", "quad4i"):
                element["type"] = family
            elements.append(element)
            if i == n - 1:
                # The outer edge, from its corner at (I + step, J) to (I + step, J + step): pulled outward.
                pressures.append({"nodes": [ids[corners[1]], ids[corners[2]]], "normal": -PRESSURE})
    constraints = [{"node": ids[(i, 0)], "z": 0.0} for i in range(m + 1)]
    constraints += [{"node": ids[(i, m)], "r": 0.0} for i in range(m + 1)]
    return {
        "schema_version": 1,
        "title": f"NAFEMS LE1 elliptic membrane, {n} x {n} {family}",
        "units": {"length": "mm", "force": "N", "stress": "MPa", "temperature": "degC"},
        "analysis": {"type": "plane_stress", "thickness": THICKNESS},
        "nodes": nodes,
        "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 20.0, "E": E, "nu": NU, "alpha": 0.0}]}],
        "elements": elements,
        "constraints": constraints,
        "loads": {"pressures": pressures},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=8, help="elements along each side (default 8)")
    parser.add_argument("--type", default="quad8", choices=["saas", "quad4i", "quad8", "quad9"])
    parser.add_argument("-o", "--output", default="-", help="output file (default: standard output)")
    args = parser.parse_args()
    if args.n < 1:
        parser.error("--n must be at least 1")
    text = json.dumps(model(args.n, args.type), indent=1) + "\n"
    if args.output == "-":
        sys.stdout.write(text)
    else:
        with open(args.output, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
