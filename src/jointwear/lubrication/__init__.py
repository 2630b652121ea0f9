"""Lubrication: the physics of a lubricated revolute joint (pin in a bushing).

A film of oil between pin and bushing carries part or all of the joint load; only
the asperities that still touch carry the rest, and only they wear. The modules are
plain, vectorised SI functions, each checked against closed forms or published values
(``docs/lubrication.md``):

* :mod:`jointwear.lubrication.film` -- film thickness and the short (Ocvirk) and long
  (Sommerfeld) bearing forces of a turning, moving pin, half-Sommerfeld cavitation;
* :mod:`jointwear.lubrication.mobility` -- the finite-length bearing (a numerical
  Reynolds solution tabulated per L/D) and Booker's mobility method for all models;
* :mod:`jointwear.lubrication.asperity` -- Greenwood--Tripp asperity contact, the
  film parameter and the lubrication regime;
* :mod:`jointwear.lubrication.mixed` -- load sharing between film and asperities
  under a steady load;
* :mod:`jointwear.lubrication.orbit` -- the pin's periodic orbit over a load cycle
  (mobility method with wedge and squeeze, asperities in the balance);
* :mod:`jointwear.lubrication.lubricants` -- named lubricants and their viscosity
  at a temperature (ASTM D341).

A lubricated run (``[lubrication]`` with a film model) follows the orbit and shares
each step's load between film, asperities and bulk in
:mod:`jointwear.contact.lubricated`.
"""
