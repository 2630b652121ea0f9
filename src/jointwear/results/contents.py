"""A run's results as plain arrays, named and described as in the result Dataset.

:func:`build_contents` turns the record of a run (:class:`jointwear.record.RunRecord`)
into :class:`ResultContents`: every variable with its dimensions, SI values and
``units`` / ``long_name`` attributes (CF style), the fully resolved configuration as TOML
text in the ``config`` attribute. The contents read like the xarray Dataset they become
(:meth:`ResultContents.to_dataset`), so the summary and the engineering checks read them
without importing xarray: importing xarray (and pandas with it) costs more than a
one-revolution run, and a summary or a sweep case needs none of it.
"""

from __future__ import annotations

import datetime as _dt
from typing import TYPE_CHECKING, Any

import numpy as np

from jointwear.coupling.dynamics import DYNAMICS_COLUMNS
from jointwear.record import UPDATE_COLUMNS
from jointwear.results.axial import axial_coordinates, axial_shape

if TYPE_CHECKING:
    import xarray as xr

    from jointwear.record import RunRecord

__all__ = ["PRESSURE_SNAPSHOTS", "ResultContents", "ResultVariable", "build_contents"]

#: how many steps of the cycle keep a full pressure distribution
PRESSURE_SNAPSHOTS = 72

#: what the revolution coordinates count (floats: a limit ends a run inside a revolution)
REVOLUTIONS_DONE = "revolutions completed (fractional where a life limit ended the run)"


class ResultVariable:
    """One variable of :class:`ResultContents`: dimensions, NumPy values and attributes.

    Reads like an ``xarray.Variable`` where the package reads results (``.values``,
    ``.dims``, ``.attrs``, ``.dtype``).
    """

    __slots__ = ("attrs", "dims", "values")

    def __init__(self, dims: tuple[str, ...], values: Any, attrs: dict[str, str]) -> None:
        self.dims = tuple(dims)
        self.values = np.asarray(values)
        self.attrs = attrs

    @property
    def dtype(self) -> np.dtype:
        return self.values.dtype

    def to_variable(self) -> xr.Variable:
        """The ``xarray.Variable`` (the values are not copied)."""
        import xarray as xr

        # fastpath: the values are NumPy arrays already; without it xarray probes for dask
        return xr.Variable(self.dims, self.values, attrs=dict(self.attrs), fastpath=True)


class ResultContents:
    """The result of one clearance joint as plain arrays, read like the Dataset it becomes.

    ``contents["wear_depth"].values``, ``"pin_wear_depth" in contents``,
    ``contents.attrs``, ``contents.sizes`` and ``contents.dims`` answer as they would
    on :meth:`to_dataset`'s Dataset, so :func:`jointwear.results.summarize` and the
    engineering checks read either.

    Parameters
    ----------
    data_vars, coords : dict of str to ResultVariable
        Variables and coordinates (SI values, ``units`` and ``long_name`` attributes).
    attrs : dict
        Global attributes.
    """

    def __init__(
        self,
        data_vars: dict[str, ResultVariable],
        coords: dict[str, ResultVariable],
        attrs: dict[str, Any],
    ) -> None:
        self.data_vars = data_vars
        self.coords = coords
        self.attrs = attrs

    def __getitem__(self, name: str) -> ResultVariable:
        found = self.data_vars.get(name) or self.coords.get(name)
        if found is None:
            raise KeyError(name)
        return found

    def __contains__(self, name: object) -> bool:
        return name in self.data_vars or name in self.coords

    @property
    def sizes(self) -> dict[str, int]:
        """Dimension name -> length."""
        out: dict[str, int] = {}
        for variable in (*self.coords.values(), *self.data_vars.values()):
            out.update(zip(variable.dims, variable.values.shape, strict=True))
        return out

    @property
    def dims(self) -> dict[str, int]:
        return self.sizes

    def to_dataset(self) -> xr.Dataset:
        """The xarray Dataset of these contents (the arrays are shared, not copied)."""
        import xarray as xr

        return xr.Dataset(
            {name: v.to_variable() for name, v in self.data_vars.items()},
            coords={name: v.to_variable() for name, v in self.coords.items()},
            attrs=dict(self.attrs),
        )


def _var(dims: tuple[str, ...], values: Any, units: str, long_name: str) -> ResultVariable:
    return ResultVariable(dims, values, {"units": units, "long_name": long_name})


