"""Reference solutions for the contact pressure models (exact elasticity and finite elements).

The paper compares NLCP with Winkler but neither with an exact solution. This
package provides two references with the contact-model interface
(``.solve(contour, pin, load, azimuth, **options) -> ContactSolution``):

=============  ==============================================================
``persson``    exact plane-strain elasticity of a pin in a hole (Persson's
               problem), numerically exact, circular bushings only
               (:mod:`jointwear.references.persson`)
``fem``        finite elements (scikit-fem) of the real bushing wall in a
               rigid housing, unilateral contact with the rigid pin, worn
               contours too (:mod:`jointwear.references.fem`)
=============  ==============================================================

For worn joints, :mod:`jointwear.references.conformal` gives the exact rigid-conformal
worn bore under a fixed load, and :mod:`jointwear.references.validation` runs the
wear simulation against it and against closed forms (the documentation's Validation
page).

Along the pin, :mod:`jointwear.references.axial_fem` solves the liner in 3-D under a
tilted pin and measures what the slices of :mod:`jointwear.contact.axial` neglect.

:mod:`jointwear.references.compare` tabulates every contact model against them
and :mod:`jointwear.references.spring_fit` fits Winkler's and NLCP's spring constants
to a reference.

The contact package registers ``persson`` and ``fem`` by name
(``"jointwear.references.persson:model"``) and imports them when first used: the
references import the contact package, never the other way round.
"""

from __future__ import annotations

__all__: list[str] = []
