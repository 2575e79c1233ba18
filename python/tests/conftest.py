"""Shared fixtures: the repository's configs and the `eyehand` command line binary."""

import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def repo():
    """The repository's root folder."""
    return REPO


@pytest.fixture(scope="session")
def cli():
    """Runs the `eyehand` binary ($EYEHAND_BIN, or target/debug/eyehand as `cargo test`
    leaves it); a missing binary fails the test."""
    binary = pathlib.Path(os.environ.get("EYEHAND_BIN", REPO / "target" / "debug" / "eyehand"))
    assert binary.is_file(), f"the eyehand binary {binary} is missing: build it (cargo build)"

    def call(*args):
        return subprocess.run(
            [str(binary), *map(str, args)], cwd=REPO, check=True, capture_output=True, text=True
        )

    return call
