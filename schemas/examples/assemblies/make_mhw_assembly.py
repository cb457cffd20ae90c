#!/usr/bin/env python3
"""Writes the MHW-like heat-shield assembly: mhw-heat-shield.geo and mhw-heat-shield.assembly.json.

    /usr/bin/python3 schemas/examples/assemblies/make_mhw_assembly.py

REPRESENTATIVE geometry and properties, not the 1976 report's (which gives no dimensions): an
axisymmetric graphite aeroshell barrel (r 2.0 .. 2.25 in, z 0 .. 4 in) closed by an end cap
(r 0 .. 2.25 in, 0.25 in thick) 0.004 in above the barrel's end, and a retainer ring (r 1.7 .. 1.995
in, z 0.5 .. 1.0 in) inside the barrel across a 0.005 in radial clearance. Gmsh x is r, y is z.

The parts touch on contact surfaces (gaps.method "exact": the retainer's outside against the barrel's
bore, the barrel's end against the cap's rim), and the temperatures come from a steady conduction
solve on the same mesh: the retainer's bore held hot (it carries the heat source's 2000 degF), the
outer surface and the cap's top heated by a film to a 3000 degF boundary layer, the barrel's base
held at 800 degF by the structure below; heat crosses each contact pair by its conductance
(touching faces) or the gas in its gap (open faces). The barrel and cap are an orthotropic,
temperature-dependent graphite (material axis 1 along z in the barrel, along r in the cap); the
retainer an isotropic one. Conductivities in lbf/(s degF) (power in in lbf/s: 1 W/(m K) = 0.125).
"""

import json
import pathlib

HERE = pathlib.Path(__file__).resolve().parent
NAME = "mhw-heat-shield"

# Geometry, in.
R_BORE, R_OUT, Z_TOP = 2.0, 2.25, 4.0
CAP_GAP, CAP_T = 0.004, 0.25
RET_IN, RET_GAP, RET_Z0, RET_Z1 = 1.7, 0.005, 0.5, 1.0
RET_OUT = R_BORE - RET_GAP
CAP_Z0 = Z_TOP + CAP_GAP
CAP_Z1 = CAP_Z0 + CAP_T
# Steady heating: temperatures degF, film lbf/(in s degF), conductivities lbf/(s degF).
T_RETAINER_BORE, T_BASE, T_BOUNDARY_LAYER, FILM = 2000.0, 800.0, 3000.0, 2.0
K_WITH_GRAIN, K_ACROSS_GRAIN, K_RETAINER = 12.0, 6.0, 10.0
H_CONTACT, K_GAS = 50.0, 0.05
CONTACT_CONDUCTANCE = {"closed": H_CONTACT, "gas_conductivity": K_GAS}
# Elements per block edge.
N_WALL, N_LOW, N_MID, N_HIGH = 4, 4, 5, 24
N_CAP_R, N_CAP_T = 16, 3
N_RET_R = 5

# Blocks: (name, r0, r1, z0, z1, nr, nz), each a transfinite quadrilateral grid.
BLOCKS = [
    ("barrel_low", R_BORE, R_OUT, 0.0, RET_Z0, N_WALL, N_LOW),
    ("barrel_mid", R_BORE, R_OUT, RET_Z0, RET_Z1, N_WALL, N_MID),
    ("barrel_high", R_BORE, R_OUT, RET_Z1, Z_TOP, N_WALL, N_HIGH),
    ("cap_centre", 0.0, R_BORE, CAP_Z0, CAP_Z1, N_CAP_R, N_CAP_T),
    ("cap_rim", R_BORE, R_OUT, CAP_Z0, CAP_Z1, N_WALL, N_CAP_T),
    ("retainer", RET_IN, RET_OUT, RET_Z0, RET_Z1, N_RET_R, N_MID),
]


def geo():
    points, lines, out = {}, {}, []

    def point(r, z):
        key = (round(r, 9), round(z, 9))
        if key not in points:
            points[key] = len(points) + 1
            out.append(f"Point({points[key]}) = {{{r!r}, {z!r}, 0}};")
        return points[key]

    def line(a, b, n):
        key = (min(a, b), max(a, b))
        if key not in lines:
            lines[key] = (len(lines) + 1, a)
            out.append(f"Line({lines[key][0]}) = {{{a}, {b}}}; Transfinite Curve{{{lines[key][0]}}} = {n + 1};")
        tag, start = lines[key]
        return tag if start == a else -tag

    edges = {}
    for s, (name, r0, r1, z0, z1, nr, nz) in enumerate(BLOCKS, start=1):
        p = [point(r0, z0), point(r1, z0), point(r1, z1), point(r0, z1)]
        bottom, right, top, left = line(p[0], p[1], nr), line(p[1], p[2], nz), line(p[2], p[3], nr), line(p[3], p[0], nz)
        edges[name] = {"bottom": abs(bottom), "right": abs(right), "top": abs(top), "left": abs(left)}
        out.append(f"Curve Loop({s}) = {{{bottom}, {right}, {top}, {left}}}; Plane Surface({s}) = {{{s}}};")
        out.append(f"Transfinite Surface{{{s}}}; Recombine Surface{{{s}}};")
        out.append(f'Physical Surface("{name}") = {{{s}}};')
    groups = {
        "barrel_base": [edges["barrel_low"]["bottom"]],
        "axis": [edges["cap_centre"]["left"]],
        "retainer_base": [edges["retainer"]["bottom"]],
        "retainer_outside": [edges["retainer"]["right"]],
        "barrel_bore_at_retainer": [edges["barrel_mid"]["left"]],
        "barrel_end": [edges["barrel_high"]["top"]],
        "cap_rim_underside": [edges["cap_rim"]["bottom"]],
        "cap_top": [edges["cap_centre"]["top"], edges["cap_rim"]["top"]],
        "retainer_bore": [edges["retainer"]["left"]],
        "outer_surface": [edges[b]["right"] for b in ("barrel_low", "barrel_mid", "barrel_high", "cap_rim")],
    }
    for name, curves in groups.items():
        out.append(f'Physical Curve("{name}") = {{{", ".join(map(str, curves))}}};')
    header = ("// MHW-like heat shield, REPRESENTATIVE geometry (not the 1976 report's, which gives no dimensions).\n"
              "// Written by make_mhw_assembly.py: every block a transfinite grid, so the faces across each gap have\n"
              "// the same node distribution. Axisymmetric section in the plane z = 0: Gmsh x is r, y is z.\n")
    return header + "\n".join(out) + "\n"


