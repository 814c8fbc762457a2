"""The `cli` marker: tests that start the sgmp or sgmp-compare executable. CTest runs them
as python_cli_tests (label `cli`), the others as python_tests (label `unit`)."""


def pytest_configure(config):
    config.addinivalue_line("markers", "cli: starts the sgmp or sgmp-compare executable")
