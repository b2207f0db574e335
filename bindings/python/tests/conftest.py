"""Shared fixtures: the C++ reference (the `foresight` CLI, when CTest passes FORESIGHT_CLI)."""

import json
import os
import subprocess

import pytest


@pytest.fixture
def cli_predict():
    """Runs `foresight predict -` on a scenario (a dict) and returns its predictions by id.

    The CLI is the C++ library's own front end: comparing with it checks the binding against the
    library, not against a copy of a formula. It computes positions in double (it links the
    library's double build); the module's default build has float positions, hence the
    tolerances of the comparisons.
    """
    path = os.environ.get("FORESIGHT_CLI")
    if not path:
        pytest.skip("FORESIGHT_CLI (the foresight command-line tool) not given")

    def run(scenario):
        done = subprocess.run([path, "predict", "-"], input=json.dumps(scenario), capture_output=True, text=True)
        assert done.returncode == 0, "foresight predict failed: " + done.stderr
        return {p["id"]: p for p in json.loads(done.stdout)["predictions"]}

    return run
