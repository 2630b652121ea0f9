"""Configuration: units at the boundary, overrides, suggestions, validation, TOML round trip."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, reject, settings
from hypothesis import strategies as st

from jointwear.config import Config, config_from_dict, load_config, parse_override
from jointwear.errors import ConfigError
from jointwear.units import to_si


@pytest.mark.parametrize(
    ("text", "kind", "expected"),
    [
        ("0.2 mm", "length", 2e-4),
        ("7.45 mm", "length", 7.45e-3),
        ("20 um", "length", 2e-5),
        ("240 rpm", "angular_velocity", 8 * math.pi),
        ("120 rpm", "angular_velocity", 4 * math.pi),
        ("2 Hz", "angular_velocity", 4 * math.pi),  # two turns a second
        ("5.05e-13 m^2/N", "wear_coefficient", 5.05e-13),
        ("5.05e-13 mm^2/N", "wear_coefficient", 5.05e-19),
        ("209 GPa", "pressure", 2.09e11),
        ("500 MPa", "pressure", 5e8),
        ("200 N", "force", 200.0),
        ("0.2 kN", "force", 200.0),
        ("90 deg", "angle", math.pi / 2),
        ("2200 kg/m^3", "density", 2200.0),
        ("460 g", "mass", 0.46),
        (0.28, "dimensionless", 0.28),
        (3, "length", 3.0),
    ],
)
def test_units_accepted(text, kind, expected):
    assert to_si(text, kind) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "kind", "needle"),
    [
        ("5 kg", "length", "expected a length"),
        ("5.05e-13 m^2", "wear_coefficient", "expected a wear coefficient"),
        ("240 rpm", "length", "expected a length"),
        ("nan mm", "length", "finite"),
        ("inf", "length", "finite"),
        (float("nan"), "force", "finite"),
        ("12 furlongs/s^3", "force", "expected a force"),
        ("12 blorps", "force", "cannot read"),
        ("", "length", "key"),
        (True, "length", "boolean"),
        ([1.0], "length", "expected a number"),
    ],
)
def test_units_rejected_with_the_key(text, kind, needle):
    with pytest.raises(ConfigError) as info:
        to_si(text, kind, "key")
    message = str(info.value)
    assert message.startswith("key:")
    assert needle in message


def test_paper_config_in_si(paper_config):
    assert paper_config.mechanism.crank_speed == pytest.approx(4 * math.pi, rel=1e-15)
    assert paper_config.mechanism.crank_length == pytest.approx(0.07)
    assert paper_config.joint.pin_radius == pytest.approx(7.45e-3)
    assert paper_config.joint.clearance == pytest.approx(5e-5)
    assert paper_config.bushing_radius == pytest.approx(7.5e-3)
    assert paper_config.materials.pin.youngs_modulus == pytest.approx(2.09e11)
    assert paper_config.materials.bushing.wear_coefficient == pytest.approx(5.05e-13)
    assert paper_config.contact.model == "asymmetric-winkler"
    assert paper_config.spring_area == pytest.approx(7.5e-3 * math.pi / 180 * 20e-3)


@pytest.mark.parametrize(
    ("text", "key", "value"),
    [
        ("joint.clearance=0.2 mm", "joint.clearance", "0.2 mm"),
        ('joint.clearance="0.2 mm"', "joint.clearance", "0.2 mm"),
        ("contact.nodes=720", "contact.nodes", 720),
        ("contact.tolerance=1e-10", "contact.tolerance", 1e-10),
        ("simulation.update_contour=true", "simulation.update_contour", True),
        ("contact.model = nlcp", "contact.model", "nlcp"),
        ("mechanism.crank_speed=240 rpm", "mechanism.crank_speed", "240 rpm"),
    ],
)
def test_parse_override(text, key, value):
    assert parse_override(text) == (key, value)


@pytest.mark.parametrize("text", ["joint.clearance", "=3", ""])
def test_parse_override_rejects_malformed(text):
    with pytest.raises(ConfigError, match="section.key=VALUE"):
        parse_override(text)


def test_overrides_apply_with_units(paper_config_path):
    cfg = load_config(
        paper_config_path,
        [
            "mechanism.crank_speed=240 rpm",
            'joint.clearance="0.2 mm"',
            "contact.nodes=720",
            "contact.model=nlcp",
            "contact.nlcp_variant=mesh-independent",
        ],
    )
    assert cfg.mechanism.crank_speed == pytest.approx(8 * math.pi, rel=1e-15)
    assert cfg.joint.clearance == pytest.approx(2e-4, rel=1e-15)
    assert cfg.contact.nodes == 720
    assert cfg.contact.model == "nlcp"
    assert cfg.contact.nlcp_variant == "mesh-independent"
    # mapping overrides and Config.replace do the same
    same = load_config(paper_config_path, {"mechanism.crank_speed": "240 rpm"})
    assert same.mechanism.crank_speed == cfg.mechanism.crank_speed
    replaced = load_config(paper_config_path).replace({"joint.clearance": "0.2 mm"})
    assert replaced.joint.clearance == cfg.joint.clearance


def test_replace_takes_a_mapping_strings_or_one_string(paper_config):
    wider = 2e-4
    for overrides in (
        {"joint.clearance": "0.2 mm"},
        ["joint.clearance=0.2 mm"],
        ("joint.clearance=0.2 mm" for _ in range(1)),
        "joint.clearance=0.2 mm",
    ):
        assert paper_config.replace(overrides).joint.clearance == pytest.approx(wider, rel=1e-15)
    # one string is one override, not a sequence of one-character ones
    with pytest.raises(ConfigError, match=r"^joint\.clearance: .*'abc'"):
        paper_config.replace("joint.clearance=abc")


@pytest.mark.parametrize(
    "overrides", [5, None, b"joint.clearance=1e-4", [("joint.clearance", 1e-4)]]
)
def test_replace_refuses_other_overrides_with_a_config_error(paper_config, overrides):
    with pytest.raises(ConfigError, match="^overrides: expected") as info:
        paper_config.replace(overrides)
    assert "\n" not in str(info.value)


def test_defaults_from_the_parameter_set():
    cfg = load_config()
    assert cfg.parameter_set == "nlcp-paper"
    assert cfg.joint.pin_radius == pytest.approx(7.45e-3)
    assert cfg.contact.tolerance == 1e-12


def test_the_default_contact_model_balances_the_real_contour():
    """A joint of one's own gets Winkler's springs on the real (worn) contour, with the
    thin-layer modulus of a wall bonded in its housing; the paper's configs name the
    paper's reading (E_w = E) themselves."""
    from pathlib import Path

    contact = load_config().contact
    assert (contact.model, contact.foundation_modulus) == ("asymmetric-winkler", "constrained")
    paper = sorted((Path(__file__).resolve().parents[1] / "examples" / "paper").glob("*.toml"))
    assert len(paper) == 15
    for path in paper:
        text = tomllib.loads(path.read_text(encoding="utf-8"))["contact"]
        assert text["model"] in ("asymmetric-winkler", "nlcp"), path.name
        assert text["foundation_modulus"] == "youngs", path.name


