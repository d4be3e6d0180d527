"""agglo.Case: TOML file, text or dict; set/get/to_toml; validation with the CLI's messages."""
import tomllib

import pytest

from agglo_cases import CASES, SQUARE, cli, cli_error


def test_dict_set_get(agglo_module):
    agglo = agglo_module
    case = agglo.Case({"name": "a b", "material": {"restitution": 0.9, "density": 2500}, "agglomerate": {"shape": "square"}})
    assert case.file == "<dict>"
    assert case.get("material.restitution") == 0.9 and case.get("material.density") == 2500
    assert case.set("material.restitution", 0.8) is case
    case.set("agglomerate.shape", "tetrahedron").set("projectile.speed", 1).set("time.early_stop", False)
    assert case.get("material.restitution") == 0.8
    assert case.get("agglomerate.shape") == "tetrahedron"
    assert case.get("projectile.speed") == 1 and isinstance(case.get("projectile.speed"), int)
    assert isinstance(case.set("projectile.speed", 1.0).get("projectile.speed"), float)
    assert case.get("time.early_stop") is False
    assert case.get("name") == "a b"
    with pytest.raises(KeyError):
        case.get("material.nothing")


def test_dict_equals_file(agglo_module):
    agglo = agglo_module
    path = CASES / "electrostatics_two_spheres.toml"
    data = tomllib.loads(path.read_text())  # includes an array of tables [[particles]]
    from_dict = tomllib.loads(agglo.Case(data).to_toml("electrostatics"))
    from_file = tomllib.loads(agglo.Case.load(path).to_toml("electrostatics"))
    assert from_dict == from_file
    case = agglo.Case(data).set("particles.1.charge", -2e-14)
    assert case.get("particles.1.charge") == -2e-14 and case.get("particles.0.charge") == 1e-14


def test_to_toml_resolves_and_copy_is_independent(agglo_module):
    agglo = agglo_module
    case = agglo.Case.load(SQUARE)
    assert "steps_per_period" not in case.to_toml()
    assert "steps_per_period" in case.to_toml("collide")  # every default filled in
    assert "steps_per_period" not in case.to_toml()       # the case itself is unchanged
    assert case.get("time.steps_per_period", "collide") == 50.0
    with pytest.raises(KeyError):
        case.get("time.steps_per_period")
    other = case.copy().set("material.restitution", 0.5)
    assert other.get("material.restitution") == 0.5 and case.get("material.restitution") == 0.98
    assert agglo.Case.from_toml("[material]\nrestitution = 0.7\n").get("material.restitution") == 0.7


def test_values_of_every_type(agglo_module):
    agglo = agglo_module
    case = agglo.Case()
    case.set("a.list", [1, 2.5, "x"]).set("a.table", {"k": True}).set("a.quote", 'say "hi"\n')
    case.set("a.real", 3.0).set("a.inf", float("inf"))
    assert case.get("a.list") == [1, 2.5, "x"] and case.get("a.table") == {"k": True}
    assert case.get("a.quote") == 'say "hi"\n'
    assert isinstance(case.get("a.real"), float) and case.get("a.inf") == float("inf")
    with pytest.raises(TypeError):
        case.set("a.b", object())


def _cli_message(tmp_path, *args):
    proc = cli("collide", SQUARE, "--out", tmp_path / "cli", *args)
    assert proc.returncode == 2, proc.stderr
    return cli_error(proc)


@pytest.mark.parametrize("key, value, cli_value", [
    ("material.restitution", 2.0, "2.0"),      # out of range: found when the command parses the case
    ("material.restitutoin", 0.8, "0.8"),      # unknown key
    ("contact.break_rule", "glue", "glue"),    # not one of the choices
])
def test_config_error_is_the_cli_message(agglo_module, tmp_path, key, value, cli_value):
    agglo = agglo_module
    case = agglo.Case.load(SQUARE).set(key, value)
    with pytest.raises(agglo.ConfigError) as err:
        agglo.collide(case)
    assert isinstance(err.value, ValueError) and isinstance(err.value, agglo.Error)
    assert str(err.value) == _cli_message(tmp_path, "--set", f"{key}={cli_value}")
    with pytest.raises(agglo.ConfigError):
        case.to_toml("collide")


def test_bad_assignment_fails_at_set(agglo_module, tmp_path):
    agglo = agglo_module
    with pytest.raises(agglo.ConfigError) as err:
        agglo.Case.load(SQUARE).set("material..restitution", 0.8)
    assert str(err.value) == _cli_message(tmp_path, "--set", "material..restitution=0.8")
    with pytest.raises(agglo.ConfigError) as err:
        agglo.Case.load(CASES / "missing.toml")
    assert "missing.toml" in str(err.value)
    with pytest.raises(agglo.ConfigError) as err:
        agglo.Case.from_toml("a = = 1", "bad.toml")
    assert str(err.value).startswith("bad.toml:1:")
