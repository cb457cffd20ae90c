#!/usr/bin/python3
"""The JSON Schema (schemas/model.schema.json) and the reader (`saasgaps validate`) agree.

(a) the schema is a valid JSON Schema 2020-12 document, and every property has a description;
(b) every example model validates against the schema and `saasgaps validate` accepts it;
(c) documents that break a rule the schema can express are rejected by both, and `saasgaps
    validate` names the expected JSON Pointer;
(d) documents that break a rule the schema cannot express (listed in its $comment) pass the
    schema and are rejected by `saasgaps validate` at the expected pointer: this documents where the
    schema's reach ends.

Run with Debian's python3 (python3-jsonschema 4.10):
  schema_agreement.py --schema S --examples DIR --saasgaps BINARY
"""

import argparse
import copy
import json
import pathlib
import subprocess
import sys
import tempfile

from jsonschema import Draft202012Validator


# ---------------------------------------------------------------------------------------------
# Editing documents by JSON Pointer


def tokens(pointer):
    return [t.replace("~1", "/").replace("~0", "~") for t in pointer.split("/")[1:]]


def parent_and_key(doc, pointer):
    *path, last = tokens(pointer)
    node = doc
    for t in path:
        node = node[int(t)] if isinstance(node, list) else node[t]
    return node, (int(last) if isinstance(node, list) else last)


def with_value(doc, pointer, value):
    doc = copy.deepcopy(doc)
    if pointer == "":
        return value
    parent, key = parent_and_key(doc, pointer)
    if isinstance(parent, list) and key == len(parent):
        parent.append(value)
    else:
        parent[key] = value
    return doc


def without(doc, pointer):
    doc = copy.deepcopy(doc)
    parent, key = parent_and_key(doc, pointer)
    del parent[key]
    return doc


def edits(doc, *changes):
    """Applies (pointer, value) pairs in order; value None deletes (JSON null is never needed here)."""
    for pointer, value in changes:
        doc = without(doc, pointer) if value is None else with_value(doc, pointer, value)
    return doc


# ---------------------------------------------------------------------------------------------
# The base model: the quickstart example with a row of gap elements under it, so that every section
# can be broken.


def gap_model(quickstart):
    doc = copy.deepcopy(quickstart)
    doc["units"] = {"length": "in", "force": "lbf", "stress": "psi", "temperature": "degF"}
    doc["nodes"] += [
        {"id": 10, "r": 0.0, "z": -0.01},
        {"id": 11, "r": 1.0, "z": -0.01},
        {"id": 12, "r": 2.0, "z": -0.01},
    ]
    doc["gaps"] = {
        "initial_modulus": 100.0,
        "tensile_schedule": [20.0, 5.0, 1.0],
        "extrapolation_factor": 0.5,
        "closure_tolerance": 0.05,
        "shear_ratio": 1e-6,
        "convergence_test": "report",
        "method": "classic",
        "elements": [
            {"id": 13, "nodes": [10, 11, 2, 1], "angle": 90.0},
            {"id": 14, "nodes": [11, 12, 3, 2], "angle": 90.0},
        ],
    }
    doc["constraints"] = [
        {"node": 10, "r": 0.0, "z": 0.0},
        {"node": 11, "r": 0.0, "z": 0.0},
        {"node": 12, "r": 0.0, "z": 0.0},
        {"node": 1, "r": 0.0},
        {"node": 4, "r": 0.0},
        {"node": 7, "r": 0.0},
    ]
    doc["materials"][0]["plasticity"] = {"yield_stress": 40000.0, "hardening_ratio": 0.1}
    doc["materials"][0]["density"] = 0.283
    doc["loads"]["nodal_forces"] = [{"node": 9, "fr": 10.0}]
    doc["loads"]["temperatures"]["nodal"] = [{"node": 1, "T": 300.0}]
    doc["loads"]["body_force"] = {"accel_z": -386.1}
    doc["solver"] = {"max_iterations": 20, "plastic_tolerance": 0.01}
    doc["output"] = {"watch_elements": [1, 4], "watch_gaps": [13]}
    return doc