def build_contents(record: RunRecord) -> ResultContents:
    """The results of a finished run as plain arrays (SI units).

    Parameters
    ----------
    record : RunRecord
        The record of one clearance joint's run. Without its contact snapshots (a sweep
        case) the pressure snapshots and the contact half-angle are left out.
    """
    data_vars = {**_wear_variables(record), **_cycle_variables(record)}
    coords = _cycle_coordinates(record)
    if record.initial is not None and record.final is not None:
        snapshots, snapshot = _pressure_variables(record)
        data_vars.update(snapshots)
        coords["snapshot"] = snapshot
    data_vars.update(film_variables(record))
    pin = record.state.pin_wear_depth
    if pin is not None:  # (a map over (z, theta) along the pin, as the bushing's)
        data_vars["pin_wear_depth"] = _var(
            axial_shape(record.config, pin.shape[-1])[1], pin, "m",
            "final wear depth of the pin, pin frame",
        )  # fmt: skip
    updates, update_coords = _record_variables(record)
    data_vars.update(updates)
    coords.update(update_coords)
    return ResultContents(data_vars, coords, _attributes(record))


def _wear_variables(record: RunRecord) -> dict[str, ResultVariable]:
    """The saved profiles, the last wear rate and the final radius of the bushing."""
    state, nodes = record.state, record.config.contact.nodes
    saved = state.saved_profiles
    revolutions = np.array(sorted(saved), dtype=np.float64)
    # along the pin (joint.axial_slices > 1) every profile is a map over (z, theta)
    shape, map_dims = axial_shape(record.config, nodes)
    profiles = np.array([saved[r] for r in revolutions]).reshape(len(revolutions), *shape)
    wear_rate = state.wear_rate if state.wear_rate is not None else np.zeros(shape)
    return {
        "wear_depth": _var(
            ("revolution", *map_dims), profiles, "m", "radial wear depth of the bushing"
        ),
        "wear_rate": _var(map_dims, wear_rate, "m", "wear depth per revolution at the last update"),
        "bushing_radius": _var(
            map_dims,
            record.config.joint.bushing_radius + state.wear_depth,
            "m",
            "final inner radius of the bushing",
        ),
    }


def _cycle_variables(record: RunRecord) -> dict[str, ResultVariable]:
    """The load cycle per step, its sliding distance and the cycle's diagnostics."""
    cycle = record.cycle
    return {
        "joint_load": _var(("step",), cycle.load, "N", "joint load magnitude"),
        "load_azimuth": _var(
            ("step",), cycle.azimuth, "rad", "direction of the load on the bushing, bushing frame"
        ),
        "relative_rotation": _var(
            ("step",),
            cycle.relative_rotation,
            "rad",
            "rotation of the pin relative to the bushing over the step",
        ),
        "sliding_distance": _var(
            ("step",), record.sliding_distance, "m", "sliding distance over the step"
        ),
        **{
            name: _var(("step",), diagnostic.values, diagnostic.units, diagnostic.long_name)
            for name, diagnostic in cycle.diagnostics.items()
        },
    }


def film_variables(record: RunRecord) -> dict[str, ResultVariable]:
    """A lubricated run's film per step of the cycle (none for a dry run)."""
    film = record.film
    if film is None:
        return {}
    return {
        "min_film_thickness": _var(
            ("step",), film.min_film_thickness, "m", "minimum oil film thickness"
        ),
        "film_parameter": _var(
            ("step",), film.film_parameter, "1", "film parameter h_min / composite roughness"
        ),
        "asperity_load_fraction": _var(
            ("step",),
            film.asperity_load_fraction,
            "1",
            "share of the load carried by solid contact (asperities and bulk)",
        ),
        "bulk_load_fraction": _var(
            ("step",), film.bulk_load_fraction, "1", "share of the load carried by bulk contact"
        ),
        "eccentricity_ratio_x": _var(
            ("step",), film.eccentricity_x, "1", "pin centre orbit x / radial clearance"
        ),
        "eccentricity_ratio_y": _var(
            ("step",), film.eccentricity_y, "1", "pin centre orbit y / radial clearance"
        ),
    }


