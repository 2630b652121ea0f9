"""``jointwear dynamics``: the load cycle of each clearance joint over one period."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from jointwear.cli.common import (
    ConfigArg,
    JsonOpt,
    SetOpt,
    app,
    console,
    emit_json,
    err_console,
)

CsvOpt = Annotated[
    Path | None,
    typer.Option(
        "--csv",
        help="Write the per-step arrays (time, forces in the bushing frame, "
        "cumulative rotation, load, azimuth, ...) to this CSV file; headers carry the "
        "units, and the file reads back as mechanism.type = 'load-history'. With "
        "several clearance joints, one file per joint (NAME.JOINT.csv).",
        show_default=False,
    ),
]
StrictOpt = Annotated[
    bool,
    typer.Option(
        "--strict",
        help="Fail (exit status 2) instead of warning when the "
        "continuous-contact assumption fails (sets dynamics.strict = true).",
    ),
]


def _rows(summary: dict[str, Any]) -> list[tuple[str, str]]:
    rows = [
        ("load min / max", f"{summary['load_min_n']:.6g} N / {summary['load_max_n']:.6g} N"),
        ("load time mean", f"{summary['load_mean_n']:.6g} N"),
        ("load sliding-weighted mean", f"{summary['load_sliding_mean_n']:.6g} N"),
        (
            "azimuth min / max",
            f"{summary['azimuth_min_deg']:.5g}° / {summary['azimuth_max_deg']:.5g}°",
        ),
        ("azimuth range", f"{summary['azimuth_range_deg']:.5g}°"),
        ("total relative rotation", f"{summary['total_relative_rotation_rad']:.6g} rad"),
        ("period / steps", f"{summary['period_s']:.6g} s / {summary['steps']}"),
    ]
    if "crank_torque_rms_nm" in summary:
        rows.append(
            (
                "crank torque rms / max |T|",
                f"{summary['crank_torque_rms_nm']:.5g} N m / "
                f"{summary['crank_torque_max_abs_nm']:.5g} N m",
            )
        )
    if summary["dynamics_model"] == "massless-link":
        rows.append(("fixed-point iterations", str(summary["iterations"])))
    rows.append(("contact lost", "yes" if summary["contact_lost"] else "no"))
    if "force_law" in summary:  # contact-impact dynamics (a duty cycle's mean impacts: not)
        rows += [
            (
                "force law / c_e / mu",
                f"{summary['force_law']} / {summary['restitution']:.4g} / "
                f"{summary['friction_coefficient']:.4g}",
            ),
            ("impacts in the cycle", str(summary["impacts"])),
            ("free-flight fraction", f"{summary['free_flight_fraction']:.4g}"),
            ("max penetration", f"{summary['max_penetration_m'] * 1e6:.4g} µm"),
            ("peak contact force", f"{summary['peak_load_n']:.6g} N"),
            (
                "|F - F_massless| rms / max",
                f"{summary['load_difference_rms_n']:.4g} N / "
                f"{summary['load_difference_max_n']:.4g} N",
            ),
            (
                "integration (" + str(summary["integrator"]) + ")",
                f"{summary['integration_runtime_s']:.3g} s, "
                f"{summary['rhs_evaluations']} evaluations",
            ),
        ]
    return rows


@app.command()
def dynamics(
    config: ConfigArg,
    set_: SetOpt = None,
    json_: JsonOpt = False,
    csv_path: CsvOpt = None,
    strict: StrictOpt = False,
) -> None:
    """Load cycle of each clearance joint: load, its azimuth on the bushing, relative rotation."""
    from rich.table import Table

    from jointwear.workflows.dynamics import joint_load_cycles

    def show(messages: list[str]) -> None:
        # warnings go to stderr as one line each, so stdout stays a single JSON object
        for message in messages:
            err_console.print(f"warning: {message}", markup=False, highlight=False, soft_wrap=True)

    done = joint_load_cycles(
        config, overrides=set_ or [], strict=strict, csv_path=csv_path, on_warnings=show
    )
    cfg, summaries = done.config, done.summaries
    first = next(iter(summaries.values()))
    if json_:
        emit_json({**first, "joints": summaries} if len(summaries) > 1 else first)
        return
    for joint, summary in summaries.items():
        table = Table(
            title=f"dynamics: {summary['mechanism']}, joint {joint}, "
            f"{summary['dynamics_model']}, clearance {cfg.joint.clearance * 1e3:.6g} mm"
        )
        table.add_column("quantity")
        table.add_column("value", justify="right")
        for name, value in _rows(summary):
            table.add_row(name, value)
        console.print(table)
    if csv_path is not None:
        console.print(f"per-step arrays written to {csv_path}", markup=False)


#: config sections of the clearance joint itself, listed beside the mechanism types
JOINT_SECTIONS = ("joint", "pin", "lubrication")


@app.command()
def mechanisms(json_: JsonOpt = False) -> None:
    """List the mechanism types ([mechanism] type = ...), their dynamics models and keys,
    and the keys of the joint itself ([joint], with the slices along the pin; [pin];
    [lubrication])."""
    from rich.markup import escape
    from rich.table import Table

    from jointwear.config import MECHANISM_TYPES
    from jointwear.config.schema import ConfigSchema
    from jointwear.mechanism import MECHANISMS

    catalogue = {
        name: {
            "description": entry.description,
            "dynamics_models": list(entry.models),
            "required_keys": [
                k for k, f in MECHANISM_TYPES[name].model_fields.items() if f.is_required()
            ],
            "optional_keys": [
                k
                for k, f in MECHANISM_TYPES[name].model_fields.items()
                if not f.is_required() and k != "type"
            ],
        }
        for name, entry in MECHANISMS.items()
    }
    # the joint the mechanism's clearance joint is: along the pin, the pin, its oil
    sections = {
        name: list(ConfigSchema.model_fields[name].annotation.model_fields)
        for name in JOINT_SECTIONS
    }
    if json_:
        emit_json({"mechanisms": catalogue, "joint_sections": sections})
        return
    table = Table(title=escape("mechanism types ([mechanism] type = ...)"))
    for column in ("type", "description", "dynamics models", "keys (required first)"):
        table.add_column(column)
    for name, entry in catalogue.items():
        keys = ", ".join(entry["required_keys"]) + "; " + ", ".join(entry["optional_keys"])
        row = (name, entry["description"], ", ".join(entry["dynamics_models"]), keys)
        table.add_row(*(escape(cell) for cell in row))
    console.print(table)
    joint = Table(title="the joint itself (any mechanism)")
    for column in ("section", "keys"):
        joint.add_column(column)
    for name, keys in sections.items():
        joint.add_row(escape(f"[{name}]"), ", ".join(keys))
    console.print(joint)
