#!/usr/bin/python3
"""Every route of a real `saasgaps serve` answered as schemas/openapi.json says it answers.

    /usr/bin/python3 tests/service/check_openapi.py --saasgaps build/saasgaps --repo .

Starts a server on an ephemeral loopback port (with a bearer token, one event stream, a 4 MiB body
limit), drives every operation of the document through its successes and its errors, and checks each
answer against the document: the status is one the operation lists, the content type one that
status lists, and the body valid against its schema (JSON Schema 2020-12 with the document's $refs,
python3-jsonschema); images and event streams are decoded. Fails when an operation of the document
was never exercised, and when GET /openapi.json is not the repository's file byte for byte.
"""

import argparse
import http.client
import json
import pathlib
import re
import subprocess
import sys
import tempfile
import time

# check() and failures are shared with the plot checks.
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "plot"))
from checking import check, failures  # noqa: E402
from jsonschema import Draft202012Validator, RefResolver  # noqa: E402

covered = {}  # (path template, method) -> set of statuses seen


def sample(value, keep=10):
    """The value with long arrays cut to their first and last `keep` items: the items of an array share
    one schema, and python3-jsonschema takes seconds over the 30,000 of a large result."""
    if isinstance(value, list):
        items = value if len(value) <= 2 * keep else value[:keep] + value[-keep:]
        return [sample(item, keep) for item in items]
    if isinstance(value, dict):
        return {key: sample(item, keep) for key, item in value.items()}
    return value


class Contract:
    """The OpenAPI document: finds an operation for a request and validates a response against it."""

    def __init__(self, document):
        self.document = document
        self.resolver = RefResolver.from_schema(document)
        self.routes = []
        for template in document["paths"]:
            pattern = re.sub(r"\\\{(\w+)\\\}", r"(?P<\1>[^/.]+)", re.escape(template))
            self.routes.append((template, re.compile("^" + pattern + "$")))

    def resolve(self, node):
        while "$ref" in node:
            node = self.resolver.resolve(node["$ref"])[1]
        return node

    def operation(self, method, path):
        for template, pattern in self.routes:
            if pattern.match(path):
                return template, self.document["paths"][template].get(method.lower())
        return None, None

    def validate(self, method, path, status, content_type, body):
        where = f"{method} {path} -> {status}"
        template, operation = self.operation(method, path)
        if not check(operation is not None, f"{where}: no operation in the document"):
            return
        covered.setdefault((template, method.lower()), set()).add(status)
        responses = operation["responses"]
        response = responses.get(str(status)) or responses.get("default")
        if not check(response is not None, f"{where}: status not documented (documented: {sorted(responses)})"):
            return
        response = self.resolve(response)
        content = response.get("content")
        if not content:
            check(body == b"", f"{where}: documented without a body, got {body[:80]!r}")
            return
        media = content_type.split(";")[0].strip()
        if not check(media in content, f"{where}: content type {content_type!r}, documented {sorted(content)}"):
            return
        schema = content[media].get("schema", {})
        if media == "application/json" or media.endswith("+json"):
            try:
                value = json.loads(body)
            except ValueError as e:
                check(False, f"{where}: body is not JSON: {e}")
                return
            self.check_value(where, schema, value)
        elif media == "image/png":
            check(body.startswith(b"\x89PNG\r\n\x1a\n"), f"{where}: not a PNG")
        elif media == "image/svg+xml":
            check(b"<svg" in body[:400], f"{where}: not an SVG")
        elif media == "text/event-stream":
            self.check_events(where, body.decode())
        else:
            check(len(body) > 0, f"{where}: empty {media}")

    def check_value(self, where, schema, value):
        validator = Draft202012Validator(schema, resolver=self.resolver)
        for error in validator.iter_errors(sample(value)):
            path = "/" + "/".join(str(p) for p in error.absolute_path)
            check(False, f"{where}: body at {path}: {error.message[:300]}")

    def check_events(self, where, text):
        schemas = self.document["components"]["schemas"]
        events = [block for block in text.split("\n\n") if block.strip() and not block.startswith(":")]
        check(len(events) > 0, f"{where}: no events")
        for block in events:
            fields = dict(line.split(": ", 1) for line in block.splitlines() if ": " in line)
            kind = fields.get("event")
            if not check(kind in ("state", "iteration", "thermal", "progress") and "id" in fields and "data" in fields,
                         f"{where}: malformed event {block[:120]!r}"):
                continue
            schema = schemas[{"state": "StateEvent", "iteration": "HistoryRow", "thermal": "ThermalRow",
                              "progress": "StudyProgress"}[kind]]
            self.check_value(f"{where} (event {fields['id']})", schema, json.loads(fields["data"]))


