"""Results as data: an xarray Dataset (netCDF) and a CSV of per-update metrics.

Every variable carries ``units`` and ``long_name`` attributes (CF style); the
fully resolved configuration is stored as TOML text in the ``config``
attribute, so a result file alone says how it was made.

A finished run first holds its results as plain NumPy arrays
(:class:`ResultContents`, the same names, dimensions and attributes); the xarray
Dataset is built from them only when it is asked for or written. Importing xarray
(and pandas with it) costs more than a one-revolution run, and a summary or a
sweep case needs none of it.
"""

from __future__ import annotations

import contextlib
import csv
import datetime as _dt
import math
import sys
import tomllib
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointwear.errors import DataError
from jointwear.io import atomic_write, check_input
from jointwear.tribology.metrics import PIN_METRICS, WEAR_METRICS

if TYPE_CHECKING:
    import xarray as xr

    from jointwear.config import Config
    from jointwear.contact import ContactSolution
    from jointwear.simulation import Simulation, SimulationState, WearResult

__all__ = [
    "WEAR_VARIABLES",
    "ResultContents",
    "ResultVariable",
    "build_contents",
    "check_result_content",
    "combine_joints",
    "config_of",
    "joint_datasets",
    "read_result",
    "read_wear_result",
    "select_joint",
    "summarize",
    "write_metrics_csv",
    "write_netcdf",
]

#: how many steps of the cycle keep a full pressure distribution
PRESSURE_SNAPSHOTS = 72

_HISTORY_META = {
    **{m.name: (m.units, m.long_name) for m in (*WEAR_METRICS, *PIN_METRICS)},
    "contact_iterations": ("1", "contact balance iterations of the revolution"),
}
_DYNAMICS_META = {
    "revolution": ("1", "revolutions completed when the dynamics were solved"),
    "load_max": ("N", "largest joint load of the cycle (sampled steps)"),
    "load_mean": ("N", "time mean of the joint load"),
    "peak_load": ("N", "largest contact force of the cycle, impacts included"),
    "impacts": ("1", "impacts per cycle"),
    "free_flight_fraction": ("1", "fraction of the cycle in free flight"),
    "load_change": ("1", "RMS change of the load vector since the last solve over RMS load"),
    "max_clearance": ("m", "largest radial play of the pin when the dynamics were solved"),
}


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
    on :meth:`to_dataset`'s Dataset, so :func:`summarize` and the engineering checks
    read either.

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


#: what the revolution coordinates count (floats: a limit ends a run inside a revolution)
_REVOLUTIONS_DONE = "revolutions completed (fractional where a life limit ended the run)"


def revolution_number(value: float) -> int | float:
    """A revolution count as read from a result: an ``int`` if whole, else the ``float`` [-].

    Parameters
    ----------
    value : float
        Revolutions [-].
    """
    value = float(value)
    return int(value) if value.is_integer() else value


def revolutions_text(value: float) -> str:
    """A revolution count for people: a whole number in full, a fraction to two decimals,
    under one revolution to three digits (``352011``, ``352011.63``, ``0.00513``).

    Parameters
    ----------
    value : float
        Revolutions [-].
    """
    number = revolution_number(value)
    if isinstance(number, int):
        return str(number)
    return f"{number:.2f}" if abs(number) >= 1.0 else f"{number:.3g}"


def end_of_run(summary: dict[str, Any]) -> str:
    """Why and when a run ended, one line from its :func:`summarize` values.

    ``stopped: wall_thickness reached at 0.00513 revolutions (7.13e-07 h)`` or
    ``completed: 1000 revolutions (no life limit reached)``.

    Parameters
    ----------
    summary : dict
        A single joint's summary.
    """
    if summary.get("stopped_by"):
        return (
            f"stopped: {summary['stopped_by']} reached at "
            f"{revolutions_text(summary['life_revolutions'])} revolutions "
            f"({summary['life_hours']:.3g} h)"
        )
    revolutions = revolutions_text(summary["revolutions"])
    return f"completed: {revolutions} revolutions (no life limit reached)"


def _var(dims, values, units: str, long_name: str) -> ResultVariable:
    return ResultVariable(dims, values, {"units": units, "long_name": long_name})


