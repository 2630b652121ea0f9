"""Results of several clearance joints: one dataset with a ``joint`` dimension, and back."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from jointwear.errors import DataError
from jointwear.record import WALL_CLOCK_KEYS

if TYPE_CHECKING:
    import xarray as xr

__all__ = ["combine_joints", "joint_datasets", "select_joint"]


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
    for key in WALL_CLOCK_KEYS:  # (each joint's run, one after the other)
        combined.attrs[key] = float(sum(ds.attrs.get(key, math.nan) for ds in datasets))
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


def joint_datasets(dataset: xr.Dataset) -> dict[str, xr.Dataset]:
    """Joint name -> its single-joint dataset (one entry for a single-joint result)."""
    if "joint" not in dataset.dims:
        return {str(dataset.attrs.get("joint", "joint")): dataset}
    return {str(j): select_joint(dataset, str(j)) for j in dataset["joint"].values}