@pytest.mark.parametrize(
    ("model", "reason"),
    [
        ("winkler", "assumes a circular bushing"),
        ("hertz", "assumes a circular bushing"),
        ("persson", "is exact for a circular bushing only"),
    ],
)
def test_a_model_that_cannot_follow_a_worn_contour_is_refused_with_contour_update(model, reason):
    from jointwear import Simulation

    frozen = load_config(overrides={"contact.model": model})
    assert frozen.contact.model == model  # without contour update: allowed
    message = (
        f"contact.model: '{model}' {reason} and cannot follow a worn contour; with "
        "simulation.update_contour = true use 'asymmetric-winkler' (the default) or 'nlcp'"
    )
    with pytest.raises(ConfigError) as refused:
        load_config(overrides={"contact.model": model, "simulation.update_contour": True})
    assert str(refused.value) == message
    with pytest.raises(ConfigError) as refused:
        frozen.replace({"simulation.update_contour": True})
    assert str(refused.value) == message
    # the model handed to a simulation, not named in its config: refused the same way
    updating = load_config(overrides={"simulation.update_contour": True})
    with pytest.raises(ConfigError) as refused:
        Simulation(updating, contact_model=model)
    assert str(refused.value) == message


def test_the_models_on_the_real_contour_follow_a_worn_one():
    from jointwear import Simulation

    for model in ("asymmetric-winkler", "nlcp"):
        overrides = {"contact.model": model, "simulation.update_contour": True}
        assert load_config(overrides=overrides).contact.model == model
    # the FE reference solves one worn contour, but is no model for a wear run
    with pytest.raises(ConfigError, match="'fem' meshes and factorises the bushing wall"):
        load_config(overrides={"contact.model": "fem", "simulation.update_contour": True})
    # a pressure law of one's own is evaluated on the real contour
    updating = load_config(overrides={"simulation.update_contour": True})
    Simulation(updating, contact_model=lambda depth: 1e11 * depth)