def build_contents(
    simulation: Simulation,
    state: SimulationState,
    initial: ContactSolution | None,
    final: ContactSolution | None,
    runtime: float,
) -> ResultContents:
    """The results of a finished run as plain arrays (SI units).

    Parameters
    ----------
    simulation : Simulation
        The simulation that ran (config, load cycle, sliding distance).
    state : SimulationState
        Its final state.
    initial, final : ContactSolution or None
        Contact on the unworn and on the final contour; ``None`` for both leaves out
        the pressure snapshots and the contact half-angle (a sweep case keeps scalars).
    runtime : float
        Wall-clock time of the run [s].
    """
    from jointwear import __version__

    config = simulation.config
    cycle = simulation.load_cycle
    nodes = config.contact.nodes
    theta = 2 * np.pi * np.arange(nodes) / nodes
    saved = state.saved_profiles
    revolutions = np.array(sorted(saved), dtype=np.float64)
    profiles = np.array([saved[r] for r in revolutions]).reshape(len(revolutions), nodes)
    steps = cycle.steps
    sliding = simulation.sliding_distance
    wear_rate = state.wear_rate if state.wear_rate is not None else np.zeros(nodes)
    data_vars = {
        "wear_depth": _var(
            ("revolution", "theta"), profiles, "m", "radial wear depth of the bushing"
        ),
        "wear_rate": _var(
            ("theta",), wear_rate, "m", "wear depth per revolution at the last update"
        ),
        "bushing_radius": _var(
            ("theta",),
            config.joint.bushing_radius + state.wear_depth,
            "m",
            "final inner radius of the bushing",
        ),
        "joint_load": _var(("step",), cycle.load, "N", "joint load magnitude"),
        "load_azimuth": _var(
            ("step",),
            cycle.azimuth,
            "rad",
            "direction of the load on the bushing, bushing frame",
        ),
        "relative_rotation": _var(
            ("step",),
            cycle.relative_rotation,
            "rad",
            "rotation of the pin relative to the bushing over the step",
        ),
        "sliding_distance": _var(("step",), sliding, "m", "sliding distance over the step"),
        **{
            name: _var(("step",), diagnostic.values, diagnostic.units, diagnostic.long_name)
            for name, diagnostic in cycle.diagnostics.items()
        },
    }
    coords = {
        "theta": _var(("theta",), theta, "rad", "bushing angle"),
        "revolution": _var(("revolution",), revolutions, "1", _REVOLUTIONS_DONE),
        "step": _var(("step",), np.arange(steps), "1", "time step of the revolution"),
        "phase": _var(("step",), cycle.phase, "rad", "phase of the cycle at the step start"),
        "time": _var(("step",), cycle.time, "s", "time of the step start"),
    }
    if initial is not None and final is not None:
        snapshot = np.unique(
            np.linspace(0, steps, min(PRESSURE_SNAPSHOTS, steps), endpoint=False).astype(int)
        )
        data_vars["pressure_initial"] = _var(
            ("snapshot", "theta"),
            initial.pressure[snapshot],
            "Pa",
            "contact pressure on the unworn bushing",
        )
        data_vars["pressure_final"] = _var(
            ("snapshot", "theta"),
            final.pressure[snapshot],
            "Pa",
            "contact pressure on the final contour",
        )
        data_vars["contact_half_angle"] = _var(
            ("step",),
            0.5 * (initial.half_angle_left + initial.half_angle_right),
            "rad",
            "mean contact half-angle on the unworn bushing",
        )
        coords["snapshot"] = _var(
            ("snapshot",), cycle.phase[snapshot], "rad", "cycle phase of the pressure snapshot"
        )
    if state.pin_wear_depth is not None:
        data_vars["pin_wear_depth"] = _var(
            ("theta",), state.pin_wear_depth, "m", "final wear depth of the pin, pin frame"
        )
    history = state.history_columns
    for name, values in history.items():
        if name == "revolution":
            continue
        units, long_name = _HISTORY_META[name]
        data_vars[name] = _var(("update",), values, units, long_name)
    dynamics = state.dynamics_updates.columns()
    for name, values in dynamics.items():
        units, long_name = _DYNAMICS_META[name]
        data_vars[f"dynamics_{name}"] = _var(("dynamics_update",), values, units, long_name)
    coords["update"] = _var(
        ("update",), np.arange(len(history["revolution"])), "1", "contour update"
    )
    coords["update_revolution"] = _var(
        ("update",),
        np.asarray(history["revolution"], dtype=np.float64),
        "1",
        f"{_REVOLUTIONS_DONE} at the update",
    )
    attrs = {
        "title": "jointwear wear simulation",
        "contact_model": simulation.law.name if final is None else final.model,
        "mechanism": cycle.mechanism,
        "dynamics_model": cycle.model,
        "joint": cycle.joint,
        "period_s": cycle.period,
        "stopped_by": state.stopped_by or "",
        "dynamics_update": str(config.simulation.dynamics_update),
        "runtime_s": runtime,
        "jointwear_version": __version__,
        "created": _dt.datetime.now(_dt.UTC).isoformat(timespec="seconds"),
        "config": config.to_toml(),
        "Conventions": "CF-1.10",
    }
    return ResultContents(data_vars, coords, attrs)


