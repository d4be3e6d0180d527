"""Issue 23 items 4 and 9: NumPy values in Case.set, nesting limits of Case(dict), one-line errors naming the
argument of a command function, the budget keywords, agglo.__version__, indices into arrays a case lacks."""
import numpy as np
import pytest

from agglo_cases import CASES, SQUARE, short


def one_line(err):
    text = str(err.value)
    assert "\n" not in text, text
    return text


def test_numpy_array_sets_a_list_of_floats(agglo_module):
    agglo = agglo_module
    case = agglo.Case.load(SQUARE).set("electrostatics.external_field", np.array([1e5, 0, 0]))
    field = case.get("electrostatics.external_field")
    assert field == [1e5, 0.0, 0.0] and all(isinstance(x, float) for x in field)
    assert "external_field = [ 100000.0, 0.0, 0.0 ]" in case.to_toml("collide")


@pytest.mark.parametrize("value", [np.array(0.75), np.float64(0.75), np.float32(0.75)])
def test_numpy_scalars_keep_their_type(agglo_module, value):
    agglo = agglo_module
    got = agglo.Case.load(SQUARE).set("material.restitution", value).get("material.restitution")
    assert isinstance(got, float) and got == 0.75  # a 0-d array was truncated to the integer 0
    n = agglo.Case.load(SQUARE).set("vcrit.scan_points", np.int64(7)).get("vcrit.scan_points")
    assert n == 7 and isinstance(n, int)
    assert agglo.Case.load(SQUARE).set("time.early_stop", np.bool_(False)).get("time.early_stop") is False


@pytest.mark.parametrize("key, value, allowed", [
    ("material.restitution", np.array([0.75]), "expected a number"),
    ("vcrit.scan_points", np.array([3.7]), "expected an integer"),
    ("vcrit.scan_points", [3.7], "expected an integer"),
    ("vcrit.scan_points", np.array([5]), "expected an integer"),
])
def test_size_one_arrays_are_not_scalars(agglo_module, key, value, allowed):
    agglo = agglo_module
    case = agglo.Case.load(SQUARE).set(key, value)
    assert isinstance(case.get(key), list)  # never truncated to a scalar
    with pytest.raises(agglo.ConfigError) as err:
        case.to_toml("vcrit")
    assert f"key '{key}' = [" in one_line(err) and allowed in one_line(err)


def test_cyclic_and_deep_dicts_raise_one_line(agglo_module):
    agglo = agglo_module
    cyclic = {"material": {}}
    cyclic["material"]["again"] = cyclic
    deep = cur = {}
    for _ in range(100000):
        cur["k"] = {}
        cur = cur["k"]
    looped = []
    looped.append(looped)
    for data, first in ((cyclic, "material"), (deep, "k")):
        with pytest.raises(agglo.ConfigError) as err:
            agglo.Case(data)
        assert one_line(err) == f"Case(dict): '{first}' is nested deeper than 64 levels " \
                                "(a dict or list that contains itself?)"
    for make in (lambda: agglo.Case({"a": {"b": looped}}), lambda: agglo.Case().set("a.b", looped)):
        with pytest.raises(agglo.ConfigError, match="nested deeper than 64 levels"):
            make()
    nested = cur = {}
    for _ in range(60):
        cur["k"] = {}
        cur = cur["k"]
    cur["x"] = 1
    assert agglo.Case(nested).get("k." * 60 + "x") == 1  # within the limit


@pytest.mark.parametrize("call, message", [
    (lambda a, c: a.collide(c, speed="fast"), "agglo.collide: speed = 'fast': give a real number"),
    (lambda a, c: a.collide(c, threads=2**40), "agglo.collide: threads = 1099511627776: give an integer from 0 to 4096"),
    (lambda a, c: a.collide(c, threads=2.0), "agglo.collide: threads = 2.0: give an integer from 0 to 4096"),
    (lambda a, c: a.collide(c, nonsense=1),
     "agglo.collide: unknown keyword argument 'nonsense' (help(agglo.collide) lists them)"),
    (lambda a, c: a.collide(c, 0.1, 2), "agglo.collide: 3 positional argument(s) given, at most 2 (case, speed); "
                                        "the others are keywords"),
    (lambda a, c: a.collide(c, 0.1, speed=0.2), "agglo.collide: speed given twice (by position and keyword)"),
    (lambda a, c: a.collide("case.toml"), "agglo.collide: case = 'case.toml': give an agglo.Case"),
    (lambda a, c: a.collide(c, out=5), "agglo.collide: out = 5: give a folder (str or os.PathLike) or None"),
    (lambda a, c: a.collide(c, progress="yes"),
     "agglo.collide: progress = 'yes': give a callable progress(fraction, sim_time) or None"),
    (lambda a, c: a.collide(c, resume=1), "agglo.collide: resume = 1: give True or False"),
    (lambda a, c: a.vcrit(c, checkpoint="often"), "agglo.vcrit: checkpoint = 'often': give a real number"),
    (lambda a, c: a.vcrit(c, max_steps=[1]), "agglo.vcrit: max_steps = [1]: give a number or a str"),
    (lambda a, c: a.acoustic(c, seeds=2.5), "agglo.acoustic: seeds = 2.5: give an integer >= 1"),
    (lambda a, c: a.sweep(c, {"projectile.speed": [0.1]}, command="collide", seeds=2.5),
     "agglo.sweep: seeds = 2.5: give an integer >= 1"),
    (lambda a, c: a.sweep(c, [0.1]), "agglo.sweep: params = [0.1]: give a dict {dotted key: list of values}"),
    (lambda a, c: a.sweep(c, {}, checkpoint=1.0),
     "agglo.sweep: unknown keyword argument 'checkpoint' (help(agglo.sweep) lists them)"),
])
def test_wrong_arguments_raise_one_line_naming_them(agglo_module, call, message):
    agglo = agglo_module
    with pytest.raises(agglo.ConfigError) as err:
        call(agglo, short(agglo))
    assert one_line(err) == message


