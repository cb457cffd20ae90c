#!/usr/bin/python3
"""The VTU export read back with meshio (python3-meshio), as ParaView users would get it.

    /usr/bin/python3 tests/plot/check_vtu.py --saasgaps build/saasgaps --examples schemas/examples

Solves report problem 3 case 1 with `saasgaps solve --vtu` and exports the result again with
`saasgaps export-vtu`, then checks: both files are identical and binary (zlib-compressed appended
data); point and cell counts equal the model's nodes and elements + gap elements; solid cells come
first, then the gaps, with is_gap and element_id to match; and values read back exactly equal the
result document's (a node's displacement and temperature, every element's sigma_r and effective
stress, every gap's closure, contact pressure and state code, the coordinates). The ASCII export
reads back to the same values and is larger; a .pvd export holds one file per iteration whose gap
closures are that iteration's history row.

The binary files are decoded here (appended_arrays), not by meshio: meshio 5.0 finds an appended
array by its offset after rewriting the offsets of those before it, so when a rewritten offset
happens to equal a later array's (it depends on how well the values compress, so on round-off) it
hands one array's values to another's name. The ASCII file, read by meshio, is the reference the
decoded binary arrays must equal.
"""

import json
import pathlib
import re
import struct
import sys
import tempfile
import zlib

import meshio
import numpy

STATE_CODES = {"open": 0, "partial": 1, "closed": 2, "overclosed": 3}
from checking import arguments, check, failures, run


def cell_array(mesh, name):
    return numpy.concatenate(mesh.cell_data[name])


NUMPY_TYPES = {"Float64": "<f8", "Float32": "<f4", "Int32": "<i4", "Int64": "<i8", "UInt8": "<u1", "UInt32": "<u4",
               "UInt64": "<u8", "Int8": "<i1"}


def appended_arrays(path):
    """Every DataArray of a zlib-compressed appended VTU file, by name: VTK's layout read directly
    (a header of UInt64 block count, block size, last block size and the compressed sizes, then the
    zlib blocks), flattened."""
    raw = path.read_bytes()
    start = raw.index(b'<AppendedData encoding="raw">')
    head = raw[:start].decode()
    data = raw[raw.index(b"_", start) + 1:]
    check('header_type="UInt64"' in head, f"{path.name}: header_type is not UInt64")
    arrays = {}
    for tag in re.findall(r"<DataArray [^>]*>", head):
        kind, name, offset = (re.search(f'{key}="([^"]*)"', tag).group(1) for key in ("type", "Name", "offset"))
        at = int(offset)
        blocks = struct.unpack_from("<Q", data, at)[0]
        sizes = struct.unpack_from(f"<{blocks}Q", data, at + 24)
        at += 24 + 8 * blocks
        decoded = b""
        for size in sizes:
            decoded += zlib.decompress(data[at:at + size])
            at += size
        arrays[name] = numpy.frombuffer(decoded, dtype=NUMPY_TYPES[kind])
    return arrays