def graphite_row(T, stiffening, expansion):
    """Orthotropic graphite at T: axis 1 the with-grain direction, 3 the hoop."""
    return {"T": T, "E1": 1.5e6 * stiffening, "E2": 1.1e6 * stiffening, "E3": 1.5e6 * stiffening,
            "nu12": 0.10, "nu13": 0.12, "nu23": 0.10, "G12": 0.45e6 * stiffening,
            "alpha1": 0.8e-6 * expansion, "alpha2": 1.9e-6 * expansion, "alpha3": 0.8e-6 * expansion,
            "k1": K_WITH_GRAIN, "k2": K_ACROSS_GRAIN, "k3": K_WITH_GRAIN}


def assembly():
    return {
        "schema_version": 1,
        "title": "MHW-like heat shield: aeroshell barrel, end cap and retainer ring across small clearances",
        "description": (
            "REPRESENTATIVE geometry and properties, not the 1976 report's (the report gives no dimensions): an "
            f"axisymmetric graphite aeroshell barrel (r {R_BORE} to {R_OUT} in, z 0 to {Z_TOP} in) held axially at its "
            f"base, an end cap (r 0 to {R_OUT} in, {CAP_T} in thick) resting {CAP_GAP} in above the barrel's end, and "
            f"a retainer ring (r {RET_IN} to {RET_OUT} in, z {RET_Z0} to {RET_Z1} in) inside the barrel across a "
            f"{RET_GAP} in radial clearance, held axially at its base; the parts touch on contact surfaces. "
            f"Temperatures from a steady conduction solve: the retainer's bore at {T_RETAINER_BORE} degF, the outer "
            f"surface and the cap's top heated by a film to {T_BOUNDARY_LAYER} degF, the barrel's base at {T_BASE} "
            "degF, heat crossing the contact pairs; stress free at 70 degF. Barrel and cap: orthotropic graphite, stiffer and more expansive with "
            "temperature (axis 1 along z in the barrel, along r in the cap); retainer: an isotropic graphite of higher expansion, which closes its clearance to the barrel. "
            "Units: in, lbf, psi, degF."),
        "units": {"length": "in", "force": "lbf", "stress": "psi", "temperature": "degF"},
        "mesh": f"{NAME}.geo",
        "analysis": {"type": "axisymmetric", "reference_temperature": 70.0},
        "materials": [
            {"id": 1, "name": "graphite, orthotropic (representative)", "elastic": "orthotropic",
             "table": [graphite_row(70.0, 1.0, 1.0), graphite_row(1500.0, 1.15, 1.6), graphite_row(3000.0, 1.3, 2.0)]},
            {"id": 2, "name": "graphite, isotropic (representative)", "elastic": "isotropic",
             "table": [{"T": 70.0, "E": 1.4e6, "nu": 0.12, "alpha": 3.0e-6, "k": K_RETAINER},
                       {"T": 3000.0, "E": 1.8e6, "nu": 0.12, "alpha": 4.6e-6, "k": K_RETAINER}]},
        ],
        "regions": [
            {"group": "barrel_low", "material": 1, "angle": 90.0},
            {"group": "barrel_mid", "material": 1, "angle": 90.0},
            {"group": "barrel_high", "material": 1, "angle": 90.0},
            {"group": "cap_centre", "material": 1, "angle": 0.0},
            {"group": "cap_rim", "material": 1, "angle": 0.0},
            {"group": "retainer", "material": 2},
        ],
        "constraints": [
            {"group": "barrel_base", "z": 0.0},
            {"group": "retainer_base", "z": 0.0},
            {"group": "axis", "r": 0.0},
        ],
        "loads": {"pressures": [{"group": "cap_top", "normal": 15.0}]},
        "gaps": {
            "method": "exact",
            "pairs": [
                {"faces": ["retainer_outside", "barrel_bore_at_retainer"], "conductance": CONTACT_CONDUCTANCE},
                {"faces": ["barrel_end", "cap_rim_underside"], "conductance": CONTACT_CONDUCTANCE},
            ],
        },
        "thermal": {
            "type": "steady",
            "boundary": [
                {"group": "retainer_bore", "temperature": T_RETAINER_BORE},
                {"group": "barrel_base", "temperature": T_BASE},
                {"group": "outer_surface", "film": FILM, "ambient": T_BOUNDARY_LAYER},
                {"group": "cap_top", "film": FILM, "ambient": T_BOUNDARY_LAYER},
            ],
        },
        "solver": {"max_iterations": 40},
    }


def main():
    (HERE / f"{NAME}.geo").write_text(geo())
    (HERE / f"{NAME}.assembly.json").write_text(json.dumps(assembly(), indent=1) + "\n")
    print("wrote", NAME + ".geo,", NAME + ".assembly.json")


if __name__ == "__main__":
    main()
