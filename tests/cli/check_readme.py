#!/usr/bin/python3
"""Every command of README.md runs as written.

    /usr/bin/python3 tests/cli/check_readme.py --saasgaps build/saasgaps --repo .

Reads the README's fenced blocks: ```sh blocks are commands (a backslash continues a line; a trailing
`# exit N` says the command exits N, otherwise it must exit 0), ```console blocks are transcripts
(`$ ` lines are commands, the lines after them their output: each shown line must appear in what the
command prints, a long line possibly wrapped; "..." ends what is compared). A block preceded by `<!-- readme-test: skip (why) -->`
is not run (installing packages, benchmarks).

The commands run with bash in a scratch directory that looks like a checkout after the build: build/
holds the binary under test, schemas/ is a copy of the repository's, docs/images/ exists. A server
(`saasgaps serve` on an ephemeral port, a fresh database) stands in for the one `./deploy/run.sh`
starts: 127.0.0.1:8080 in a command becomes its address. curl is run with --fail-with-body, so an
HTTP error answer fails the command. Afterwards the walk-through's result.json must show that the
cancel and the resume took effect: a converged result whose history has rows of two runs. Links in
README.md and docs/*.md must stay inside the repository and name files that exist.
"""

import argparse
import json
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import time

# check() and failures are shared with the plot checks.
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "plot"))
from checking import check, failures  # noqa: E402

SKIP = re.compile(r"<!--\s*readme-test:\s*skip\b")
EXPECTED_EXIT = re.compile(r"#\s*exit (\d+)")


def blocks(readme):
    """(language, lines, skipped, first line number) of each fenced block."""
    lines = readme.splitlines()
    found, i = [], 0
    while i < len(lines):
        fence = re.match(r"^```(\w*)\s*$", lines[i])
        if not fence:
            i += 1
            continue
        start = i
        i += 1
        body = []
        while i < len(lines) and not lines[i].startswith("```"):
            body.append(lines[i])
            i += 1
        previous = next((line for line in reversed(lines[:start]) if line.strip()), "")
        found.append((fence.group(1), body, bool(SKIP.search(previous)), start + 1))
        i += 1
    return found


def shell_commands(lines):
    """Logical command lines of a sh block: continuations joined, comment-only and blank lines dropped."""
    commands, current = [], ""
    for line in lines:
        if line.rstrip().endswith("\\"):
            current += line.rstrip()[:-1] + " "
            continue
        current += line
        if current.strip() and not current.strip().startswith("#"):
            commands.append(current.strip())
        current = ""
    return commands


def transcript(lines):
    """(command, expected output lines) of each `$ ` line of a console block."""
    steps = []
    for line in lines:
        if line.startswith("$ "):
            steps.append((line[2:], []))
        elif steps:
            steps[-1][1].append(line)
    return steps


class Workspace:
    """A scratch checkout and a server for the commands to run against."""

    def __init__(self, saasgaps, repo, directory):
        self.directory = directory
        (directory / "build").mkdir()
        (directory / "build" / "saasgaps").symlink_to(pathlib.Path(saasgaps).resolve())
        shutil.copytree(repo / "schemas", directory / "schemas")
        (directory / "docs" / "images").mkdir(parents=True)
        self.server = subprocess.Popen([saasgaps, "serve", "--port", "0", "--db", str(directory / "server.db")],
                                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        match = re.search(r"127\.0\.0\.1:(\d+)", self.server.stdout.readline())
        if not match:
            self.server.kill()
            sys.exit("the server did not start")
        self.address = f"127.0.0.1:{match.group(1)}"

    def run(self, command, timeout=180):
        """Runs one command as the README shows it; returns (exit code, output)."""
        script = ("curl() { command curl --fail-with-body \"$@\"; }\n" +
                  command.replace("127.0.0.1:8080", self.address))
        started = time.time()
        done = subprocess.run(["bash", "-c", script], cwd=self.directory, capture_output=True, text=True,
                              timeout=timeout)
        print(f"[{time.time() - started:5.1f} s] exit {done.returncode}: {command[:110]}")
        return done.returncode, done.stdout + done.stderr

    def stop(self):
        self.server.terminate()
        self.server.wait(timeout=30)


def run_readme(workspace, readme):
    ran = 0
    for language, lines, skipped, line_number in blocks(readme):
        where = f"README.md:{line_number}"
        if skipped or language not in ("sh", "console"):
            continue
        if language == "sh":
            for command in shell_commands(lines):
                expected = EXPECTED_EXIT.search(command)
                code, output = workspace.run(command)
                ran += 1
                want = int(expected.group(1)) if expected else 0
                check(code == want, f"{where}: `{command}` exited {code}, expected {want}:\n{output[-2000:]}")
        else:
            for command, shown in transcript(lines):
                code, output = workspace.run(command)
                ran += 1
                check(code == 0, f"{where}: `{command}` exited {code}:\n{output[-2000:]}")
                # The README may wrap a long line: each shown piece must be in the output, compared
                # as printed or with its whitespace collapsed.
                flat = " ".join(output.split())
                for line in shown:
                    piece = line.split("...")[0].rstrip()
                    if piece.strip():
                        check(piece in output or " ".join(piece.split()) in flat,
                              f"{where}: `{command}` did not print {piece!r}")
    return ran


def check_walk_through(directory):
    """The curl walk-through cancelled its job and resumed it: two runs made the converged result."""
    path = directory / "result.json"
    if not check(path.exists(), "the walk-through wrote no result.json"):
        return
    result = json.loads(path.read_text())
    check(result["status"] == "converged", f"walk-through result: {result['status']}: {result.get('message')}")
    attempts = sorted({row["attempt"] for row in result["history"]})
    check(attempts == [1, 2], f"walk-through history rows come from runs {attempts}, expected 1 (cancelled) and 2 (resumed)")
    schedule = [row["tensile_modulus"] for row in result["history"] if row["attempt"] == 2]
    check(schedule[:2] == [2.0, 1.0], f"the resumed run's tensile moduli begin {schedule[:2]}, expected the new schedule [2, 1]")


def check_links(repo):
    """README.md and docs/*.md link only inside the repository, to files that exist."""
    for document in [repo / "README.md", *sorted((repo / "docs").glob("*.md"))]:
        text = document.read_text()
        name = document.relative_to(repo)
        check("../shared" not in text, f"{name} refers outside the repository (../shared)")
        for target in re.findall(r"\]\(([^)#\s]+)[^)]*\)", text):
            if not re.match(r"^[a-z]+:", target):
                check((document.parent / target).exists(), f"{name} links to {target}, which does not exist")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--saasgaps", required=True)
    parser.add_argument("--repo", required=True, type=pathlib.Path)
    args = parser.parse_args()
    readme = (args.repo / "README.md").read_text()
    check_links(args.repo)
    with tempfile.TemporaryDirectory(prefix="saasgaps-readme-") as tmp:
        workspace = Workspace(args.saasgaps, args.repo, pathlib.Path(tmp))
        try:
            ran = run_readme(workspace, readme)
        finally:
            workspace.stop()
        check(ran >= 10, f"only {ran} commands found in README.md")
        check_walk_through(pathlib.Path(tmp))
    if failures:
        sys.exit(f"{len(failures)} failures")
    print(f"every one of the README's {ran} commands ran as written")


if __name__ == "__main__":
    main()