ORTHOTROPIC_ROW = {"T": 0.0, "E1": 20e6, "E2": 10e6, "E3": 10e6, "nu12": 0.25, "nu13": 0.25, "nu23": 0.3,
                   "G12": 5e6, "alpha1": 1e-6, "alpha2": 2e-6, "alpha3": 3e-6}
AXISYMMETRIC = [("/analysis/type", "axisymmetric"), ("/analysis/thickness", None)]


def schema_expressible_cases(base):
    """(name, document, pointer saasgaps must report): the schema rejects these too."""
    m = base
    cases = [
        ("schema_version 2", edits(m, ("/schema_version", 2)), "/schema_version"),
        ("schema_version as a string", edits(m, ("/schema_version", "1")), "/schema_version"),
        ("title missing", edits(m, ("/title", None)), ""),
        ("title a number", edits(m, ("/title", 5)), "/title"),
        ("description null", with_value(m, "/description", None), "/description"),
        ("unknown top-level key", edits(m, ("/extra", 1)), "/extra"),
        ("document is an array", [m], ""),
        ("analysis type unknown", edits(m, ("/analysis/type", "plane")), "/analysis/type"),
        ("thickness 0", edits(m, ("/analysis/thickness", 0)), "/analysis/thickness"),
        ("thickness with axisymmetric", edits(m, ("/analysis/type", "axisymmetric")), "/analysis/thickness"),
        ("axisymmetric node at r < 0", edits(m, *AXISYMMETRIC, ("/nodes/6/r", -0.001)), "/nodes/6/r"),
        ("node id 0", edits(m, ("/nodes/0/id", 0)), "/nodes/0/id"),
        ("node id as a string", edits(m, ("/nodes/0/id", "1")), "/nodes/0/id"),
        ("node id above 2^31 - 1", edits(m, ("/nodes/0/id", 2147483648)), "/nodes/0/id"),
        ("node without z", edits(m, ("/nodes/0/z", None)), "/nodes/0"),
        ("node with an unknown key", edits(m, ("/nodes/0/x", 1.0)), "/nodes/0/x"),
        ("element with 5 nodes", edits(m, ("/elements/0/nodes", [1, 2, 5, 4, 3])), "/elements/0/nodes"),
        ("element with 2 nodes", edits(m, ("/elements/0/nodes", [1, 2])), "/elements/0/nodes"),
        ("element repeats a node", edits(m, ("/elements/0/nodes", [1, 2, 2, 4])), "/elements/0/nodes/2"),
        ("element without material", edits(m, ("/elements/0/material", None)), "/elements/0"),
        ("element angle a string", edits(m, ("/elements/0/angle", "0")), "/elements/0/angle"),
        ("elastic unknown", edits(m, ("/materials/0/elastic", "anisotropic")), "/materials/0/elastic"),
        ("empty table", edits(m, ("/materials/0/table", [])), "/materials/0/table"),
        ("nu = 0.5", edits(m, ("/materials/0/table/0/nu", 0.5)), "/materials/0/table/0/nu"),
        ("nu = -1", edits(m, ("/materials/0/table/0/nu", -1)), "/materials/0/table/0/nu"),
        ("E = 0", edits(m, ("/materials/0/table/0/E", 0)), "/materials/0/table/0/E"),
        ("isotropic row with E1", edits(m, ("/materials/0/table/0/E1", 1.0)), "/materials/0/table/0/E1"),
        ("orthotropic row without G12",
         edits(m, ("/materials/0/elastic", "orthotropic"), ("/materials/0/table", [ORTHOTROPIC_ROW]),
               ("/materials/0/table/0/G12", None)), "/materials/0/table/0"),
        ("orthotropic E3 = 0",
         edits(m, ("/materials/0/elastic", "orthotropic"), ("/materials/0/table", [ORTHOTROPIC_ROW]),
               ("/materials/0/table/0/E3", 0)), "/materials/0/table/0/E3"),
        ("compression row of the wrong kind", edits(m, ("/materials/0/compression_table", [ORTHOTROPIC_ROW])),
         "/materials/0/compression_table/0/E1"),
        ("density < 0", edits(m, ("/materials/0/density", -1)), "/materials/0/density"),
        ("hardening ratio 1", edits(m, ("/materials/0/plasticity/hardening_ratio", 1)),
         "/materials/0/plasticity/hardening_ratio"),
        ("yield stress 0", edits(m, ("/materials/0/plasticity/yield_stress", 0)),
         "/materials/0/plasticity/yield_stress"),
        ("empty plasticity table", edits(m, ("/materials/0/plasticity", [])), "/materials/0/plasticity"),
        ("plasticity a string", edits(m, ("/materials/0/plasticity", "bilinear")), "/materials/0/plasticity"),
        ("xfact = 1", edits(m, ("/gaps/extrapolation_factor", 1)), "/gaps/extrapolation_factor"),
        ("negative schedule value", edits(m, ("/gaps/tensile_schedule", [20.0, -1.0])), "/gaps/tensile_schedule/1"),
        ("empty schedule", edits(m, ("/gaps/tensile_schedule", [])), "/gaps/tensile_schedule"),
        ("initial modulus 0", edits(m, ("/gaps/initial_modulus", 0)), "/gaps/initial_modulus"),
        ("closure tolerance 0", edits(m, ("/gaps/closure_tolerance", 0)), "/gaps/closure_tolerance"),
        ("shear ratio 0", edits(m, ("/gaps/shear_ratio", 0)), "/gaps/shear_ratio"),
        ("convergence test unknown", edits(m, ("/gaps/convergence_test", "lenient")), "/gaps/convergence_test"),
        ("gap method unknown", edits(m, ("/gaps/method", "penalty")), "/gaps/method"),
        ("unit name empty", edits(m, ("/units", {"stress": ""})), "/units/stress"),
        ("unit name a number", edits(m, ("/units", {"length": 1})), "/units/length"),
        ("unknown unit kind", edits(m, ("/units", {"time": "s"})), "/units/time"),
        ("gap element without angle", edits(m, ("/gaps/elements/0/angle", None)), "/gaps/elements/0"),
        ("no gap elements", edits(m, ("/gaps/elements", [])), "/gaps/elements"),
        ("empty node set", edits(m, ("/sets", {"nodes": {"a": []}})), "/sets/nodes/a"),
        ("unknown kind of set", edits(m, ("/sets", {"faces": {"a": [1]}})), "/sets/faces"),
        ("constraint with a node and a set", edits(m, ("/constraints/0/set", "a")), "/constraints/0/set"),
        ("no constraints", edits(m, ("/constraints", [])), "/constraints"),
        ("constraint of neither r nor z", edits(m, ("/constraints/3", {"node": 1})), "/constraints/3"),
        ("pressure on 4 nodes", edits(m, ("/loads/pressures/0/nodes", [7, 8, 9, 10])), "/loads/pressures/0/nodes"),
        ("pressure on one node twice", edits(m, ("/loads/pressures/0/nodes", [8, 8])), "/loads/pressures/0/nodes/1"),
        ("omega with plane strain", edits(m, ("/loads/body_force/omega", 10.0)), "/loads/body_force/omega"),
        ("nodal force as a string", edits(m, ("/loads/nodal_forces/0/fr", "10")), "/loads/nodal_forces/0/fr"),
        ("nodal temperature without T", edits(m, ("/loads/temperatures/nodal/0/T", None)),
         "/loads/temperatures/nodal/0"),
        ("max_iterations 0", edits(m, ("/solver/max_iterations", 0)), "/solver/max_iterations"),
        ("max_iterations 2.5", edits(m, ("/solver/max_iterations", 2.5)), "/solver/max_iterations"),
        ("max_iterations 100001", edits(m, ("/solver/max_iterations", 100001)), "/solver/max_iterations"),
        ("plastic tolerance 0", edits(m, ("/solver/plastic_tolerance", 0)), "/solver/plastic_tolerance"),
        ("watched id as a string", edits(m, ("/output/watch_elements/0", "1")), "/output/watch_elements/0"),
        ("watched twice", edits(m, ("/output/watch_elements/1", 1)), "/output/watch_elements/1"),
        ("no steps", edits(m, ("/steps", [])), "/steps"),
        ("step without a name", edits(m, ("/steps", [{"increments": 2}])), "/steps/0"),
        ("step increments 0", edits(m, ("/steps", [{"name": "a", "increments": 0}])), "/steps/0/increments"),
        ("step loads with an unknown member", edits(m, ("/steps", [{"name": "a", "loads": {"wind": 1}}])),
         "/steps/0/loads/wind"),
        ("thermal type unknown", edits(m, ("/thermal", {"type": "radiant"})), "/thermal/type"),
        ("negative conductivity", edits(m, ("/materials/0/table/0/k", -1.0)), "/materials/0/table/0/k"),
        ("film without ambient",
         edits(m, ("/thermal", {"type": "steady", "boundary": [{"edges": [[1, 2]], "film": 1.0}]})),
         "/thermal/boundary/0"),
        ("radiation without stefan_boltzmann",
         edits(m, ("/thermal", {"type": "steady",
                                "boundary": [{"edges": [[1, 2]], "emissivity": 0.5, "ambient": 300.0}]})),
         "/thermal/boundary/0"),
    ]
    return [(name, json.dumps(doc, indent=1), pointer) for name, doc, pointer in cases]


