#!/usr/bin/env python3
"""Writes the shrink-fit ring example: two concentric steel rings, the inner one heated into the outer.

    /usr/bin/python3 schemas/examples/make_ring_model.py   # rewrites schemas/examples/ring-shrink-fit-plane-strain.json
    /usr/bin/python3 schemas/examples/make_ring_model.py --radial 160 --hoop 1600 -o /tmp/annulus-1e6.json
                                                           # a large one for benchmarks (1,031,288 unknowns)

A quarter annulus in plane strain, (r, z) = (x, y). Inner ring a1 = 1.0 .. b1 = 1.5 in, heated by 400 degF;
outer ring a2 = 1.502 .. b2 = 2.2 in, cold; 8 radial x 24 hoop elements each. 24 gap elements bridge the
0.002 in radial gap, M radial (angle = the element's mid angle). The x axis is a line of symmetry (z = 0 there),
so is the y axis (r = 0 there).

Node ids: inner ring 1 + i + 9 j, outer ring 1001 + i + 9 j (i = 0..8 outward, j = 0..24 counter-clockwise
from the x axis). Element ids: inner 1 + i + 8 j, outer 201 + i + 8 j, gaps 401 + j.
"""

import argparse
import json
import math
import pathlib

HERE = pathlib.Path(__file__).resolve().parent

E, NU, ALPHA, DT = 30.0e6, 0.3, 6.5e-6, 400.0
A1, B1, DELTA, B2 = 1.0, 1.5, 0.002, 2.2
A2 = B1 + DELTA
RADIAL, HOOP = 8, 24
INNER_NODE, OUTER_NODE = 1, 1001
INNER_ELEMENT, OUTER_ELEMENT, GAP_ELEMENT = 1, 201, 401


def lame_contact_pressure():
    """Contact pressure p when the gap just closes (plane strain Lame solution, both rings the same steel).

    Radial displacement of a ring under sigma_r = A - B / r^2: u = (1 + nu) / E [(1 - 2 nu) A r + B / r].
    Inner ring, external pressure p: A = -p b1^2 / (b1^2 - a1^2), B = A a1^2, plus the free thermal growth
    (1 + nu) alpha dT b1 (plane strain). Outer ring, internal pressure p: A = p a2^2 / (b2^2 - a2^2),
    B = A b2^2. Contact: u_inner(b1) - u_outer(a2) = delta.
    """
    free_growth = (1.0 + NU) * ALPHA * DT * B1
    ai = -B1 * B1 / (B1 * B1 - A1 * A1)
    inner = (1.0 + NU) / E * ((1.0 - 2.0 * NU) * ai * B1 + ai * A1 * A1 / B1)
    ao = A2 * A2 / (B2 * B2 - A2 * A2)
    outer = (1.0 + NU) / E * ((1.0 - 2.0 * NU) * ao * A2 + ao * B2 * B2 / A2)
    return (DELTA - free_growth) / (inner - outer)


def node_id(first, i, j, radial=RADIAL):
    return first + i + (radial + 1) * j


def ring(first_node, first_element, r0, r1, radial=RADIAL, hoop=HOOP):
    """Nodes and elements of one ring, radial x hoop quads."""
    nodes, elements = [], []
    for j in range(hoop + 1):
        angle = 0.5 * math.pi * j / hoop
        # Exact zeros on the symmetry axes: the constraints there must hold the nodes that lie on them.
        c = 1.0 if j == 0 else 0.0 if j == hoop else math.cos(angle)
        s = 0.0 if j == 0 else 1.0 if j == hoop else math.sin(angle)
        for i in range(radial + 1):
            r = r0 + (r1 - r0) * i / radial
            nodes.append({"id": node_id(first_node, i, j, radial), "r": round(r * c, 9), "z": round(r * s, 9)})
    for j in range(hoop):
        for i in range(radial):
            # Outward, then counter-clockwise round the axis: counter-clockwise in (x, y).
            elements.append({"id": first_element + i + radial * j, "material": 1,
                             "nodes": [node_id(first_node, i, j, radial), node_id(first_node, i + 1, j, radial),
                                       node_id(first_node, i + 1, j + 1, radial),
                                       node_id(first_node, i, j + 1, radial)]})
    return nodes, elements