class Server:
    """`saasgaps serve` on port 0; the port is read from its first line."""

    def __init__(self, saasgaps, directory, arguments):
        self.process = subprocess.Popen([saasgaps, "serve", "--port", "0", "--db", str(directory / "jobs.db"), *arguments],
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        line = self.process.stdout.readline()
        match = re.search(r"127\.0\.0\.1:(\d+)", line)
        if not match:
            self.process.kill()
            sys.exit(f"the server did not start: {line}")
        self.port = int(match.group(1))

    def stop(self):
        self.process.terminate()
        self.process.wait(timeout=30)


class Client:
    def __init__(self, contract, port, token):
        self.contract, self.port, self.token = contract, port, token

    def request(self, method, path, body=None, headers=None, token=True, expect=None):
        """Sends one request, validates the answer against the contract, returns (status, headers, body)."""
        all_headers = dict(headers or {})
        if token:
            all_headers["Authorization"] = "Bearer " + self.token
        if isinstance(body, (dict, list)):
            body = json.dumps(body)
            all_headers.setdefault("Content-Type", "application/json")
        connection = http.client.HTTPConnection("127.0.0.1", self.port, timeout=60)
        try:
            connection.request(method, path, body=body, headers=all_headers)
        except (BrokenPipeError, ConnectionResetError):
            pass  # the server may answer (413) before it has read the whole body
        response = connection.getresponse()
        data = response.read()
        connection.close()
        bare = path.split("?")[0]
        self.contract.validate(method, bare, response.status, response.getheader("Content-Type", ""), data)
        if expect is not None:
            check(response.status == expect,
                  f"{method} {path}: expected {expect}, got {response.status}: {data[:300]!r}")
        return response.status, response, data

    def json(self, method, path, **kwargs):
        status, response, data = self.request(method, path, **kwargs)
        return json.loads(data) if data else None

    def wait_for(self, job, states, seconds=60):
        deadline = time.time() + seconds
        while time.time() < deadline:
            state = self.json("GET", f"/v1/jobs/{job}")["state"]
            if state in states:
                return state
            time.sleep(0.05)
        sys.exit(f"job {job} did not reach {states} in {seconds} s")


def multipart(parts):
    """Request arguments for a multipart/form-data body of (field, file name, bytes) parts."""
    boundary = "saasgaps-openapi-check"
    body = b""
    for field, filename, data in parts:
        body += (f"--{boundary}\r\nContent-Disposition: form-data; name=\"{field}\"; filename=\"{filename}\"\r\n"
                 f"Content-Type: application/octet-stream\r\n\r\n").encode() + data + b"\r\n"
    body += f"--{boundary}--\r\n".encode()
    return {"body": body, "headers": {"Content-Type": f"multipart/form-data; boundary={boundary}"}}


def exercise(client, repo, document_bytes, directory):
    examples = repo / "schemas" / "examples"
    problem1 = (examples / "report-problem1.json").read_bytes()

    # Public routes answer without the token; the rest do not.
    for path in ("/healthz", "/readyz", "/", "/app.js", "/app.css"):
        client.request("GET", path, token=False, expect=200)
    status, _, served = client.request("GET", "/openapi.json", token=False, expect=200)
    check(served == document_bytes, "GET /openapi.json is not schemas/openapi.json")
    client.request("GET", "/v1/jobs", token=False, expect=401)
    client.request("GET", "/metrics", expect=200)

    # Submission: accepted, replayed, conflicting key, not JSON, invalid, too large.
    first = client.json("POST", "/v1/jobs", body=problem1, headers={"Idempotency-Key": "k1",
                                                                    "Content-Type": "application/json"}, expect=202)
    job = first["id"]
    _, replay, _ = client.request("POST", "/v1/jobs", body=problem1,
                                  headers={"Idempotency-Key": "k1", "Content-Type": "application/json"}, expect=202)
    check(replay.getheader("Idempotent-Replayed") == "true", "a replayed submission lacks Idempotent-Replayed")
    problem2 = (examples / "report-problem2.json").read_bytes()
    client.request("POST", "/v1/jobs", body=problem2, headers={"Idempotency-Key": "k1",
                                                               "Content-Type": "application/json"}, expect=409)
    client.request("POST", "/v1/jobs", body="{not json", headers={"Content-Type": "application/json"}, expect=400)
    invalid = client.json("POST", "/v1/jobs", body={"schema_version": 1, "title": "x"}, expect=422)
    check(any(e["pointer"] == "" for e in invalid["errors"]), "422 without pointers")
    client.request("POST", "/v1/jobs", body=b" " * (4 * 1024 * 1024 + 1),
                   headers={"Content-Type": "application/json"}, expect=413)

    # A converged job: everything that reads it.
    client.wait_for(job, {"converged"})
    client.request("GET", f"/v1/jobs/{job}", expect=200)
    client.request("GET", "/v1/jobs?state=converged&page_size=1", expect=200)
    client.request("GET", "/v1/jobs?state=finished", expect=400)
    client.request("GET", "/v1/jobs?page_size=0", expect=400)
    rows = client.json("GET", f"/v1/jobs/{job}/iterations?after=2", expect=200)
    check([r["iteration"] for r in rows["iterations"]] == [3, 4], f"iterations after 2: {rows}")
    client.request("GET", f"/v1/jobs/{job}/iterations?after=-1", expect=400)
    client.request("GET", f"/v1/jobs/{job}/events", expect=200)
    client.request("GET", f"/v1/jobs/{job}/events", headers={"Last-Event-ID": "3"}, expect=200)
    client.request("GET", f"/v1/jobs/{job}/result", expect=200)
    _, _, model = client.request("GET", f"/v1/jobs/{job}/model", expect=200)
    check(model == problem1, "the stored model differs from the submitted one")
    client.request("GET", f"/v1/jobs/{job}/units", expect=200)
    contact = client.json("GET", f"/v1/jobs/{job}/contact", expect=200)
    check(contact == {"contact": []}, f"contact of a model without contact surfaces: {contact}")
    client.request("GET", f"/v1/jobs/{job}/result.vtu", expect=200)
    # The values at the centre of the first element, and the problems of a bad point.
    result = client.json("GET", f"/v1/jobs/{job}/result", expect=200)
    check(client.json("GET", f"/v1/jobs/{job}", expect=200)["error_estimate"] == result["error_estimate"],
          "the job's error_estimate differs from its result's")
    nodes = {n["id"]: (n["r"], n["z"]) for n in result["nodes"]}
    corners = [nodes[n] for n in result["elements"][0]["nodes"]]
    centre = (sum(c[0] for c in corners) / len(corners), sum(c[1] for c in corners) / len(corners))
    probe = client.json("GET", f"/v1/jobs/{job}/probe?at={centre[0]!r},{centre[1]!r}", expect=200)
    check(probe["element"] == result["elements"][0]["id"], f"probe at {centre}: {probe}")
    client.request("GET", f"/v1/jobs/{job}/probe?at=1e9,1e9", expect=422)
    client.request("GET", f"/v1/jobs/{job}/probe?at=x", expect=400)
    client.request("GET", f"/v1/jobs/{job}/plots/effective.png?width=300&height=200&mesh=1", expect=200)
    client.request("GET", f"/v1/jobs/{job}/plots/closure.svg?along=position", expect=200)
    client.request("GET", f"/v1/jobs/{job}/plots/convergence.svg", expect=200)
    client.request("GET", f"/v1/jobs/{job}/plots/sigma_q.png", expect=404)
    client.request("GET", f"/v1/jobs/{job}/plots/effective.png?width=1", expect=400)
    client.request("POST", f"/v1/jobs/{job}/cancel", body="", expect=409)
    client.request("POST", f"/v1/jobs/{job}/resume", body="", expect=409)
    # A result submitted as a model is named as such.
    _, _, result = client.request("GET", f"/v1/jobs/{job}/result")
    named = client.json("POST", "/v1/jobs", body=result, headers={"Content-Type": "application/json"}, expect=422)
    check(named["errors"][0]["detail"].startswith("this is a result document"), f"a result as a model: {named}")

    # A transient heat conduction run: its thermal rows, one per output time, and their events.
    heated = json.loads((examples / "quickstart-plane-strain-block.json").read_text())
    del heated["loads"]["temperatures"]
    heated["materials"][0]["density"] = 1.0
    heated["materials"][0]["table"][0].update({"k": 1.0, "c": 1.0})
    heated["thermal"] = {"type": "transient", "initial_temperature": 70.0, "time_step": 0.1, "end_time": 1.0,
                         "output_times": [0.5, 1.0], "boundary": [{"edges": [[1, 2], [2, 3]], "temperature": 500.0}]}
    thermal_job = client.json("POST", "/v1/jobs", body=heated, expect=202)["id"]
    client.wait_for(thermal_job, {"converged"})
    rows = client.json("GET", f"/v1/jobs/{thermal_job}/thermal", expect=200)
    check([(r["index"], r["time"], r["time_steps"]) for r in rows["thermal"]] == [(1, 0.5, 5), (2, 1.0, 10)],
          f"thermal rows: {rows}")
    after = client.json("GET", f"/v1/jobs/{thermal_job}/thermal?after=1", expect=200)
    check([r["index"] for r in after["thermal"]] == [2], f"thermal rows after 1: {after}")
    client.request("GET", f"/v1/jobs/{thermal_job}/thermal?after=-1", expect=400)
    _, _, stream = client.request("GET", f"/v1/jobs/{thermal_job}/events", expect=200)
    check(stream.decode().count("event: thermal\n") == 2, "the event stream lacks the two thermal events")

    # Jobs that do not exist, including an id beyond 64 bits.
    for missing in ("424242", "99999999999999999999"):
        problem = client.json("GET", f"/v1/jobs/{missing}", expect=404)
        check(missing in problem["detail"], f"404 for job {missing} does not name it: {problem['detail']}")
        for suffix in ("/iterations", "/thermal", "/events", "/result", "/model", "/units", "/contact", "/result.vtu",
                       "/plots/effective.png", "/probe?at=0,0"):
            client.request("GET", f"/v1/jobs/{missing}{suffix}", expect=404)
        client.request("POST", f"/v1/jobs/{missing}/cancel", body="", expect=404)
        client.request("POST", f"/v1/jobs/{missing}/resume", body="", expect=404)
        client.request("DELETE", f"/v1/jobs/{missing}", expect=404)

    # A long job: running, its stream slot, cancel, resume with a bad and a good body.
    block = subprocess.run([sys.executable, str(examples / "make_block_model.py"), "120"],
                           capture_output=True, check=True).stdout
    long_job = client.json("POST", "/v1/jobs", body=block, headers={"Content-Type": "application/json"}, expect=202)["id"]
    client.wait_for(long_job, {"running"})
    client.request("GET", f"/v1/jobs/{long_job}/result", expect=409)
    client.request("DELETE", f"/v1/jobs/{long_job}", expect=409)
    stream = http.client.HTTPConnection("127.0.0.1", client.port, timeout=60)
    stream.request("GET", f"/v1/jobs/{long_job}/events", headers={"Authorization": "Bearer " + client.token})
    held = stream.getresponse()
    check(held.status == 200, f"event stream: {held.status}")
    held.read1(1)  # the stream is open and counted
    client.request("GET", f"/v1/jobs/{job}/events", expect=503)
    stream.close()
    client.request("POST", f"/v1/jobs/{long_job}/cancel", body="", expect=202)
    client.wait_for(long_job, {"cancelled"})
    bad = client.json("POST", f"/v1/jobs/{long_job}/resume", body={"max_iterations": 0, "tensile_shedule": [1]}, expect=422)
    check({e["pointer"] for e in bad["errors"]} == {"/max_iterations", "/tensile_shedule"}, f"resume 422: {bad}")
    client.request("POST", f"/v1/jobs/{long_job}/resume", body="[1,", headers={"Content-Type": "application/json"},
                   expect=400)
    client.request("POST", f"/v1/jobs/{long_job}/resume", body="{}", headers={"Content-Type": "text/plain"}, expect=415)
    client.request("POST", f"/v1/jobs/{long_job}/resume", body={"max_iterations": 60, "tensile_schedule": [2, 1]}, expect=202)
    client.request("POST", f"/v1/jobs/{long_job}/cancel", body="", expect=202)
    client.wait_for(long_job, {"cancelled"})
    client.request("GET", f"/v1/jobs/{long_job}/result", expect=200)

    # A plot the result cannot show: a gap plot of a model without gaps is 409.
    beam = (examples / "report-beam-model-a.json").read_bytes()
    beam_job = client.json("POST", "/v1/jobs", body=beam, headers={"Content-Type": "application/json"}, expect=202)["id"]
    client.wait_for(beam_job, {"converged"})
    client.request("GET", f"/v1/jobs/{beam_job}/plots/effective.png?width=300&height=200", expect=200)
    client.request("GET", f"/v1/jobs/{beam_job}/plots/closure.png", expect=409)
    client.request("GET", f"/v1/jobs/{beam_job}/plots/contact_pressure.csv", expect=409)

    # The result cache (docs/studies.md): the same model again is answered by the job that solved it.
    cached = client.json("POST", "/v1/jobs", body=beam, headers={"Content-Type": "application/json"}, expect=200)
    check(cached.get("cached") is True and cached["id"] == beam_job, f"a cached answer: {cached}")
    client.request("POST", "/v1/jobs?cache=off", body=beam, headers={"Content-Type": "application/json"}, expect=202)

    # Studies: points as jobs, their progress, cancel and resume, a bad study.
    block_model = json.loads((examples / "quickstart-plane-strain-block.json").read_text())
    study = {"schema_version": 1, "title": "block over its pressure", "model": block_model,
             "parameters": [{"name": "p", "pointer": "/loads/pressures/0/normal", "values": [1000.0, 2000.0]}],
             "outputs": [{"name": "uz", "of": "nodes.u_z", "reduce": "min"}]}
    study_id = client.json("POST", "/v1/studies", body=study, expect=202)["id"]
    client.request("GET", f"/v1/studies/{study_id}/events", expect=200)  # ends once no point runs
    done = client.json("GET", f"/v1/studies/{study_id}", expect=200)
    check(done["status"] == "converged", f"a study: {done}")
    client.json("GET", "/v1/studies", expect=200)
    client.request("POST", f"/v1/studies/{study_id}/cancel", body="", expect=202)
    client.request("POST", f"/v1/studies/{study_id}/resume", body="", expect=202)
    for suffix in ("", "/events"):
        client.request("GET", f"/v1/studies/999999{suffix}", expect=404)
    for suffix in ("/cancel", "/resume"):
        client.request("POST", f"/v1/studies/999999{suffix}", body="", expect=404)
    bad = dict(study, outputs=[{"name": "x", "of": "nodes.nothing", "reduce": "max"}])
    client.json("POST", "/v1/studies", body=bad, expect=422)
    client.request("POST", "/v1/studies", body="{x", headers={"Content-Type": "application/json"}, expect=400)
    client.request("GET", "/v1/studies", token=False, expect=401)

    # A mechanism is refused before it is queued.
    free = json.loads((examples / "report-beam-model-a.json").read_text())
    free["constraints"] = [{"node": 2, "r": 0.0}]
    refused = client.json("POST", "/v1/jobs", body=free, expect=422)
    check("not restrained" in json.dumps(refused), f"a mechanism: {refused}")

    # Imports: an assembly and the mesh it names, as multipart/form-data.
    assemblies = examples / "assemblies"
    ring_fit = [("assembly", "ring-fit.assembly.json", (assemblies / "ring-fit.assembly.json").read_bytes()),
                ("mesh", "ring-fit.geo", (assemblies / "ring-fit.geo").read_bytes())]
    client.request("POST", "/v1/imports", **multipart(ring_fit), expect=200)
    client.request("POST", "/v1/imports?submit=true", **multipart(ring_fit), expect=202)
    client.request("POST", "/v1/imports", **multipart(ring_fit[1:]), expect=400)
    client.request("POST", "/v1/imports", **multipart([("assembly", "a.json", b'{"mesh": 1}')]), expect=422)

    # A study of an assembly: the study and the mesh its assembly names, as multipart/form-data.
    rings = json.loads((examples / "studies" / "press-fit-interference.study.json").read_text())
    rings["parameters"][0]["values"] = [1.0e-4, 2.0e-4]
    rings_parts = [("study", "rings.study.json", json.dumps(rings).encode()),
                   ("mesh", "press-fit-rings.geo", (examples / "studies" / "press-fit-rings.geo").read_bytes())]
    rings_id = client.json("POST", "/v1/studies", **multipart(rings_parts), expect=202)["id"]
    client.request("GET", f"/v1/studies/{rings_id}/events", expect=200)
    check(client.json("GET", f"/v1/studies/{rings_id}", expect=200)["status"] == "converged", "an assembly study")
    client.request("POST", "/v1/studies", **multipart(rings_parts[1:]), expect=400)  # no part "study"
    client.json("POST", "/v1/studies", body=rings, expect=422)  # an assembly study without its files

    client.request("DELETE", f"/v1/jobs/{job}", expect=204)
    client.request("GET", f"/v1/jobs/{job}", expect=404)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--saasgaps", required=True)
    parser.add_argument("--repo", required=True, type=pathlib.Path)
    args = parser.parse_args()
    document_bytes = (args.repo / "schemas" / "openapi.json").read_bytes()
    document = json.loads(document_bytes)
    check(document.get("openapi", "").startswith("3.1."), "not an OpenAPI 3.1 document")
    for name, schema in document["components"]["schemas"].items():
        Draft202012Validator.check_schema(schema)
    contract = Contract(document)

    with tempfile.TemporaryDirectory(prefix="saasgaps-openapi-") as tmp:
        directory = pathlib.Path(tmp)
        (directory / "token").write_text("s3cret-token\n")
        server = Server(args.saasgaps, directory, ["--token-file", str(directory / "token"), "--max-streams", "1",
                                                   "--max-body", str(4 * 1024 * 1024)])
        try:
            exercise(Client(contract, server.port, "s3cret-token"), args.repo, document_bytes, directory)
        finally:
            server.stop()

    for template, item in document["paths"].items():
        for method in item:
            if method == "parameters":
                continue
            statuses = covered.get((template, method))
            check(statuses is not None, f"{method.upper()} {template} was never exercised")
            if statuses:
                print(f"{method.upper():6} {template}: {' '.join(str(s) for s in sorted(statuses))}")
    if failures:
        sys.exit(f"{len(failures)} failures")
    print("every route answered as schemas/openapi.json says")


if __name__ == "__main__":
    main()
