import os
import pathlib

import pytest


@pytest.fixture(scope="session")
def source_dir():
    return pathlib.Path(os.environ["FACET_SOURCE_DIR"])


@pytest.fixture(scope="session")
def tabletop(source_dir):
    return source_dir / "graphs" / "tabletop.yaml"


@pytest.fixture(scope="session")
def mosd(source_dir):
    return source_dir / "data" / "mosd"