def model(radial=RADIAL, hoop=HOOP, ids=(INNER_NODE, OUTER_NODE, INNER_ELEMENT, OUTER_ELEMENT, GAP_ELEMENT)):
    """The document; radial, hoop and the first ids (inner node, outer node, inner element, outer
    element, gap) are parameters so that the benchmarks can scale the mesh up."""
    inner_node, outer_node, inner_element, outer_element, gap_element = ids
    inner_nodes, inner_elements = ring(inner_node, inner_element, A1, B1, radial, hoop)
    outer_nodes, outer_elements = ring(outer_node, outer_element, A2, B2, radial, hoop)
    gaps = [{"id": gap_element + j,
             "nodes": [node_id(inner_node, radial, j, radial), node_id(outer_node, 0, j, radial),
                       node_id(outer_node, 0, j + 1, radial), node_id(inner_node, radial, j + 1, radial)],
             "angle": round(90.0 * (j + 0.5) / hoop, 6)}
            for j in range(hoop)]
    constraints = []
    for first in (inner_node, outer_node):
        constraints += [{"node": node_id(first, i, 0, radial), "z": 0.0} for i in range(radial + 1)]
        constraints += [{"node": node_id(first, i, hoop, radial), "r": 0.0} for i in range(radial + 1)]
    p = lame_contact_pressure()
    description = (
        f"Shrink fit by heating, checked against Lame's thick-cylinder solution. Two concentric steel rings "
        f"(E = 30e6 psi, nu = 0.3, alpha = 6.5e-6 /degF) in plane strain, a quarter annulus with symmetry on "
        f"both axes: the inner ring (r {A1} to {B1} in) is heated by {DT:g} degF, the outer ring (r {A2} to {B2} "
        f"in) stays at the reference 0 degF, and {hoop} gap elements (M radial) span the {DELTA} in radial gap. "
        f"Free thermal growth of the inner ring's outside, (1 + nu) alpha dT b1 = "
        f"{(1 + NU) * ALPHA * DT * B1:.5f} in, exceeds the gap, so the gap closes everywhere. With "
        f"u(r) = (1 + nu)/E [(1 - 2 nu) A r + B/r] for sigma_r = A - B/r^2 in each ring (plane strain), the "
        f"contact condition u_inner(b1) - u_outer(a2) = delta gives the contact pressure p = {p:.1f} psi: every "
        f"gap's sigma_m should be close to -p (the closure within the tolerance of 100 %, which shifts p "
        f"slightly), uniformly round the ring. Units: in, lbf, psi, degF. Node ids: inner ring 1 + i + 9 j, "
        f"outer ring 1001 + i + 9 j (i outward, j counter-clockwise from the x axis); elements 1-192 inner, "
        f"201-392 outer, gaps 401-424.")
    return {
        "schema_version": 1,
        "title": "Shrink fit: heated inner ring in a cold outer ring (plane strain, Lame check)",
        "description": description,
        "analysis": {"type": "plane_strain", "thickness": 1.0, "reference_temperature": 0.0},
        "nodes": inner_nodes + outer_nodes,
        "materials": [{"id": 1, "name": "steel", "elastic": "isotropic",
                       "table": [{"T": 0.0, "E": E, "nu": NU, "alpha": ALPHA}]}],
        "elements": inner_elements + outer_elements,
        "gaps": {"initial_modulus": 100.0, "tensile_schedule": [20.0, 5.0, 1.0], "elements": gaps},
        "constraints": constraints,
        "loads": {"temperatures": {"default": 0.0,
                                   "nodal": [{"node": n["id"], "T": DT} for n in inner_nodes]}},
        "solver": {"max_iterations": 40},
        "output": {"watch_elements": [inner_element + radial - 1, outer_element],
                   "watch_gaps": [gap_element, gap_element + hoop // 2, gap_element + hoop - 1]},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--radial", type=int, default=RADIAL, help="elements through each ring's thickness")
    parser.add_argument("--hoop", type=int, default=HOOP, help="elements round the quarter (= gap elements)")
    parser.add_argument("-o", "--output", type=pathlib.Path, help="write here, compact (default: the example)")
    args = parser.parse_args()
    if args.output is None:
        path = HERE / "ring-shrink-fit-plane-strain.json"
        path.write_text(json.dumps(model(), indent=1) + "\n")
    else:
        # Ids must not collide: the outer ring and the gaps are numbered past the inner ring.
        radial, hoop = args.radial, args.hoop
        ids = (1, 1 + (radial + 1) * (hoop + 1), 1, 1 + radial * hoop, 1 + 2 * radial * hoop)
        path = args.output
        path.write_text(json.dumps(model(radial, hoop, ids), separators=(",", ":")) + "\n")
    print("wrote", path, f"(Lame contact pressure {lame_contact_pressure():.1f} psi)")


if __name__ == "__main__":
    main()
