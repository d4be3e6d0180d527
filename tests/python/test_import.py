"""The module imported is the one of the build under test."""


def test_imports_build_under_test(agglo_module):
    assert agglo_module.__doc__
