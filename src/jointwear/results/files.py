"""Result files: netCDF (h5netcdf) written atomically and read back checked, and the CSV
of the per-update metrics.

Every variable carries ``units`` and ``long_name`` attributes (CF style); the fully
resolved configuration is stored as TOML text in the ``config`` attribute, so a result
file alone says how it was made.
"""

from __future__ import annotations

import contextlib
import csv
import sys
import tomllib
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from jointwear.errors import DataError
from jointwear.io import atomic_write, check_input
from jointwear.results.contents import ResultContents
from jointwear.results.joints import joint_datasets
from jointwear.results.netcdf_file import contents_netcdf, writes_plainly
from jointwear.tribology.metrics import PIN_METRICS, WEAR_METRICS

if TYPE_CHECKING:
    import xarray as xr

    from jointwear.config import Config

__all__ = [
    "WEAR_VARIABLES",
    "check_result_content",
    "config_of",
    "read_result",
    "write_metrics_csv",
    "write_netcdf",
]


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


def write_netcdf(dataset: xr.Dataset | ResultContents, path: str | Path) -> None:
    """Write a result to netCDF-4 (h5netcdf) atomically.

    A single joint's contents of plain numbers are written with h5netcdf as xarray
    writes their Dataset (:mod:`jointwear.results.netcdf_file`), without importing
    xarray; a Dataset, and other contents, with xarray.

    Parameters
    ----------
    dataset : xarray.Dataset or ResultContents
        The result.
    path : path-like
        The file.
    """
    # serialised in memory, then written as plain bytes: a full disk fails in an ordinary
    # write (no HDF5 file handle is left open to be closed again at exit)
    if isinstance(dataset, ResultContents) and writes_plainly(dataset):
        data: bytes | memoryview = contents_netcdf(dataset)
    else:
        if isinstance(dataset, ResultContents):
            dataset = dataset.to_dataset()
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


def write_metrics_csv(dataset: xr.Dataset | ResultContents, path: str | Path) -> None:
    """Per-update metrics as CSV, units in the header; a ``joint`` column for several joints.

    ``dataset`` is a result Dataset, or a single joint's :class:`ResultContents`.
    """
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
