"""Shared fixtures of the Python suite: run from the repository root (configs/ paths), with
build/python on PYTHONPATH and GAITOPT naming the CLI binary (tests/CMakeLists.txt sets both)."""
import os
import pathlib

import pytest

import gaitopt

ROOT = pathlib.Path(__file__).resolve().parents[2]
FIVE_LINK = str(ROOT / "configs/robots/mu2004_five_link.yaml")


@pytest.fixture(scope="session")
def robot():
    return gaitopt.Robot(FIVE_LINK)


@pytest.fixture(scope="session")
def poly_gait(robot):
    return gaitopt.design_poly(robot, str(ROOT / "configs/gaits/mu2004.yaml"))


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("GAITOPT")
    if not path:
        pytest.skip("GAITOPT (the CLI binary) not set")
    return path