def test_budget_keywords(agglo_module, monkeypatch, tmp_path):
    agglo = agglo_module
    monkeypatch.delenv("AGGLO_MAX_STEPS", raising=False)
    with pytest.raises(agglo.LimitError) as err:
        agglo.collide(short(agglo), max_steps=1000)
    text = one_line(err)
    assert "step budget 1e+03 steps" in text and "max_steps= or AGGLO_MAX_STEPS" in text and "--max" not in text
    with pytest.raises(agglo.LimitError, match="output budget"):
        agglo.collide(short(agglo), max_output="1K", out=tmp_path / "o")
    assert not (tmp_path / "o").exists()
    monkeypatch.setenv("AGGLO_MAX_STEPS", "1000")  # the keyword overrides the environment
    assert agglo.collide(short(agglo), max_steps="1e12").summary
    with pytest.raises(agglo.ConfigError, match="max_memory"):
        agglo.collide(short(agglo), max_memory="lots")


def test_version_at_package_level(agglo_module):
    assert agglo_module.__version__ == agglo_module._agglo.__version__ and agglo_module.__version__


def test_index_into_missing_array_is_refused_at_set(agglo_module):
    agglo = agglo_module
    case = agglo.Case.load(SQUARE)  # a shape case: no [[particles]]
    before = case.to_toml()
    with pytest.raises(agglo.ConfigError) as err:
        case.set("particles.99.radius", 1e-6)
    assert one_line(err) == ("--set 'particles.99.radius=1e-06': '99' is not a valid index (the case has no array "
                             "'particles': 0 elements)")
    assert case.to_toml() == before  # nothing changed
    two = agglo.Case.load(CASES / "electrostatics_two_spheres.toml")
    with pytest.raises(agglo.ConfigError, match=r"'99' is not a valid index \(array has 2 elements\)"):
        two.set("particles.99.radius", 1e-6)


def test_format_is_checked_without_out(agglo_module):
    """Issue 23 item 12: format= was validated only when out= was given."""
    agglo = agglo_module
    with pytest.raises(agglo.ConfigError) as err:
        agglo.collide(short(agglo), format="xml")
    assert "xml" in one_line(err)
    with pytest.raises(agglo.ConfigError, match="xml"):
        agglo.sweep(short(agglo), {"projectile.speed": [0.1]}, command="collide", format="xml")
    assert agglo.collide(short(agglo), format="netcdf").summary  # a valid one still runs without out


def test_huge_key_is_cut_in_the_error_line(agglo_module):
    """Issue 23 item 12: a 1 MB key was echoed whole in the error line; now its first 80 characters and '…'."""
    agglo = agglo_module
    case = short(agglo)
    with pytest.raises(agglo.ConfigError) as err:
        case.set("projectile." + "k" * 1_000_000, 1.0)
        agglo.collide(case)
    text = one_line(err)
    assert len(text) < 1000 and "k" * 69 + "\u2026" in text, text[:300]


def test_huge_seed_ensemble_is_refused_at_once(agglo_module):
    """Issue 23 item 10: seeds=10**9 did not answer in 60 s (every member planned before the budgets)."""
    import time
    agglo = agglo_module
    case = agglo.Case.load(CASES / "seed002_baseline.toml")
    t0 = time.monotonic()
    with pytest.raises(agglo.LimitError) as err:
        agglo.acoustic(case, seeds=10**9)
    assert "driven by --seeds" in one_line(err) and time.monotonic() - t0 < 10
