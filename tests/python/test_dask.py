"""The Dask example on a LocalCluster of two worker processes: a 2 x 2 map equals the serial computation."""
import os
import pathlib
import sys

import pytest


def test_dask_breakup_map(agglo_module, source_dir, tmp_path):
    distributed = pytest.importorskip("distributed")
    import cloudpickle
    sys.path.insert(0, str(source_dir / "examples"))
    try:
        import dask_breakup_map as ex
    finally:
        sys.path.pop(0)
    cloudpickle.register_pickle_by_value(ex)  # the workers get the task functions by value
    speeds, permittivities, offsets = [0.1, 0.5], [1.0, 2.5], [0.05]  # point charges; dielectric (slower)
    text = agglo_module.Case.from_toml(ex.base_case()).set("electrostatics.target_accuracy", 1e-2).to_toml()
    serial = ex.run_serial(text, speeds, permittivities, offsets)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        files = client.run(lambda: __import__("agglo").__file__)
        parallel = ex.run_dask(client, text, speeds, permittivities, offsets)
    assert len(files) == 2 and set(files.values()) == {agglo_module.__file__}  # workers import the build under test
    assert parallel == serial
    assert [r[:2] for r in serial] == [(0.1, 1.0), (0.1, 2.5), (0.5, 1.0), (0.5, 2.5)]
    ex.write_csv(serial, tmp_path / "map.csv")
    assert (tmp_path / "map.csv").read_text().splitlines()[0] == "speed,permittivity,samples,broken,probability"
