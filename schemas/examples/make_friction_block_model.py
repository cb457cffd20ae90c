#!/usr/bin/env python3
"""Writes the frictional block example: a steel block pressed onto a steel base, pushed sideways and back.

    /usr/bin/python3 schemas/examples/make_friction_block_model.py   # rewrites schemas/examples/friction-block-push.json

Plane strain, (r, z) = (x, y), thickness 1 in. The base, 3 x 1 in (5 x 2 elements), is held at its bottom. The
block, 1 x 1 in (4 x 2 elements), sits on it at x = 1 .. 2 with zero gap; the two meshes do not match across the
interface (no node of one face lies on a node of the other). Contact surfaces "block bottom" (side A) and
"base top", friction mu = 0.3. A 1000 psi pressure presses the block's top (N = 1000 lbf), and the block's top
nodes are prescribed along x: step "press" (1 increment) holds them at 0, step "push" moves them to
PUSH = 4e-4 in in 10 increments (the block sticks, then slides at mu N = 300 lbf), step "back" returns them to 0
in 10 increments (it sticks again, then slides back at -mu N: the hysteresis of Coulomb friction). The
friction's moment about the block's foot lifts its trailing edge: one point of the block's face opens.

Node ids: base 1 + i + 6 j (i = 0..5, j = 0..2), block 101 + i + 5 j (i = 0..4, j = 0..2).
Element ids: base 1.., block 101...
"""

import argparse
import json
import pathlib

HERE = pathlib.Path(__file__).resolve().parent

E, NU, ALPHA = 30.0e6, 0.3, 6.5e-6
PRESSURE, MU, PUSH = 1000.0, 0.3, 4.0e-4
BASE_NODE, BLOCK_NODE = 1, 101
BASE_ELEMENT, BLOCK_ELEMENT = 1, 101


def grid(first_node, first_element, x0, x1, y0, y1, ni, nj):
    """Nodes and counter-clockwise quads of a ni x nj grid on [x0, x1] x [y0, y1]; node (i, j) is first + i + (ni + 1) j."""
    node = lambda i, j: first_node + i + (ni + 1) * j
    nodes = [{"id": node(i, j), "r": x0 + (x1 - x0) * i / ni, "z": y0 + (y1 - y0) * j / nj}
             for j in range(nj + 1) for i in range(ni + 1)]
    elements = [{"id": first_element + i + ni * j,
                 "nodes": [node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)], "material": 1}
                for j in range(nj) for i in range(ni)]
    return nodes, elements, node


def model():
    base_nodes, base_elements, base = grid(BASE_NODE, BASE_ELEMENT, 0.0, 3.0, 0.0, 1.0, 5, 2)
    block_nodes, block_elements, block = grid(BLOCK_NODE, BLOCK_ELEMENT, 1.0, 2.0, 1.0, 2.0, 4, 2)
    top = [block(i, 2) for i in range(5)]
    return {
        "schema_version": 1,
        "title": "Frictional block: pressed onto a base, pushed sideways and back (plane strain, mu 0.3)",
        "description": (
            "A 1 x 1 in steel block (4 x 2 elements) on a 3 x 1 in steel base (5 x 2 elements) held at its bottom, "
            "touching on contact surfaces whose meshes do not match, Coulomb friction mu = 0.3. Step press: 1000 psi "
            "on the block's top (N = 1000 lbf per inch of thickness), its top held at x = 0. Step push: the top moved "
            "to x = 0.0004 in in 10 increments; the block sticks, then slides at mu N = 300 lbf, the friction's moment "
            "lifting its trailing edge. Step back: the top returned to x = 0 in 10 increments; it sticks, then slides "
            "back at -mu N. Units: in, lbf, psi. Written by schemas/examples/make_friction_block_model.py."),
        "units": {"length": "in", "force": "lbf", "stress": "psi"},
        "analysis": {"type": "plane_strain", "thickness": 1.0},
        "nodes": base_nodes + block_nodes,
        "materials": [{"id": 1, "name": "steel", "elastic": "isotropic", "table": [{"T": 0.0, "E": E, "nu": NU, "alpha": ALPHA}]}],
        "elements": base_elements + block_elements,
        "constraints": [{"node": base(i, 0), "r": 0.0, "z": 0.0} for i in range(6)],
        "loads": {"pressures": [{"nodes": [top[i + 1], top[i]], "normal": PRESSURE} for i in range(4)]},
        "contact": {
            "surfaces": [
                {"name": "block bottom", "edges": [[block(i, 0), block(i + 1, 0)] for i in range(4)]},
                {"name": "base top", "edges": [[base(i, 2), base(i + 1, 2)] for i in range(5)]},
            ],
            "pairs": [{"surfaces": ["block bottom", "base top"], "friction": MU}],
        },
        "steps": [
            {"name": "press", "increments": 1, "constraints": [{"node": n, "r": 0.0} for n in top]},
            {"name": "push", "increments": 10, "constraints": [{"node": n, "r": PUSH} for n in top]},
            {"name": "back", "increments": 10, "constraints": [{"node": n, "r": 0.0} for n in top]},
        ],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", type=pathlib.Path, default=HERE / "friction-block-push.json")
    args = parser.parse_args()
    args.output.write_text(json.dumps(model(), indent=1) + "\n")


if __name__ == "__main__":
    main()
