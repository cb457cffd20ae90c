#!/usr/bin/python3
"""The assembly schema (schemas/assembly.schema.json) and `saasgaps import` agree.

(a) the schema is a valid JSON Schema 2020-12 document, and every property has a description;
(b) every example assembly (schemas/examples/assemblies/*.assembly.json) validates against it, and
    `saasgaps import` turns it into a model document that model.schema.json and `saasgaps validate`
    accept;
(c) assemblies that break a rule the schema expresses are rejected by both, `saasgaps import`
    (exit 2) naming the expected JSON Pointer.

Run with Debian's python3 (python3-jsonschema 4.10):
  assembly_schema_agreement.py --schemas DIR --examples DIR --saasgaps BINARY
"""

import argparse
import copy
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

from jsonschema import Draft202012Validator

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from schema_agreement import undocumented_properties  # noqa: E402


def run(*args):
    done = subprocess.run(list(args), capture_output=True, text=True, timeout=120)
    return done.returncode, done.stdout, done.stderr


def broken(doc):
    """(name, document, pointer) for rules the schema can express."""
    def edit(change):
        d = copy.deepcopy(doc)
        change(d)
        return d
    return [
        ("no mesh", edit(lambda d: d.pop("mesh")), ""),
        ("unknown key", edit(lambda d: d.update({"meshes": "x.msh"})), "/meshes"),
        ("region without material", edit(lambda d: d["regions"][0].pop("material")), "/regions/0"),
        ("group not a string", edit(lambda d: d["constraints"][0].update({"group": 7})), "/constraints/0/group"),
        ("gap elements given", edit(lambda d: d["gaps"].update({"elements": []})), "/gaps/elements"),
        ("one face", edit(lambda d: d["gaps"]["pairs"][0].update({"faces": ["x_axis"]})), "/gaps/pairs/0/faces"),
        ("zero tolerance", edit(lambda d: d["gaps"]["pairs"][0].update({"tolerance": 0})), "/gaps/pairs/0/tolerance"),
        ("first_id of an exact pair (contact surfaces)", edit(lambda d: d["gaps"].update({"method": "exact"})),
         "/gaps/pairs/0/first_id"),
        ("adapt without target_error", edit(lambda d: d.update({"adapt": {"max_cycles": 3}})), "/adapt"),
        ("adapt target of 100 %", edit(lambda d: d.update({"adapt": {"target_error": 1.0}})), "/adapt/target_error"),
        ("adapt target of 0", edit(lambda d: d.update({"adapt": {"target_error": 0}})), "/adapt/target_error"),
        ("no adapt cycle", edit(lambda d: d.update({"adapt": {"target_error": 0.01, "max_cycles": 0}})),
         "/adapt/max_cycles"),
        ("absurd adapt cycles", edit(lambda d: d.update({"adapt": {"target_error": 0.01, "max_cycles": 10**6}})),
         "/adapt/max_cycles"),
        ("adapt max_nodes too small", edit(lambda d: d.update({"adapt": {"target_error": 0.01, "max_nodes": 10}})),
         "/adapt/max_nodes"),
        ("mesh parameter not a number", edit(lambda d: d.update({"mesh_parameters": {"d": "wide"}})),
         "/mesh_parameters/d"),
        ("temperature file without path",
         edit(lambda d: d["loads"]["temperatures"].update({"file": {"field": "T"}})), "/loads/temperatures/file"),
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--schemas", required=True, type=pathlib.Path)
    parser.add_argument("--examples", required=True, type=pathlib.Path)
    parser.add_argument("--saasgaps", required=True)
    args = parser.parse_args()
    failures = []

    schema = json.loads((args.schemas / "assembly.schema.json").read_text(encoding="utf-8"))
    Draft202012Validator.check_schema(schema)
    assembly_validator = Draft202012Validator(schema)
    model_validator = Draft202012Validator(json.loads((args.schemas / "model.schema.json").read_text(encoding="utf-8")))
    failures += [f"(a) property without a description: {p}" for p in undocumented_properties(schema)]

    examples = sorted(args.examples.glob("*.assembly.json"))
    if len(examples) < 2:
        failures.append(f"(b) expected the example assemblies in {args.examples}")
    with tempfile.TemporaryDirectory() as workdir:
        model_path = pathlib.Path(workdir) / "model.json"
        shutil.copy(args.examples / "ring-fit.geo", workdir)  # the broken cases' mesh
        for path in examples:
            errors = [e.message for e in assembly_validator.iter_errors(json.loads(path.read_text(encoding="utf-8")))]
            if errors:
                failures.append(f"(b) {path.name}: the schema rejects it: {errors[:3]}")
            code, _, err = run(args.saasgaps, "import", str(path), "-o", str(model_path))
            if code != 0:
                failures.append(f"(b) {path.name}: saasgaps import exit {code}: {err[:500]}")
                continue
            errors = [e.message for e in model_validator.iter_errors(json.loads(model_path.read_text(encoding="utf-8")))]
            if errors:
                failures.append(f"(b) {path.name}: model.schema.json rejects the imported model: {errors[:3]}")
            code, _, err = run(args.saasgaps, "validate", str(model_path))
            if code != 0:
                failures.append(f"(b) {path.name}: saasgaps validate exit {code}: {err[:500]}")

        ring = args.examples / "ring-fit.assembly.json"
        base = json.loads(ring.read_text(encoding="utf-8"))
        base["loads"]["temperatures"]["groups"] = [{"group": "inner_ring", "T": 400.0}]
        for name, doc, pointer in broken(base):
            if not list(assembly_validator.iter_errors(doc)):
                failures.append(f"(c) {name}: the schema accepts it")
            case = pathlib.Path(workdir) / "case.json"
            case.write_text(json.dumps(doc), encoding="utf-8")
            code, _, err = run(args.saasgaps, "import", str(case), "-o", str(model_path))
            prefix = (pointer or "(document)") + ": "
            if code != 2:
                failures.append(f"(c) {name}: saasgaps import exit {code} (want 2): {err[:300]}")
            elif not any(line.startswith(prefix) for line in err.splitlines()):
                failures.append(f"(c) {name}: saasgaps import did not report {pointer!r}:\n{err}")

    for f in failures:
        print(f)
    print(f"{len(examples)} example assemblies; {len(broken(base))} broken assemblies; {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