def semantic_cases(base):
    """(name, text, pointer saasgaps must report): the schema accepts these; only the reader can tell."""
    m = base
    second_material = copy.deepcopy(m["materials"][0])
    cases = [
        ("duplicate node id", edits(m, ("/nodes/1/id", 1)), "/nodes/1/id"),
        ("duplicate material id", edits(m, ("/materials/1", second_material)), "/materials/1/id"),
        ("gap element id used by an element", edits(m, ("/gaps/elements/0/id", 1)), "/gaps/elements/0/id"),
        ("element node not defined", edits(m, ("/elements/0/nodes/0", 99)), "/elements/0/nodes/0"),
        ("element material not defined", edits(m, ("/elements/0/material", 9)), "/elements/0/material"),
        ("constraint node not defined", edits(m, ("/constraints/0/node", 99)), "/constraints/0/node"),
        ("watch_elements names a gap", edits(m, ("/output/watch_elements/0", 13)), "/output/watch_elements/0"),
        ("watch_gaps names a solid element", edits(m, ("/output/watch_gaps/0", 1)), "/output/watch_gaps/0"),
        ("clockwise element", edits(m, ("/elements/0/nodes", [4, 5, 2, 1])), "/elements/0/nodes"),
        ("bow-tie quadrilateral", edits(m, ("/elements/0/nodes", [1, 2, 4, 5])), "/elements/0/nodes"),
        ("clockwise gap element", edits(m, ("/gaps/elements/0/nodes", [1, 2, 11, 10])), "/gaps/elements/0/nodes"),
        ("table not sorted by T",
         edits(m, ("/materials/0/table/1", {"T": 0.0, "E": 29e6, "nu": 0.3, "alpha": 7e-6})), "/materials/0/table/1/T"),
        ("orthotropic compliance not positive definite",
         edits(m, ("/materials/0/elastic", "orthotropic"), ("/materials/0/table", [dict(ORTHOTROPIC_ROW, nu12=1.5)])),
         "/materials/0/table/0"),
        ("component constrained twice", edits(m, ("/constraints/6", {"node": 10, "z": 0.5})), "/constraints/6/z"),
        ("pressure on a diagonal", edits(m, ("/loads/pressures/0/nodes", [7, 5])), "/loads/pressures/0/nodes"),
        ("pressure on an interior edge", edits(m, ("/loads/pressures/0/nodes", [5, 8])), "/loads/pressures/0/nodes"),
        ("pressure on a gap element's edge", edits(m, ("/loads/pressures/0/nodes", [10, 11])),
         "/loads/pressures/0/nodes"),
        ("node with two temperatures", edits(m, ("/loads/temperatures/nodal/1", {"node": 1, "T": 5.0})),
         "/loads/temperatures/nodal/1/node"),
        ("id written 1.0", edits(m, ("/nodes/0/id", 1.0)), "/nodes/0/id"),
        ("schema_version written 1.0", edits(m, ("/schema_version", 1.0)), "/schema_version"),
        ("max_iterations written 3.0", edits(m, ("/solver/max_iterations", 3.0)), "/solver/max_iterations"),
        ("step constraint node not defined",
         edits(m, ("/steps", [{"name": "a", "constraints": [{"node": 99, "z": 0.1}]}])), "/steps/0/constraints/0/node"),
        ("step names repeated", edits(m, ("/steps", [{"name": "a"}, {"name": "a"}])), "/steps/1/name"),
        ("constraint names an unknown node set",
         edits(m, ("/sets", {"nodes": {"base": [10, 11]}}), ("/constraints/0", {"set": "pushed", "z": 0.0})),
         "/constraints/0/set"),
        ("pressure names an unknown edge set",
         edits(m, ("/loads/pressures/0", {"set": "bore", "normal": 1.0})), "/loads/pressures/0/set"),
        ("node set names an undefined node", edits(m, ("/sets", {"nodes": {"base": [10, 99]}})), "/sets/nodes/base/1"),
        ("thermal with given temperatures",
         edits(m, ("/materials/0/table/0/k", 1.0), ("/thermal", {"type": "steady", "boundary": [{"edges": [[1, 2]], "temperature": 100.0}]})), "/loads/temperatures"),
        ("thermal material without k", edits(m, ("/loads/temperatures", None), ("/thermal", {"type": "steady", "boundary": [{"edges": [[1, 2]], "temperature": 100.0}]})),
         "/materials/0/table"),
        ("radiation to a negative ambient",
         edits(m, ("/loads/temperatures", None), ("/materials/0/table/0/k", 1.0),
               ("/thermal", {"type": "steady", "boundary": [{"edges": [[1, 2]], "emissivity": 0.5, "ambient": -3.0,
                                                            "stefan_boltzmann": 1.0e-8}]})),
         "/thermal/boundary/0/ambient"),
        ("steady thermal with nothing holding the temperature",
         edits(m, ("/loads/temperatures", None), ("/materials/0/table/0/k", 1.0),
               ("/thermal", {"type": "steady", "boundary": [{"edges": [[1, 2]], "flux": 1.0}]})),
         "/thermal/boundary"),
        ("step load on an undefined node",
         edits(m, ("/steps", [{"name": "a", "loads": {"nodal_forces": [{"node": 99, "fz": 1.0}]}}])),
         "/steps/0/loads/nodal_forces/0/node"),
    ]
    texts = [(name, json.dumps(doc, indent=1), pointer) for name, doc, pointer in cases]
    # Text-level cases: Python's json reads 1e400 as inf and keeps the last of repeated keys, so
    # the schema sees a valid document.
    sentinel = edits(m, ("/nodes/1/r", 123456.789))
    texts.append(("number beyond a double (1e400)", json.dumps(sentinel).replace("123456.789", "1e400"), "/nodes/1/r"))
    repeated = edits(m, ("/nodes/0/repeated", 0.0))
    texts.append(("repeated key", json.dumps(repeated).replace('"repeated": 0.0', '"r": 0.0'), "/nodes/0/r"))
    return texts


