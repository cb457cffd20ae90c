#!/usr/bin/env python3
"""Writes the MHW-like heat-shield assembly: mhw-heat-shield.geo, mhw-heat-shield-temperatures.vtu and
mhw-heat-shield.assembly.json.

    /usr/bin/python3 schemas/examples/assemblies/make_mhw_assembly.py

REPRESENTATIVE geometry and properties, not the 1976 report's (which gives no dimensions): an
axisymmetric graphite aeroshell barrel (r 2.0 .. 2.25 in, z 0 .. 4 in) closed by an end cap
(r 0 .. 2.25 in, 0.25 in thick) 0.004 in above the barrel's end, and a retainer ring (r 1.7 .. 1.995
in, z 0.5 .. 1.0 in) inside the barrel across a 0.005 in radial clearance. Gmsh x is r, y is z.

The temperature field stands in for a thermal code's output: hot outside, hotter towards the cap,
written as a VTU point field at the mesh's nodes (every block is a transfinite grid, so the nodes
are known here without meshing). The barrel and cap are an orthotropic, temperature-dependent
graphite (material axis 1 along z in the barrel, along r in the cap); the retainer an isotropic one.
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


def temperature(r, z):
    """degF: 600 on the axis at the base, up to about 2900 on the cap's outer rim."""
    return 600.0 + 1500.0 * (r / R_OUT) ** 2 + 800.0 * (z / CAP_Z1) ** 1.5


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
    }
    for name, curves in groups.items():
        out.append(f'Physical Curve("{name}") = {{{", ".join(map(str, curves))}}};')
    header = ("// MHW-like heat shield, REPRESENTATIVE geometry (not the 1976 report's, which gives no dimensions).\n"
              "// Written by make_mhw_assembly.py: every block a transfinite grid, so the faces across each gap have\n"
              "// the same node distribution. Axisymmetric section in the plane z = 0: Gmsh x is r, y is z.\n")
    return header + "\n".join(out) + "\n"


def node_positions():
    seen = {}
    for _, r0, r1, z0, z1, nr, nz in BLOCKS:
        for j in range(nz + 1):
            for i in range(nr + 1):
                r, z = r0 + (r1 - r0) * i / nr, z0 + (z1 - z0) * j / nz
                seen[(round(r, 9), round(z, 9))] = (r, z)
    return list(seen.values())


def vtu():
    nodes = node_positions()
    points = " ".join(f"{r!r} {z!r} 0" for r, z in nodes)
    values = " ".join(f"{temperature(r, z):.3f}" for r, z in nodes)
    return ('<?xml version="1.0"?>\n'
            '<!-- Stands in for a thermal code\'s output: nodal temperatures (degF) of the heat shield. -->\n'
            '<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n'
            f' <UnstructuredGrid>\n  <Piece NumberOfPoints="{len(nodes)}" NumberOfCells="0">\n'
            f'   <Points>\n    <DataArray type="Float64" NumberOfComponents="3" format="ascii">{points}</DataArray>\n'
            '   </Points>\n   <PointData Scalars="temperature">\n'
            f'    <DataArray type="Float64" Name="temperature" format="ascii">{values}</DataArray>\n'
            '   </PointData>\n   <Cells>\n'
            '    <DataArray type="Int64" Name="connectivity" format="ascii"></DataArray>\n'
            '    <DataArray type="Int64" Name="offsets" format="ascii"></DataArray>\n'
            '    <DataArray type="UInt8" Name="types" format="ascii"></DataArray>\n'
            '   </Cells>\n  </Piece>\n </UnstructuredGrid>\n</VTKFile>\n')


def graphite_row(T, stiffening, expansion):
    """Orthotropic graphite at T: axis 1 the with-grain direction, 3 the hoop."""
    return {"T": T, "E1": 1.5e6 * stiffening, "E2": 1.1e6 * stiffening, "E3": 1.5e6 * stiffening,
            "nu12": 0.10, "nu13": 0.12, "nu23": 0.10, "G12": 0.45e6 * stiffening,
            "alpha1": 0.8e-6 * expansion, "alpha2": 1.9e-6 * expansion, "alpha3": 0.8e-6 * expansion}


def assembly():
    return {
        "schema_version": 1,
        "title": "MHW-like heat shield: aeroshell barrel, end cap and retainer ring across small clearances",
        "description": (
            "REPRESENTATIVE geometry and properties, not the 1976 report's (the report gives no dimensions): an "
            f"axisymmetric graphite aeroshell barrel (r {R_BORE} to {R_OUT} in, z 0 to {Z_TOP} in) held axially at its "
            f"base, an end cap (r 0 to {R_OUT} in, {CAP_T} in thick) resting {CAP_GAP} in above the barrel's end, and "
            f"a retainer ring (r {RET_IN} to {RET_OUT} in, z {RET_Z0} to {RET_Z1} in) inside the barrel across a "
            f"{RET_GAP} in radial clearance, held axially at its base. Heated unevenly (a thermal code's nodal field, "
            "mhw-heat-shield-temperatures.vtu): about 1100 degF at the bore, up to 2900 degF at the cap's rim; "
            "stress free at 70 degF. Barrel and cap: orthotropic graphite, stiffer and more expansive with "
            "temperature (axis 1 along z in the barrel, along r in the cap); retainer: an isotropic graphite of higher expansion, which closes its clearance to the barrel. "
            "Units: in, lbf, psi, degF."),
        "units": {"length": "in", "force": "lbf", "stress": "psi", "temperature": "degF"},
        "mesh": f"{NAME}.geo",
        "analysis": {"type": "axisymmetric", "reference_temperature": 70.0},
        "materials": [
            {"id": 1, "name": "graphite, orthotropic (representative)", "elastic": "orthotropic",
             "table": [graphite_row(70.0, 1.0, 1.0), graphite_row(1500.0, 1.15, 1.6), graphite_row(3000.0, 1.3, 2.0)]},
            {"id": 2, "name": "graphite, isotropic (representative)", "elastic": "isotropic",
             "table": [{"T": 70.0, "E": 1.4e6, "nu": 0.12, "alpha": 3.0e-6},
                       {"T": 3000.0, "E": 1.8e6, "nu": 0.12, "alpha": 4.6e-6}]},
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
        "loads": {
            "pressures": [{"group": "cap_top", "normal": 15.0}],
            "temperatures": {"default": 70.0,
                             "file": {"path": f"{NAME}-temperatures.vtu", "field": "temperature"}},
        },
        "gaps": {
            "initial_modulus": 1000.0,
            "tensile_schedule": [100.0, 10.0, 1.0],
            "pairs": [
                {"faces": ["retainer_outside", "barrel_bore_at_retainer"], "first_id": 1001},
                {"faces": ["barrel_end", "cap_rim_underside"], "first_id": 2001},
            ],
        },
        "solver": {"max_iterations": 40},
        "output": {"watch_gaps": [1001, 1005, 2001, 2004]},
    }


def main():
    (HERE / f"{NAME}.geo").write_text(geo())
    (HERE / f"{NAME}-temperatures.vtu").write_text(vtu())
    (HERE / f"{NAME}.assembly.json").write_text(json.dumps(assembly(), indent=1) + "\n")
    print("wrote", NAME + ".geo,", NAME + "-temperatures.vtu,", NAME + ".assembly.json")


if __name__ == "__main__":
    main()
