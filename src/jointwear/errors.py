"""Exception types of jointwear.

Every error a user can cause derives from :class:`JointwearError`; the CLI turns
these into a one-line message and exit status 2. Anything else is a bug (exit 1).
"""

from __future__ import annotations

__all__ = [
    "ConfigError",
    "ContactError",
    "ContactLossWarning",
    "ContactModelWarning",
    "ConvergenceError",
    "DataError",
    "FitMisfitWarning",
    "GeometryError",
    "JointwearError",
    "MaterialLimitWarning",
    "MechanismError",
    "TimeLimitError",
    "WearFeedbackWarning",
    "WearThroughError",
]


class JointwearError(Exception):
    """Base class of all errors caused by input or by physics the model cannot handle.

    The message is one line: a line break inside it (a file name with a newline,
    a value pasted with one) is shown escaped, as ``\\n``.
    """

    def __str__(self) -> str:
        return super().__str__().replace("\r", "\\r").replace("\n", "\\n")


class ConfigError(JointwearError, ValueError):
    """A configuration value is missing, unknown, of the wrong unit or out of range.

    The message starts with the dotted key, e.g. ``joint.clearance: must be > 0``.
    """


class DataError(JointwearError, ValueError):
    """A data file (measured points, result file, sweep file) cannot be used."""


class GeometryError(JointwearError, ValueError):
    """The joint geometry is impossible (pin not inside bushing, bad contour ...)."""


class ContactError(JointwearError):
    """The contact problem has no solution (e.g. the load pushes the pin through the wall)."""


class ConvergenceError(ContactError):
    """An iterative solver did not converge within its iteration budget."""


class MechanismError(JointwearError):
    """The mechanism cannot assemble or its model assumptions are violated."""


class TimeLimitError(JointwearError):
    """The wall-clock limit (``--time-limit``) passed before the job finished.

    A checkpointed run keeps its checkpoint and a sweep its finished cases; the
    message names the command that continues.
    """


class WearThroughError(JointwearError):
    """Wear has consumed the whole bushing wall."""


class ContactLossWarning(UserWarning):
    """The joint force reverses relative to the rod, so pin and bushing would separate.

    The massless-link dynamics model assumes continuous contact; where the force
    reverses its results are not physical. ``dynamics.strict = true`` turns this
    warning into :class:`MechanismError`.
    """


class ContactModelWarning(UserWarning):
    """A run left the range in which its contact model holds (said once per run).

    A circular-bushing model worn deeper than a fraction of the clearance, a Hertz
    contact that is not small, a contact arc cut at 90 degrees, strains beyond linear
    elasticity, or the constrained modulus of a nearly incompressible wall
    (:mod:`jointwear.tribology.checks`); the message names the setting to change.
    """


class MaterialLimitWarning(UserWarning):
    """The joint runs beyond a datasheet limit of its bushing material.

    Nominal pressure, sliding speed or PV above the material's ``max_*`` values
    (:mod:`jointwear.materials`): the wear coefficient measured below the limit does
    not hold there (melting, creep, severe wear), so the predicted wear is optimistic.
    """


class WearFeedbackWarning(UserWarning):
    """A run's assumptions are in doubt as the joint wears (said once per run).

    Wear of the order of the clearance under the massless-link load, a load that
    falls to zero, or separation found when the dynamics are solved on the worn
    joint; the message names the setting that would model it.
    """


class FitMisfitWarning(UserWarning):
    """A fitted model leaves residuals well above the measurement noise.

    The model cannot explain the measurement (wrong contact model, load, speed or
    revolutions), and an uncertainty computed on the assumption that it does is
    not to be trusted.
    """