_STOPPED_BY = {"long_name": "life limit that ended the joint's run ('' if none)"}


def combine_joints(datasets: list[xr.Dataset]) -> xr.Dataset:
    """One dataset with a ``joint`` dimension from the datasets of single joints.

    Joints updated a different number of times (adaptive updating, or a run that a
    limit ended) leave the shorter ``update`` series padded with NaN; the saved profiles
    are on the union of the joints' revolutions, NaN where a joint has none
    (:func:`select_joint` takes each joint's own). ``stopped_by`` is a variable along
    ``joint``.
    """
    import xarray as xr

    names = [str(ds.attrs["joint"]) for ds in datasets]
    # (each joint's run ends on its own: what ended it is a variable along the joints, an
    # attribute that differs between them would be dropped)
    per_joint = [
        ds.reset_coords("update_revolution").assign(
            update_revolution=ds["update_revolution"].astype(float),
            stopped_by=xr.Variable((), str(ds.attrs.get("stopped_by", "")), _STOPPED_BY),
        )
        for ds in datasets
    ]
    combined = xr.concat(
        per_joint,
        dim=xr.Variable(("joint",), names, attrs={"long_name": "clearance joint"}),
        data_vars="all",
        coords="different",
        compat="equals",
        join="outer",
        combine_attrs="drop_conflicts",
    )
    combined.attrs["joint"] = ", ".join(names)
    combined.attrs["runtime_s"] = float(sum(ds.attrs["runtime_s"] for ds in datasets))
    return combined


def select_joint(dataset: xr.Dataset, joint: str | None = None) -> xr.Dataset:
    """The dataset of one joint (default: the one with the deepest wear).

    Parameters
    ----------
    dataset : xarray.Dataset
        A result, with or without a ``joint`` dimension.
    joint : str, optional
        Name of the joint.
    """
    if "joint" not in dataset.dims:
        if joint is not None and joint != dataset.attrs.get("joint", joint):
            raise DataError(
                f"result: no clearance joint {joint!r} (it has {dataset.attrs.get('joint')!r})"
            )
        return dataset
    names = [str(j) for j in dataset["joint"].values]
    if joint is None:
        peaks = [float(np.nanmax(dataset["peak_wear_depth"].sel(joint=j).values)) for j in names]
        joint = names[int(np.argmax(peaks))]
    if joint not in names:
        from jointwear.registry import suggest

        raise DataError(f"result: no clearance joint {joint!r}{suggest(joint, names)}")
    single = dataset.sel(joint=joint, drop=True)
    if "stopped_by" in single.data_vars:
        single.attrs["stopped_by"] = str(single["stopped_by"].values)
        single = single.drop_vars("stopped_by")
    updates = int(np.count_nonzero(np.isfinite(single["update_revolution"].values)))
    single = single.isel(update=slice(0, updates))
    # the profiles are saved at every joint's revolutions (each joint's run ends at its
    # own, fractional where a limit ended it): rows of NaN only are the other joints'
    # padding
    depth = single["wear_depth"]
    saved = depth.notnull().any([dim for dim in depth.dims if dim != "revolution"]).values
    if not saved.all():
        single = single.isel(revolution=np.flatnonzero(saved))
    if "dynamics_revolution" in single:
        solves = int(np.count_nonzero(np.isfinite(single["dynamics_revolution"].values)))
        single = single.isel(dynamics_update=slice(0, solves))
    single.attrs["joint"] = joint
    return single


def summarize(dataset: xr.Dataset) -> dict[str, Any]:
    """The scalar results of a single-joint result dataset (SI, units in the keys).

    The wear metrics (:data:`~jointwear.tribology.metrics.WEAR_METRICS`) at the end
    of the run, what ran, and the life: ``stopped_by`` (the ``[life]`` limit that
    ended the run, or ``None``), ``life_revolutions`` and ``life_hours`` (where it
    was reached, a fraction of a revolution included, or ``None``; then ``revolutions``
    is the same) and ``dynamics_updates`` (solves of the dynamics on the
    worn joint, the first on the unworn joint not counted).
    """
    out: dict[str, Any] = {
        m.key: float(dataset[m.name].values[-1]) * m.scale
        for m in (*WEAR_METRICS, *PIN_METRICS)
        if m.key is not None and m.name in dataset
    }
    revolutions = revolution_number(dataset["update_revolution"].values[-1])
    stopped_by = str(dataset.attrs.get("stopped_by", "")) or None
    period = float(dataset.attrs.get("period_s", math.nan))
    updates = dataset.sizes.get("dynamics_update", 1)
    out.update(
        {
            "revolutions": revolutions,
            "contour_updates": int(dataset.sizes["update"]),
            "contact_model": dataset.attrs["contact_model"],
            "mechanism": dataset.attrs.get("mechanism", "slider-crank"),
            "joint": str(dataset.attrs.get("joint", "rod-slider")),
            "stopped_by": stopped_by,
            "life_revolutions": revolutions if stopped_by else None,
            "life_hours": revolutions * period / 3600.0 if stopped_by else None,
            "dynamics_updates": max(int(updates) - 1, 0),
            "runtime_s": float(dataset.attrs.get("runtime_s", math.nan)),
        }
    )
    return out


def _local_scheduler() -> contextlib.AbstractContextManager[Any]:
    """Serialise with dask's synchronous scheduler while a dask.distributed client is current.

    xarray's netCDF writer takes a client's locks then, and they cannot key the memory
    buffer the result is written to. (Only a process that has loaded ``distributed`` can
    have a client: the check imports nothing.)
    """
    distributed = sys.modules.get("distributed")
    if distributed is None:
        return contextlib.nullcontext()
    try:
        distributed.Client.current(allow_global=True)
    except ValueError:  # no client
        return contextlib.nullcontext()
    import dask

    return dask.config.set(scheduler="synchronous")


def write_netcdf(dataset: xr.Dataset, path: str | Path) -> None:
    """Write a result Dataset to netCDF-4 (h5netcdf) atomically."""
    # serialised in memory, then written as plain bytes: a full disk fails in an ordinary
    # write (no HDF5 file handle is left open to be closed again at exit)
    with _local_scheduler():
        data = dataset.to_netcdf(engine="h5netcdf", invalid_netcdf=False)
    with atomic_write(path, "wb") as handle:
        handle.write(data)


def read_result(path: str | Path) -> xr.Dataset:
    """Read a result file written by :func:`write_netcdf` (loaded into memory).

    Raises
    ------
    DataError
        If the file is missing, unreadable or not a jointwear result.
    """
    path = Path(path)
    check_input(path, "result", max_bytes=None)
    import xarray as xr

    try:
        with xr.open_dataset(path, engine="h5netcdf") as handle:
            dataset = handle.load()
    except Exception as exc:
        raise DataError(f"{path}: not a readable netCDF result ({type(exc).__name__})") from None
    for required in ("wear_depth", "peak_wear_depth"):
        if required not in dataset:
            raise DataError(f"{path}: not a jointwear result (no {required!r} variable)")
    check_result_content(dataset, path)
    return dataset


def read_wear_result(path: str | Path) -> WearResult:
    """Read a ``result.nc`` written by ``jointwear run --out`` back into a result.

    Parameters
    ----------
    path : path-like
        The result file.

    Returns
    -------
    WearResult
        Its dataset, the configuration stored in it and the run's wall-clock time
        (``summary()`` is the summary the run wrote, without the engineering checks).

    Raises
    ------
    DataError
        If the file is missing, unreadable, not a jointwear result or without a
        readable stored config.
    """
    from jointwear.errors import ConfigError
    from jointwear.simulation import WearResult

    dataset = read_result(path)
    try:
        config = config_of(dataset)
    except (ConfigError, DataError) as exc:
        raise DataError(f"{path}: {exc}") from None
    runtime = float(dataset.attrs.get("runtime_s", math.nan))
    return WearResult(config=config, dataset=dataset, runtime=runtime)


