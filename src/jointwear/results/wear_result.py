"""A run's result: what :meth:`jointwear.Simulation.run` returns and
:func:`jointwear.read_result` reads back."""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ConfigError, DataError
from jointwear.results.contents import ResultContents, build_contents
from jointwear.results.files import config_of, read_result, write_netcdf
from jointwear.results.joints import combine_joints, select_joint
from jointwear.results.summary import run_summary

if TYPE_CHECKING:
    from jointwear.config import Config
    from jointwear.record import RunRecord

__all__ = ["WearResult", "read_wear_result"]

FloatArray = NDArray[np.float64]


class WearResult:
    """Outcome of a simulation.

    Parameters
    ----------
    config : Config
        The fully resolved configuration.
    dataset : xarray.Dataset, optional
        The result Dataset (given, or built from ``contents`` when first read).
    runtime : float
        Wall-clock time of the run [s].
    contents : ResultContents, optional
        The results of one clearance joint as plain arrays
        (:class:`jointwear.results.ResultContents`).
    warnings : tuple of str
        The warnings the run gave about its models' range and the wear's feedback.

    Attributes
    ----------
    dataset : xarray.Dataset
        Profiles, per-step loads, pressure snapshots and per-update metrics,
        with ``units`` and ``long_name`` attributes (built on first access: the
        summary and :meth:`joint_data` need no xarray).
    """

    __slots__ = ("_contents", "_dataset", "config", "runtime", "warnings")

    def __init__(
        self,
        config: Config,
        dataset: Any = None,
        runtime: float = math.nan,
        *,
        contents: ResultContents | None = None,
        warnings: tuple[str, ...] = (),
    ) -> None:
        if dataset is None and contents is None:
            raise TypeError("WearResult needs a dataset or its contents")
        self.config = config
        self.runtime = runtime
        self.warnings = warnings
        self._dataset = dataset
        self._contents = contents

    @classmethod
    def of_record(cls, record: RunRecord) -> WearResult:
        """The result of one clearance joint's run.

        Parameters
        ----------
        record : RunRecord
            The record of the run.
        """
        return cls(
            record.config,
            runtime=record.runtime,
            contents=build_contents(record),
            warnings=record.warnings,
        )

    @classmethod
    def of_joints(
        cls,
        config: Config,
        records: Sequence[RunRecord],
        runtime: float,
        compile_time: float = 0.0,
        compile_in_runtime: float = 0.0,
    ) -> WearResult:
        """The result of several clearance joints, each its own run, along ``joint``.

        Parameters
        ----------
        config : Config
            The configuration of the whole mechanism.
        records : sequence of RunRecord
            Each joint's record.
        runtime : float
            Wall-clock time of all the runs [s].
        compile_time : float
            numba's compile seconds of the whole mechanism's work, set-up included [s].
        compile_in_runtime : float
            Of ``compile_time``, the seconds inside ``runtime`` [s].
        """
        dataset = combine_joints([build_contents(r).to_dataset() for r in records])
        dataset.attrs["compile_time_s"] = compile_time
        dataset.attrs["runtime_without_compile_s"] = runtime - compile_in_runtime
        said = tuple(message for record in records for message in record.warnings)
        return cls(config, dataset, runtime, warnings=said)

    @property
    def dataset(self) -> Any:
        """The result as an xarray Dataset (built from the plain arrays on first access)."""
        if self._dataset is None:
            self._dataset = self._contents.to_dataset()
        return self._dataset

    @property
    def data(self) -> Any:
        """The whole result read like a Dataset, as it is held: a single joint's plain
        arrays (:class:`jointwear.results.ResultContents`) until :attr:`dataset` is
        built, else the Dataset. Enough for the files of a run (netCDF, CSV) without
        xarray."""
        return self._contents if self._dataset is None else self._dataset

    def joint_data(self, joint: str | None = None) -> Any:
        """The results of one joint (default: the most worn one), read like a Dataset.

        A single-joint run answers with its plain arrays
        (:class:`jointwear.results.ResultContents`: ``["name"].values``, ``.attrs``,
        ``.sizes``) without importing xarray; a result of several joints with
        :meth:`joint_dataset`.

        Parameters
        ----------
        joint : str, optional
            Name of the joint.
        """
        if self._contents is None:
            return self.joint_dataset(joint)
        own = str(self._contents.attrs.get("joint", "joint"))
        if joint is not None and joint != own:
            raise DataError(f"result: no clearance joint {joint!r} (it has {own!r})")
        return self._contents

    @property
    def wear_depth(self) -> FloatArray:
        """Final wear-depth profile [m] (of the most worn joint if there are several)."""
        return np.asarray(self.joint_data()["wear_depth"].values[-1])

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the simulated clearance joints."""
        if self._contents is not None:
            return (str(self._contents.attrs.get("joint", "joint")),)
        if "joint" in self.dataset.dims:
            return tuple(str(j) for j in self.dataset["joint"].values)
        return (str(self.dataset.attrs.get("joint", "joint")),)

    def joint_dataset(self, joint: str | None = None) -> Any:
        """The dataset of one joint (default: the most worn one), without a joint dimension.

        Parameters
        ----------
        joint : str, optional
            Name of the joint.
        """
        return select_joint(self.dataset, joint)

    def summary(self, checks: bool = False) -> dict[str, Any]:
        """The ``jointwear run --json`` object (SI units in the key names).

        With several clearance joints, the top-level values are those of the most
        worn joint (``joint``), and ``joints`` holds every joint's.

        Parameters
        ----------
        checks : bool
            With the engineering checks (``checks``), as ``run --json`` prints it and
            ``summary.json`` holds it (:func:`jointwear.results.run_summary`).
        """
        return run_summary(self, checks)

    def __repr__(self) -> str:
        from jointwear.display import wear_result_repr

        return wear_result_repr(self)

    def _repr_html_(self) -> str:
        from jointwear.display import wear_result_html

        return wear_result_html(self)

    def plot(self, kind: str = "wear_polar", **kwargs: Any) -> Any:
        """One figure of the result, a matplotlib Figure (:func:`jointwear.plots.plot_wear_result`).

        Parameters
        ----------
        kind : str
            ``"wear_polar"``, ``"wear_profiles"``, ``"pressure"``, ``"joint_load"`` or
            ``"wear_history"``.
        **kwargs
            Passed to :func:`jointwear.plots.plot_wear_result`.
        """
        from jointwear.plots import plot_wear_result

        return plot_wear_result(self, kind, **kwargs)

    def to_netcdf(self, path: str | Path) -> None:
        """Write the dataset as netCDF (h5netcdf), atomically.

        A single joint's result not yet built as a Dataset is written from its plain
        arrays (:func:`jointwear.results.write_netcdf`): the same file, without xarray.
        """
        write_netcdf(self.data, path)


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
    dataset = read_result(path)
    try:
        config = config_of(dataset)
    except (ConfigError, DataError) as exc:
        raise DataError(f"{path}: {exc}") from None
    runtime = float(dataset.attrs.get("runtime_s", math.nan))
    return WearResult(config=config, dataset=dataset, runtime=runtime)
