"""pytest set-up: the tests import the agglo module of the build under test (AGGLO_BUILD_DIR)."""
import os
import pathlib

import pytest

BUILD = pathlib.Path(os.environ.get("AGGLO_BUILD_DIR", pathlib.Path(__file__).resolve().parents[2] / "build"))
SOURCE = pathlib.Path(os.environ.get("AGGLO_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def agglo_module():
    import agglo
    assert pathlib.Path(agglo.__file__).resolve().is_relative_to((BUILD / "python").resolve()), agglo.__file__
    return agglo


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE
