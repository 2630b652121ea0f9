"""``jointwear dynamics``: joint load over one crank revolution."""

from __future__ import annotations

import csv
import math
import warnings
from pathlib import Path
from typing import Annotated

import typer
from rich.table import Table

from jointwear.cli.common import (
    ConfigArg,
    JsonOpt,
    SetOpt,
    app,
    console,
    emit_json,
    err_console,
    load,
)
from jointwear.io import atomic_write
from jointwear.mechanism import JointLoad, joint_load, solve_contact_impact

CsvOpt = Annotated[
    Path | None,
    typer.Option("--csv", help="Write the per-step arrays (crank angle, load, azimuth, ...) "
                 "to this CSV file; headers carry the units.", show_default=False),
]
StrictOpt = Annotated[
    bool,
    typer.Option("--strict", help="Fail (exit status 2) instead of warning when the joint "
                 "force reverses relative to the rod (sets dynamics.strict = true)."),
]


def write_csv(path: Path, result: JointLoad) -> None:
    """Write the per-step arrays of ``result`` to ``path`` (atomically, full precision)."""
    columns = result.columns()
    rows = zip(*columns.values(), strict=True)
    with atomic_write(path, encoding="utf-8", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(columns)
        writer.writerows([repr(float(value)) for value in row] for row in rows)


@app.command()
def dynamics(
    config: ConfigArg,
    set_: SetOpt = None,
    json_: JsonOpt = False,
    csv_path: CsvOpt = None,
    strict: StrictOpt = False,
) -> None:
    """Joint load, its azimuth on the bushing and the relative rotation over one revolution."""
    overrides = list(set_ or [])
    if strict:
        overrides.append("dynamics.strict=true")
    cfg = load(config, overrides)
    extra: dict[str, object] = {}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        if cfg.dynamics.model == "contact-impact":
            # the richer solution: impacts, free flight, difference from massless-link
            solution = solve_contact_impact(cfg)
            result = solution.load
            extra = solution.summary()
        else:
            result = joint_load(cfg)
    # warnings go to stderr as one line each, so stdout stays a single JSON object
    for warning in caught:
        err_console.print(f"warning: {warning.message}", markup=False, highlight=False,
                          soft_wrap=True)
    if csv_path is not None:
        write_csv(csv_path, result)
    summary = {
        **result.summary(),
        "spring_mode": cfg.mechanism.spring_mode,
        "clearance_m": cfg.joint.clearance,
        "crank_speed_rpm": cfg.mechanism.crank_speed * 60.0 / (2.0 * math.pi),
        **extra,
    }
    if json_:
        emit_json(summary)
        return
    table = Table(
        title=f"dynamics: {summary['dynamics_model']}, {summary['crank_speed_rpm']:.6g} rpm, "
        f"clearance {cfg.joint.clearance * 1e3:.6g} mm, spring {cfg.mechanism.spring_mode}, "
        f"bushing on the {cfg.mechanism.bushing_body}"
    )
    table.add_column("quantity")
    table.add_column("value", justify="right")
    rows = [
        ("load min / max", f"{summary['load_min_n']:.6g} N / {summary['load_max_n']:.6g} N"),
        ("load time mean", f"{summary['load_mean_n']:.6g} N"),
        ("load sliding-weighted mean", f"{summary['load_sliding_mean_n']:.6g} N"),
        ("azimuth min / max",
         f"{summary['azimuth_min_deg']:.5g}° / {summary['azimuth_max_deg']:.5g}°"),
        ("azimuth range", f"{summary['azimuth_range_deg']:.5g}°"),
        ("total relative rotation", f"{summary['total_relative_rotation_rad']:.6g} rad"),
        ("crank torque rms / max |T|",
         f"{summary['crank_torque_rms_nm']:.5g} N m / "
         f"{summary['crank_torque_max_abs_nm']:.5g} N m"),
        ("steps per revolution", str(summary["steps"])),
        ("fixed-point iterations", str(summary["iterations"])),
        ("contact lost", "yes" if summary["contact_lost"] else "no"),
    ]
    if extra:
        rows += [
            ("force law / c_e / mu",
             f"{summary['force_law']} / {summary['restitution']:.4g} / "
             f"{summary['friction_coefficient']:.4g}"),
            ("impacts in the revolution", str(summary["impacts"])),
            ("free-flight fraction", f"{summary['free_flight_fraction']:.4g}"),
            ("max penetration", f"{summary['max_penetration_m'] * 1e6:.4g} µm"),
            ("|F - F_massless| rms / max",
             f"{summary['load_difference_rms_n']:.4g} N / "
             f"{summary['load_difference_max_n']:.4g} N"),
            ("integration (" + str(summary["integrator"]) + ")",
             f"{summary['integration_runtime_s']:.3g} s, "
             f"{summary['rhs_evaluations']} evaluations"),
        ]
    for name, value in rows:
        table.add_row(name, value)
    console.print(table)
    if csv_path is not None:
        console.print(f"per-step arrays written to {csv_path}", markup=False)
