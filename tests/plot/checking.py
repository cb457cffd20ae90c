"""What the plot checks share: recording failures, and running the saasgaps binary."""

import argparse
import pathlib
import subprocess
import sys

failures = []


def check(condition, message):
    """Records a failed check and goes on, so one run reports every failure; returns the condition."""
    if not condition:
        failures.append(message)
        print("FAIL:", message)
    return condition


def run(saasgaps, *args):
    """Runs saasgaps with args; a failure ends the check with its stderr."""
    done = subprocess.run([saasgaps, *args], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"saasgaps {' '.join(args)} failed ({done.returncode}): {done.stderr}")


def arguments(doc):
    """--saasgaps BINARY --examples DIR, as every check takes them; doc's first line describes them."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--saasgaps", required=True)
    parser.add_argument("--examples", required=True, type=pathlib.Path)
    return parser.parse_args()
