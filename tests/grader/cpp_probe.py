"""A C++ probe program compiled for the launcher's tests (test_launcher, test_program_server).

A probe is a tiny program that prints what it sees in the jail; :func:`compiled_probe` builds it
once per module, or skips where no compiled program can run (no gcc, no g++, no bubblewrap).

Example (in a test module):
    @pytest.fixture(scope="module")
    def probe(tmp_path_factory) -> str:
        return compiled_probe(PROBE, tmp_path_factory)
"""
from __future__ import annotations

import shutil

import pytest

from grader.jail import launcher
from grader.jail.sandbox import jail_kind
from grader.judging.compile import compile_source
from grader.judging.languages import CPP


def compiled_probe(source: str, tmp_path_factory: pytest.TempPathFactory) -> str:
    """The path of ``source`` compiled as the judge compiles C++ (in its compile jail)."""
    if launcher.compiler() is None or shutil.which("g++") is None or jail_kind() != "bwrap":
        pytest.skip("needs gcc, g++ and the bubblewrap jail")
    built = compile_source(source, CPP, str(tmp_path_factory.mktemp("probe")))
    assert built.ok, built.message
    return built.binary