def main():
    args = arguments(__doc__)
    model_path = args.examples / "report-problem3-case1.json"
    model = json.loads(model_path.read_text())
    with tempfile.TemporaryDirectory(prefix="saasgaps-vtu-") as tmp:
        out = pathlib.Path(tmp)
        run(args.saasgaps, "solve", str(model_path), "-q", "-o", str(out / "result.json"), "--vtu", str(out / "solve.vtu"))
        run(args.saasgaps, "export-vtu", str(out / "result.json"), "-o", str(out / "export.vtu"))
        check((out / "solve.vtu").read_bytes() == (out / "export.vtu").read_bytes(),
              "solve --vtu and export-vtu wrote different files")
        result = json.loads((out / "result.json").read_text())
        binary = (out / "export.vtu").read_bytes()
        check(b'compressor="vtkZLibDataCompressor"' in binary and b'format="appended"' in binary,
              "the default VTU is not zlib-compressed appended data")
        run(args.saasgaps, "export-vtu", str(out / "result.json"), "--format", "ascii", "-o", str(out / "ascii.vtu"))
        mesh = meshio.read(out / "ascii.vtu")
        check((out / "ascii.vtu").stat().st_size > 1.5 * len(binary), "the ASCII file is not larger than the binary one")
        decoded = appended_arrays(out / "export.vtu")
        check((decoded["Points"] == mesh.points.ravel()).all(), "ASCII and binary points differ")
        for name in list(mesh.cell_data) + list(mesh.point_data):
            values = cell_array(mesh, name) if name in mesh.cell_data else mesh.point_data[name]
            check((decoded[name] == values.ravel()).all(), f"ASCII and binary {name} differ")
        (out / "series").mkdir()
        run(args.saasgaps, "export-vtu", str(out / "result.json"), "-o", str(out / "series" / "p3.pvd"))
        pvd = (out / "series" / "p3.pvd").read_text()
        history = result["history"]
        check(pvd.count("<DataSet") == len(history), f"the .pvd lists {pvd.count('<DataSet')} files for {len(history)} iterations")
        for row in (history[0], history[len(history) // 2]):
            step = appended_arrays(out / "series" / f"p3_iter{row['iteration']:04d}.vtu")
            closures = step["gap_closure"][len(model["elements"]):]
            check(list(closures) == row["gap_closures"], f"iteration {row['iteration']}: gap closures differ from its history row")

    n_elements, n_gaps = len(model["elements"]), len(model["gaps"]["elements"])
    check(len(mesh.points) == len(model["nodes"]), f"{len(mesh.points)} points for {len(model['nodes'])} nodes")
    n_cells = sum(len(block.data) for block in mesh.cells)
    check(n_cells == n_elements + n_gaps, f"{n_cells} cells for {n_elements} elements + {n_gaps} gaps")

    # Coordinates and point data, node by node (points are in the document's node order).
    node_ids = mesh.point_data["node_id"]
    for i, node in enumerate(result["nodes"]):
        check(node_ids[i] == node["id"], f"point {i} is node {node_ids[i]}, expected {node['id']}")
        check(tuple(mesh.points[i]) == (node["r"], node["z"], 0.0), f"node {node['id']}: coordinates")
        check(tuple(mesh.point_data["displacement"][i]) == (node["u_r"], node["u_z"], 0.0),
              f"node {node['id']}: displacement {mesh.point_data['displacement'][i]} vs {node['u_r']}, {node['u_z']}")
        check(mesh.point_data["temperature"][i] == node["T"], f"node {node['id']}: temperature")
    centre = result["nodes"][0]
    print(f"node {centre['id']}: u_z = {mesh.point_data['displacement'][0][1]!r} (result {centre['u_z']!r})")

    ids, is_gap = cell_array(mesh, "element_id"), cell_array(mesh, "is_gap")
    # A plane model's VTU names the result's sigma_r in its axes: sigma_x (docs/vtu.md).
    plane = result["analysis"].startswith("plane")
    check(("sigma_r" in mesh.cell_data) != plane, "cylindrical names in a plane model's VTU, or plane ones in an axisymmetric one")
    sigma_r, effective = cell_array(mesh, "sigma_x" if plane else "sigma_r"), cell_array(mesh, "effective")
    closure, state = cell_array(mesh, "gap_closure"), cell_array(mesh, "gap_state")
    pressure = cell_array(mesh, "gap_contact_pressure")
    for i, element in enumerate(result["elements"]):
        check(ids[i] == element["id"] and is_gap[i] == 0, f"cell {i} should be element {element['id']}")
        check(sigma_r[i] == element["sigma_r"], f"element {element['id']}: sigma_r {sigma_r[i]!r} vs {element['sigma_r']!r}")
        check(effective[i] == element["effective"], f"element {element['id']}: effective")
        check(state[i] == -1, f"element {element['id']}: gap_state {state[i]} on a solid")
    for k, gap in enumerate(result["gaps"]):
        i = n_elements + k
        check(ids[i] == gap["id"] and is_gap[i] == 1, f"cell {i} should be gap {gap['id']}")
        check(closure[i] == gap["closure"], f"gap {gap['id']}: closure {closure[i]!r} vs {gap['closure']!r}")
        check(state[i] == STATE_CODES[gap["state"]], f"gap {gap['id']}: state code {state[i]} for {gap['state']}")
        check(pressure[i] == gap["contact_pressure"], f"gap {gap['id']}: contact pressure {pressure[i]!r}")
    element62 = next(i for i, e in enumerate(result["elements"]) if e["id"] == 62)
    print(f"element 62: sigma_r = {sigma_r[element62]!r}; gap 81: closure = {closure[n_elements]!r}")

    if failures:
        sys.exit(f"{len(failures)} check(s) failed")
    print("all VTU checks passed")


if __name__ == "__main__":
    main()
