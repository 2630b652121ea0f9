"""Load balance: where the pin sits so that the springs carry the joint load.

For every load ``F`` at azimuth ``psi`` (the direction in which the pin presses
on the bushing) find the pin-centre position ``e`` such that the springs'
resultant equals the load:

* ``balance="paper"``: the pin moves along the load line only, ``e = s w``,
  and ``s`` is iterated until the component along the load balances it
  (paper eqs. 5 and 7, with ``cos beta``): ``sum_j p_j A_j cos(beta_j) = F``.
  On an asymmetric (worn) contour the resultant then has a sideways component,
  reported as ``tangential_force``.
* ``balance="equilibrium"``: full 2-D equilibrium, the resultant *vector*
  equals the load vector (no sideways residue).

All loads are solved together (no Python loop over loads): nodes are gathered
into a window around each load line, where the only nodes that can touch lie
(a node more than 90 degrees from the load can never touch because the pin is
smaller than the bushing), and a bracketed Newton iteration
(:func:`jointwear.solvers.bracketed_newton`) runs on the whole batch.

Starting points: a warm start takes the caller's offsets (the previous revolution).
A cold start on a circle (an unworn bushing, or the symmetric law) takes the
node-free contact of a pin in a circle (:func:`.guesses.circle_guess`, ~1e-5 of the
load off); on a worn contour a batch of >= 64 loads solves every 8th load first and
interpolates (:func:`.guesses.coarse_guess`), a small batch starts from a
conformal-contact estimate. The balance of a cold start then takes fourth-order steps
(power law 1.5: the residual gives its second and third derivatives), which bring a
~1e-5 start to round-off in one step: two evaluations per load, the step and the check.

Convergence: ``|F_total - F| <= max(tolerance, 8 eps * sum|f_j|)``: the
paper's 1e-12 N, with a round-off floor for loads where 1e-12 N is below what
double precision can resolve in a sum of spring forces; and where one ulp of the
offset moves the sum by more than that (deep wear, stiff contact), a residual that
a few ulps of the offset explain (no bisection below what the arithmetic resolves).

Modules: one statement of the balance, one windowed solver, one compiled kernel.

* :mod:`.paper`: eqs. (5)/(7) stated plainly on every node, the reference
  (:func:`~.paper.paper_balance`, :func:`~.paper.paper_pressure`);
* :mod:`.solve`: :func:`solve_contact`, the batched solver on node windows;
* :mod:`.window`: window geometry (cached), bracket, contact extent;
* :mod:`.residual`: the fused, allocation-free NumPy residual;
* :mod:`.guesses`: conformal estimate, node-free circle, coarse pass;
* :mod:`.equilibrium`: full 2-D equilibrium.

The simulation's inner step, balance and Archard wear per revolution, is
:func:`jointwear.contact.kernel.revolution_wear`: a compiled loop per load
(:mod:`jointwear.contact._compiled`, held to :mod:`.paper` by the tests), or without
numba :func:`solve_contact` itself.
"""

from __future__ import annotations

from jointwear.contact.balance.solve import check_reach, checked_loads, solve_contact

__all__ = ["check_reach", "checked_loads", "solve_contact"]