# ---------------------------------------------------------------------------------------------


def undocumented_properties(schema, where="#"):
    """Pointers of schema properties without a description. The conditions of if/then/else are
    tests, not documentation, and are skipped."""
    missing = []
    if isinstance(schema, dict):
        for key, sub in schema.get("properties", {}).items():
            if not (isinstance(sub, dict) and "description" in sub):
                missing.append(f"{where}/properties/{key}")
        for key, sub in schema.items():
            if key != "if":
                missing += undocumented_properties(sub, f"{where}/{key}")
    elif isinstance(schema, list):
        for i, sub in enumerate(schema):
            missing += undocumented_properties(sub, f"{where}/{i}")
    return missing


class Validate:
    """Runs `saasgaps validate` on document text."""

    def __init__(self, binary, workdir):
        self.binary = binary
        self.path = pathlib.Path(workdir) / "model.json"

    def __call__(self, text):
        self.path.write_text(text, encoding="utf-8")
        return self.run(self.path)

    def run(self, path):
        done = subprocess.run([self.binary, "validate", str(path)], capture_output=True, text=True, timeout=60)
        return done.returncode, done.stdout, done.stderr


def reported(stderr, pointer):
    prefix = (pointer or "(document)") + ": "
    return any(line.startswith(prefix) for line in stderr.splitlines())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--schema", required=True, type=pathlib.Path)
    parser.add_argument("--examples", required=True, type=pathlib.Path)
    parser.add_argument("--saasgaps", required=True)
    args = parser.parse_args()

    failures = []
    checked = {"a": 0, "b": 0, "c": 0, "d": 0}

    # (a)
    schema = json.loads(args.schema.read_text(encoding="utf-8"))
    Draft202012Validator.check_schema(schema)
    validator = Draft202012Validator(schema)
    for pointer in undocumented_properties(schema):
        failures.append(f"(a) schema property without a description: {pointer}")
    checked["a"] = 1

    with tempfile.TemporaryDirectory() as workdir:
        validate = Validate(args.saasgaps, workdir)

        # (b)
        examples = sorted(args.examples.glob("*.json"))
        if not examples:
            failures.append(f"(b) no examples in {args.examples}")
        for path in examples:
            errors = [e.message for e in validator.iter_errors(json.loads(path.read_text(encoding="utf-8")))]
            if errors:
                failures.append(f"(b) {path.name}: the schema rejects it: {errors[:3]}")
            code, _, stderr = validate.run(path)
            if code != 0:
                failures.append(f"(b) {path.name}: saasgaps validate exit {code}: {stderr.strip()[:500]}")
            checked["b"] += 1

        quickstart_path = args.examples / "quickstart-plane-strain-block.json"
        base = gap_model(json.loads(quickstart_path.read_text(encoding="utf-8")))
        base_text = json.dumps(base, indent=1)
        code, _, stderr = validate(base_text)
        base_errors = [e.message for e in validator.iter_errors(base)]
        if code != 0 or base_errors:
            failures.append(f"base model with gaps is not valid: exit {code} {stderr.strip()[:500]} {base_errors[:3]}")

        # (c)
        cases = schema_expressible_cases(base)
        for name, text, pointer in cases:
            if not list(validator.iter_errors(json.loads(text))):
                failures.append(f"(c) {name}: the schema accepts it")
            code, _, stderr = validate(text)
            if code != 2:
                failures.append(f"(c) {name}: saasgaps validate exit {code} (want 2): {stderr.strip()[:300]}")
            elif not reported(stderr, pointer):
                failures.append(f"(c) {name}: saasgaps validate did not report {pointer!r}:\n{stderr}")
            checked["c"] += 1
        if len(cases) < 25:
            failures.append(f"(c) only {len(cases)} cases")

        # (d)
        for name, text, pointer in semantic_cases(base):
            errors = [e.message for e in validator.iter_errors(json.loads(text))]
            if errors:
                failures.append(f"(d) {name}: the schema rejects it ({errors[:2]}); move the case to (c)")
            code, _, stderr = validate(text)
            if code != 2:
                failures.append(f"(d) {name}: saasgaps validate exit {code} (want 2): {stderr.strip()[:300]}")
            elif not reported(stderr, pointer):
                failures.append(f"(d) {name}: saasgaps validate did not report {pointer!r}:\n{stderr}")
            checked["d"] += 1

    print(f"schema valid (2020-12); {checked['b']} examples; {checked['c']} documents both reject; "
          f"{checked['d']} documents only saasgaps rejects")
    for failure in failures:
        print("FAIL", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