def _cycle_coordinates(record: RunRecord) -> dict[str, ResultVariable]:
    """The bushing angle, the saved profiles' revolutions and the steps of the cycle."""
    cycle, nodes = record.cycle, record.config.contact.nodes
    revolutions = np.array(sorted(record.state.saved_profiles), dtype=np.float64)
    return {
        **{name: _var(*spec) for name, spec in axial_coordinates(record.config).items()},
        "theta": _var(("theta",), 2 * np.pi * np.arange(nodes) / nodes, "rad", "bushing angle"),
        "revolution": _var(("revolution",), revolutions, "1", REVOLUTIONS_DONE),
        "step": _var(("step",), np.arange(cycle.steps), "1", "time step of the revolution"),
        "phase": _var(("step",), cycle.phase, "rad", "phase of the cycle at the step start"),
        "time": _var(("step",), cycle.time, "s", "time of the step start"),
    }


def _pressure_variables(record: RunRecord) -> tuple[dict[str, ResultVariable], ResultVariable]:
    """Pressure snapshots of the unworn and the final contour (:data:`PRESSURE_SNAPSHOTS`
    steps), the mean contact half-angle on the unworn bushing, and the snapshots' phase."""
    initial, final, steps = record.initial, record.final, record.cycle.steps
    # at most one point per step: distinct and increasing as they are (np.unique would
    # only add the import of numpy.ma to a run's start)
    snapshot = np.linspace(0, steps, min(PRESSURE_SNAPSHOTS, steps), endpoint=False).astype(int)
    variables = {
        "pressure_initial": _var(
            ("snapshot", "theta"),
            initial.pressure[snapshot],
            "Pa",
            "contact pressure on the unworn bushing",
        ),
        "pressure_final": _var(
            ("snapshot", "theta"),
            final.pressure[snapshot],
            "Pa",
            "contact pressure on the final contour",
        ),
        "contact_half_angle": _var(
            ("step",), initial.half_angle, "rad", "mean contact half-angle on the unworn bushing"
        ),
    }
    phase = _var(
        ("snapshot",), record.cycle.phase[snapshot], "rad", "cycle phase of the pressure snapshot"
    )
    return variables, phase


def _record_variables(
    record: RunRecord,
) -> tuple[dict[str, ResultVariable], dict[str, ResultVariable]]:
    """The per-update record and the dynamics record, with their coordinates."""
    history = record.state.history_columns
    variables = {}
    for name, values in history.items():
        if name != "revolution":
            units, long_name = UPDATE_COLUMNS[name]
            variables[name] = _var(("update",), values, units, long_name)
    for name, values in record.state.dynamics_updates.columns().items():
        units, long_name = DYNAMICS_COLUMNS[name]
        variables[f"dynamics_{name}"] = _var(("dynamics_update",), values, units, long_name)
    coords = {
        "update": _var(("update",), np.arange(len(history["revolution"])), "1", "contour update"),
        "update_revolution": _var(
            ("update",),
            np.asarray(history["revolution"], dtype=np.float64),
            "1",
            f"{REVOLUTIONS_DONE} at the update",
        ),
    }
    return variables, coords


def _film_model(record: RunRecord) -> dict[str, str]:
    """The film model of a lubricated run: the dynamics' (a given cycle's too) or the
    load cycle's sharing (``[lubrication]``); none for a dry run."""
    section = record.config.lubrication
    model = record.cycle.extras.get("film_model") or (section.model if section.lubricated else "")
    return {"film_model": str(model)} if model else {}


def _attributes(record: RunRecord) -> dict[str, Any]:
    """The global attributes: what ran, how it ended, and the configuration as TOML."""
    from jointwear.version import package_version

    cycle, config = record.cycle, record.config
    return {
        "title": "jointwear wear simulation",
        "contact_model": record.contact_model,
        "mechanism": cycle.mechanism,
        "dynamics_model": cycle.model,
        "joint": cycle.joint,
        "period_s": cycle.period,
        # a duty cycle's modes one after the other last period_s; a cycle, on average, this
        **({"mean_cycle_duration_s": cycle.duty.mean_period} if cycle.duty else {}),
        **_film_model(record),
        # the contact-impact integrator that ran (``dynamics.integrator = "auto"`` resolved)
        **({"integrator": str(cycle.extras["integrator"])} if "integrator" in cycle.extras else {}),
        "stopped_by": record.state.stopped_by or "",
        "dynamics_update": str(config.simulation.dynamics_update),
        "runtime_s": record.runtime,
        "compile_time_s": record.compile_time,
        "runtime_without_compile_s": record.runtime - record.compile_in_runtime,
        "jointwear_version": package_version(),
        "created": _dt.datetime.now(_dt.UTC).isoformat(timespec="seconds"),
        "config": config.to_toml(),
        "Conventions": "CF-1.10",
    }