#: variables of a result whose values are wear depths: present, in metres, finite, >= 0
WEAR_VARIABLES = ("wear_depth", "peak_wear_depth")


def check_result_content(dataset: xr.Dataset, path: str | Path) -> None:
    """Refuse a result whose wear variables are not finite, non-negative depths in metres.

    A file edited or written by another program can carry the right names with
    wrong content; every command that reads results (``plot``, ``compare``) sees
    it refused here, naming the file and the variable.

    Parameters
    ----------
    dataset : xarray.Dataset
        The result, loaded.
    path : path-like
        The file, for the message.

    Raises
    ------
    DataError
        Wrong dimensions or units, a non-numeric, non-finite or negative wear value.
    """
    depth = dataset["wear_depth"]
    if "theta" not in depth.dims or "revolution" not in depth.dims:
        raise DataError(
            f"{path}: variable 'wear_depth' has dimensions {depth.dims}, "
            "expected ('revolution', 'theta')"
        )
    if "theta" not in dataset.coords or dataset.sizes["theta"] < 3:
        raise DataError(f"{path}: no 'theta' coordinate with at least 3 nodes")
    # several joints: each joint's own rows (a joint's records end where its run ended; the
    # rest is NaN padding)
    singles: tuple[xr.Dataset, ...] = (dataset,)
    if "joint" in dataset.dims:
        # (records that cannot be split by joint are checked whole, and refused there)
        with contextlib.suppress(TypeError, ValueError, KeyError, DataError):
            singles = tuple(joint_datasets(dataset).values())
    for single in singles:
        _check_wear_values(single, path)


def _check_wear_values(dataset: xr.Dataset, path: str | Path) -> None:
    """Refuse wear variables of one joint that are not finite, non-negative metres."""
    for name in WEAR_VARIABLES:
        variable = dataset[name]
        units = variable.attrs.get("units")
        if units != "m":
            raise DataError(f"{path}: variable {name!r} is in {units!r}, expected 'm'")
        if not np.issubdtype(variable.dtype, np.number) or np.issubdtype(
            variable.dtype, np.complexfloating
        ):
            raise DataError(f"{path}: variable {name!r} holds {variable.dtype}, not real numbers")
        values = np.asarray(variable.values, dtype=float)
        if not np.all(np.isfinite(values)):
            bad = int(np.count_nonzero(~np.isfinite(values)))
            raise DataError(f"{path}: variable {name!r} has {bad} non-finite value(s) (nan or inf)")
        if values.size and values.min() < 0:
            raise DataError(
                f"{path}: variable {name!r} has negative wear (down to {values.min():.3g} m); "
                "a wear depth is >= 0"
            )


def config_of(dataset: xr.Dataset) -> Config:
    """The configuration stored in a result Dataset."""
    from jointwear.config import config_from_dict

    try:
        data: dict[str, Any] = tomllib.loads(dataset.attrs["config"])
    except (KeyError, tomllib.TOMLDecodeError) as exc:
        raise DataError(f"result: no readable stored config ({exc})") from None
    return config_from_dict(data, defaults=False)


def joint_datasets(dataset: xr.Dataset) -> dict[str, xr.Dataset]:
    """Joint name -> its single-joint dataset (one entry for a single-joint result)."""
    if "joint" not in dataset.dims:
        return {str(dataset.attrs.get("joint", "joint")): dataset}
    return {str(j): select_joint(dataset, str(j)) for j in dataset["joint"].values}


def write_metrics_csv(dataset: xr.Dataset, path: str | Path) -> None:
    """Per-update metrics as CSV, units in the header; a ``joint`` column for several joints."""
    joints = joint_datasets(dataset)
    several = len(joints) > 1
    with atomic_write(path, newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        for index, (joint, single) in enumerate(joints.items()):
            columns = [("revolution", single["update_revolution"].values, 1.0)] + [
                (m.header, single[m.name].values, m.scale)
                for m in (*WEAR_METRICS, *PIN_METRICS)
                if m.name in single
            ]
            if index == 0:
                writer.writerow((["joint"] if several else []) + [n for n, _, _ in columns])
            for i in range(len(columns[0][1])):
                row = [f"{values[i] * scale:.10g}" for _, values, scale in columns]
                writer.writerow(([joint] if several else []) + row)
