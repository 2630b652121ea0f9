"""The contact–impact machinery every mechanism shares: force laws and integrator.

==============================  ==========================================================
:mod:`.force_laws`              point force laws (Hertz + hysteresis damping), friction
:mod:`.distributed`             distributed laws: the bushing's springs on the pin
:mod:`.joint_contact`           :class:`~.joint_contact.JointContact`: the joint's force
:mod:`.film`                    the oil film's force of a lubricated joint, its parameters
:mod:`.compiled_film`           the film's force compiled by numba (imported on first use)
:mod:`.settings`                :class:`~.settings.ContactImpactSettings` (``[dynamics]``)
:mod:`.integrator`              integration through the contact events
:mod:`.revolution`              a settled, sampled revolution and its solution
:mod:`.free_pin`                a free pin in a fixed bushing (one impact in isolation)
==============================  ==========================================================

A mechanism brings its own contact system (its equations of motion), e.g.
:mod:`jointwear.mechanism.slider_crank.contact_impact`.
"""