@pytest.mark.parametrize(
    ("overrides", "allowed"),
    [
        ({"contact.nodes": 360}, True),  # the paper's 1 degree springs on a 1 degree mesh
        ({"contact.nodes": 720}, False),
        ({"contact.nodes": 180}, False),
        ({"contact.nodes": 720, "contact.nlcp_variant": "mesh-independent"}, True),
        # a spring area of one's own, and the mesh it belongs to
        ({"contact.nodes": 720, "contact.spring_area": 7.5e-3 * math.pi / 360 * 0.02}, True),
        ({"contact.nodes": 360, "contact.spring_area": 2e-6}, False),
    ],
)
def test_nlcps_paper_form_only_on_the_mesh_its_spring_area_belongs_to(overrides, allowed):
    overrides = {
        "contact.model": "nlcp",
        "joint.clearance": "0.05 mm",
        "joint.pin_radius": "7.45 mm",
        "joint.axial_length": "20 mm",
        **overrides,
    }
    if allowed:
        assert load_config(overrides=overrides).contact.model == "nlcp"
    else:
        with pytest.raises(
            ConfigError, match=r"^contact\.nlcp_variant: 'paper' .*'mesh-independent'$"
        ):
            load_config(overrides=overrides)


@pytest.mark.parametrize(
    ("override", "needle"),
    [
        ("jiont.clearance=1e-5", "jiont: unknown key; did you mean 'joint'?"),
        ("joint.clearence=1e-5", "joint.clearence: unknown key; did you mean 'clearance'?"),
        ("mechansim.crank_length=1", "did you mean 'mechanism'?"),
        ("materials.pn.youngs_modulus=1", "did you mean 'pin'?"),
        ("materials.pin.young_modulus=1", "did you mean 'youngs_modulus'?"),
        ("contact.modle=nlcp", "did you mean 'model'?"),
        ("contact.model=nlpc", "contact.model: unknown contact model 'nlpc'; did you mean 'nlcp'?"),
        ("contact.model=winklr", "did you mean 'winkler'?"),
        ("contact.balance=equilibirum", "did you mean 'equilibrium'?"),
        ("contact.foundation_modulus=constraned", "did you mean 'constrained'?"),
    ],
)
def test_unknown_keys_and_values_suggest(paper_config_path, override, needle):
    with pytest.raises(ConfigError) as info:
        load_config(paper_config_path, [override])
    assert needle in str(info.value)
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("crank", ["0.2 m", "200 mm", "0.3 m"])
def test_crank_not_shorter_than_rod_is_rejected(paper_config_path, crank):
    with pytest.raises(ConfigError) as info:
        load_config(paper_config_path, [f'mechanism.crank_length="{crank}"'])
    message = str(info.value)
    assert message.startswith("mechanism.crank_length:")
    assert "rod_length" in message


@pytest.mark.parametrize(
    ("override", "key"),
    [
        ("joint.clearance=0", "joint.clearance"),
        ("joint.clearance=-1e-6", "joint.clearance"),
        ('joint.pin_radius="5 kg"', "joint.pin_radius"),
        ("joint.axial_length=nan", "joint.axial_length"),
        ("materials.bushing.poisson_ratio=0.5", "materials.bushing.poisson_ratio"),
        ("materials.pin.poisson_ratio=-1.0", "materials.pin.poisson_ratio"),
        ("materials.pin.youngs_modulus=0", "materials.pin.youngs_modulus"),
        ("contact.nodes=8", "contact.nodes"),
        ("contact.exponent=0", "contact.exponent"),
        ("contact.tolerance=0", "contact.tolerance"),
        ("joint.clearance=true", "joint.clearance"),
        ('contact.stiffness="2e7 N/m"', "contact.stiffness"),
        ("contact.stiffness=0", "contact.stiffness"),
        ('contact.stiffness="2e7 Pa"', "contact.stiffness"),
    ],
)
def test_invalid_values_name_their_key(paper_config_path, override, key):
    with pytest.raises(ConfigError) as info:
        load_config(paper_config_path, [override])
    assert str(info.value).startswith(key + ":")


def test_poisson_ratio_limits_are_open(paper_config_path):
    for value in (-0.99, 0.0, 0.49):
        cfg = load_config(paper_config_path, [f"materials.bushing.poisson_ratio={value}"])
        assert cfg.materials.bushing.poisson_ratio == value


def test_to_toml_round_trip(paper_config_path):
    cfg = load_config(paper_config_path, ["mechanism.crank_speed=240 rpm", "contact.nodes=720"])
    text = cfg.to_toml()
    data = tomllib.loads(text)
    again = config_from_dict(data, defaults=False)
    assert again.to_dict() == cfg.to_dict()
    assert again.to_toml() == text  # a fixed point
    assert again.mechanism.crank_speed == cfg.mechanism.crank_speed  # exact float repr
    assert again.spring_area == cfg.spring_area
    assert again.mechanism.rod_centroidal_inertia == cfg.mechanism.rod_centroidal_inertia


EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
SHARED_OVERRIDES = {
    "joint.clearance": st.floats(1e-6, 1e-3).map(lambda v: f"{v!r} m"),
    "joint.pin_radius": st.floats(2e-3, 5e-2),
    "materials.pin.poisson_ratio": st.floats(-0.99, 0.49),
    "materials.bushing.wear_coefficient": st.floats(1e-18, 1e-10),
    "contact.nodes": st.integers(16, 2000),
    "simulation.revolutions": st.integers(1, 10**9),
    "simulation.update_every": st.sampled_from([1, 7, "adaptive"]),
}
#: values past a turn are written with their unit (``"6.98 rad"``): drawn on both sides
MECHANISMS = {
    "slider-crank": (
        EXAMPLES / "paper" / "table3_winkler_120rpm.toml",
        {"mechanism.crank_speed": st.floats(1.0, 5e4).map(lambda v: f"{v!r} rpm")},
    ),
    "four-bar": (
        EXAMPLES / "four_bar.toml",
        {
            "mechanism.rocker_spring_angle": st.floats(-2000.0, 2000.0).map(lambda v: f"{v!r} deg"),
            "mechanism.clearance_joint": st.sampled_from(
                [["crank-coupler"], ["rocker-ground", "coupler-rocker"]]
            ),
        },
    ),
    "oscillating": (EXAMPLES / "oscillating_liner.toml", {}),
}


@st.composite
def configs(draw: st.DrawFn) -> Config:
    """A config from an example of each mechanism (or a load history under an arbitrary
    file name), with some of its values overridden."""
    kind = draw(st.sampled_from([*MECHANISMS, "load-history"]))
    if kind == "load-history":
        path = None
        name = draw(
            st.text(
                st.characters(blacklist_categories=("Cs",), blacklist_characters="\x00/"),
                min_size=1,
                max_size=12,
            ).filter(lambda text: text not in {".", ".."})
        )
        overrides: dict[str, object] = {"mechanism.type": kind, "mechanism.file": name}
        choices = SHARED_OVERRIDES
    else:
        path, specific = MECHANISMS[kind]
        overrides = {}
        choices = {**SHARED_OVERRIDES, **specific}
    keys = draw(st.lists(st.sampled_from(sorted(choices)), unique=True, max_size=4))
    overrides.update({key: draw(choices[key]) for key in keys})
    try:
        return load_config(path, overrides)
    except ConfigError:  # a combination the config refuses (e.g. clearance past the pin)
        reject()


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(config=configs())
def test_to_toml_reads_back_as_the_same_config(config: Config, tmp_path_factory):
    """The written config, with the header a run puts above it, loads as the same config,
    and writing that again gives the same text."""
    text = config.to_toml()
    path = tmp_path_factory.mktemp("config") / "config.toml"
    path.write_text("# fully resolved configuration, SI units\n" + text, encoding="utf-8")
    again = config_from_dict(tomllib.loads(path.read_text(encoding="utf-8")), defaults=False)
    assert again.to_dict() == config.to_dict()
    assert again.to_toml() == text
    assert load_config(path).to_dict() == config.to_dict()


def test_angles_past_a_turn_are_written_with_their_unit():
    config = load_config(EXAMPLES / "four_bar.toml", {"mechanism.rocker_spring_angle": "400 deg"})
    written = tomllib.loads(config.to_toml())["mechanism"]["rocker_spring_angle"]
    assert written == f"{math.radians(400)!r} rad"


def test_defaults_false_requires_every_section():
    with pytest.raises(ConfigError, match="missing"):
        config_from_dict({"joint": {"pin_radius": 1e-3}}, defaults=False)


def test_unknown_parameter_set():
    with pytest.raises(ConfigError, match="parameter_set"):
        config_from_dict({"parameter_set": "nlcp-papr"})


def test_missing_and_invalid_files(tmp_path):
    with pytest.raises(ConfigError, match="file not found"):
        load_config(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("joint = [")
    with pytest.raises(ConfigError, match="not valid TOML"):
        load_config(bad)


def test_nlcp_stiffness_units_follow_the_exponent(paper_config_path):
    # K has the unit N/m^n: a unit string is checked against the configured exponent
    cfg = load_config(paper_config_path, ['contact.stiffness="2e4 N/mm**1.5"'])
    assert cfg.contact.stiffness == pytest.approx(2e4 * 1e3**1.5, rel=1e-12)
    linear = load_config(paper_config_path, ["contact.exponent=1", 'contact.stiffness="3 N/mm"'])
    assert linear.contact.stiffness == pytest.approx(3e3, rel=1e-12)
    with pytest.raises(ConfigError, match=r"^contact.stiffness: .* N/m\*\*1.5"):
        load_config(paper_config_path, ['contact.stiffness="3 N/mm"'])
    # the default is eq. (2), written into the resolved config
    default = load_config(paper_config_path)
    assert default.contact.stiffness is None
    assert default.to_dict()["contact"]["stiffness"] == pytest.approx(6.708e7, rel=1e-3)
