"""The explorer's physical views use gold from the table, which yields at these loads: the
library's PlasticityWarning is expected there (the page shows it; test_app checks that)."""

import pytest


def pytest_collection_modifyitems(items):
    for item in items:
        if "tests/explorer/" in str(item.fspath).replace("\\", "/"):
            item.add_marker(pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning"))
