"""A run's result file written from its plain arrays with h5netcdf, as xarray writes it.

xarray's netCDF writer (``Dataset.to_netcdf(engine="h5netcdf")``), and the Dataset it
writes, cost a run with ``--out`` more than the run: xarray and pandas are imported, and
where dask is installed xarray's probes for other array types import ``dask.array`` and
pint (with ``dask.base``), and its writer asks dask for a scheduler, which imports
``distributed``. A single joint's :class:`~jointwear.results.ResultContents` hold plain
NumPy arrays of numbers with text ``units`` and ``long_name`` attributes; such contents
are written here through h5netcdf's public API into the file xarray would write: the
same dimensions, variables, attributes, ``_FillValue`` of floats (NaN, as xarray's
default) and ``coordinates`` attributes of the non-dimension coordinates (CF
conventions, as xarray encodes them). xarray reads it back identical, encodings
included (``tests/results/test_netcdf_file.py``). Contents holding anything else
(:func:`writes_plainly` says) go to xarray's writer.
"""

from __future__ import annotations

import io
import numbers
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:
    from jointwear.results.contents import ResultContents, ResultVariable

__all__ = ["contents_netcdf", "writes_plainly"]

#: the attributes a variable of the contents may carry to be written here
VARIABLE_ATTRIBUTES = frozenset({"units", "long_name"})


def _plain_attribute(name: object, value: object) -> bool:
    """A text or a real number, under a name netCDF and xarray take as it is."""
    if not isinstance(name, str) or "/" in name or not name:
        return False
    if isinstance(value, str):
        return True
    return isinstance(value, numbers.Real) and not isinstance(value, bool | np.bool_)


def writes_plainly(contents: ResultContents) -> bool:
    """Whether :func:`contents_netcdf` writes ``contents`` as xarray would.

    Real numbers (integers, floats) in every variable, attributes ``units`` and
    ``long_name`` of text on the variables, text or number global attributes (no
    ``coordinates`` among them), names without ``/``.

    Parameters
    ----------
    contents : ResultContents
        The results of one clearance joint.
    """
    variables = {**contents.data_vars, **contents.coords}
    for name, variable in variables.items():
        if not isinstance(name, str) or "/" in name or not name:
            return False
        if variable.values.dtype.kind not in "iuf":
            return False
        attrs = variable.attrs
        if not set(attrs) <= VARIABLE_ATTRIBUTES or not all(
            isinstance(text, str) for text in attrs.values()
        ):
            return False
    if "coordinates" in contents.attrs:
        return False
    return all(_plain_attribute(name, value) for name, value in contents.attrs.items())


def _coordinates_attributes(
    variables: dict[str, ResultVariable], coordinates: set[str]
) -> tuple[dict[str, str], str]:
    """The ``coordinates`` attribute of each variable, and the file's (CF conventions).

    A non-dimension coordinate is named by every other variable that has all its
    dimensions (and is neither such a coordinate nor the coordinate of a dimension of
    its own); one named by none goes into the global attribute. Names sorted, as
    xarray writes them.
    """
    extra = {name for name in coordinates if name not in variables[name].dims}
    named: dict[str, set[str]] = {}
    for coordinate in extra:
        wanted = set(variables[coordinate].dims)
        for name, variable in variables.items():
            if name not in extra and name not in variable.dims and wanted <= set(variable.dims):
                named.setdefault(name, set()).add(coordinate)
    written = set().union(*named.values()) if named else set()
    return (
        {name: " ".join(sorted(names)) for name, names in named.items()},
        " ".join(sorted(extra - written)),
    )


def contents_netcdf(contents: ResultContents) -> bytes:
    """The netCDF-4 file of ``contents`` (see :func:`writes_plainly` for which contents).

    Dimensions in the order they first appear (data variables, then coordinates), each
    variable contiguous, uncompressed and of its own dtype, floats with ``_FillValue``
    NaN, as ``Dataset.to_netcdf(engine="h5netcdf")`` writes them.

    Parameters
    ----------
    contents : ResultContents
        The results of one clearance joint, all written plainly.

    Returns
    -------
    bytes
        The file.
    """
    import h5netcdf

    variables = {**contents.data_vars, **contents.coords}
    per_variable, global_coordinates = _coordinates_attributes(variables, set(contents.coords))
    sizes: dict[str, int] = {}
    for variable in variables.values():
        for dim, size in zip(variable.dims, variable.values.shape, strict=True):
            sizes.setdefault(dim, size)
    attributes: dict[str, Any] = dict(contents.attrs)
    if global_coordinates:
        attributes["coordinates"] = global_coordinates
    buffer = io.BytesIO()
    with h5netcdf.File(buffer, "w", format="NETCDF4", invalid_netcdf=False) as handle:
        for key, value in attributes.items():
            handle.attrs[key] = value
        for dim, size in sizes.items():
            handle.dimensions[dim] = size
        for name, variable in variables.items():
            values = variable.values
            floating = values.dtype.kind == "f"
            created = handle.create_variable(
                name,
                dimensions=variable.dims,
                dtype=values.dtype,
                fillvalue=values.dtype.type(np.nan) if floating else None,
                **({"chunks": None} if values.ndim else {}),
            )
            for key, text in variable.attrs.items():
                created.attrs[key] = text
            if name in per_variable:
                created.attrs["coordinates"] = per_variable[name]
            created[...] = values
    return buffer.getvalue()
