r"""The body a contact computes: a table material or one's own values, with overrides.

Users rarely have the table's clean-surface values: surfaces in air adhere far less than
:math:`2\gamma`, a film has its own modulus, a material may not be in the table at all.
:func:`contact_material` builds the :class:`~asperity.materials.Material` a
:class:`~asperity.physical.PhysicalContact` computes from a table name and/or values
of one's own, checked once, here:

* the **first body**: a table name (``'Au'``), a :class:`~asperity.materials.Material`,
  or ``E`` and ``nu`` alone (a body not in the table); ``E`` and ``nu`` replace the
  table's values;
* the **second body**: the rigid flat of the paper, unless ``material`` names a pair
  (``'Au/Au'``, ``'A/B'``) or ``material2``/``E2``/``nu2`` give one; two bodies are
  mapped onto their equivalent body by :func:`~asperity.materials.pair`
  (:math:`E^* = [(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2]^{-1}`, :math:`G^* = 2G_1G_2/(G_1+G_2)`);
* the **interface**: Burgers vector ``b``, work of adhesion ``w``, Dugdale range ``h``
  or stress ``sigma0`` replace the body's (or pair's) values.

So ``contact_material("Au")`` is gold on a rigid flat and ``contact_material("Au/Au")``
two gold bodies: :math:`E^*` and :math:`G^*` halve and the answers change (for
:math:`\sigma_s` = 2 nm, :math:`R` = 1 µm the pull-off force is 1.6 times larger, the
friction force under 1 mN 1.2 times smaller).

References
----------
.. [1] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §4.2.
.. [2] Adams, Müftü, Mohd Azhar, Eqs (2), (14)-(16).
"""

from __future__ import annotations

from dataclasses import replace

from ._validation import check_optional_positive, check_scalar_poisson
from .materials import Material, as_material, material_names, pair

__all__ = ["contact_material"]


def _first_and_second(material_, material2):
    """The first body, the second body (or None) and the pair's own w, from the table or a Material."""
    if material_ is None:
        first, second, pair_w = None, None, None
    elif isinstance(material_, str) and "/" in material_ and \
            material_.strip().lower() not in {n.lower() for n in material_names()}:
        if material_.count("/") > 1:
            raise ValueError(f"material must name one body ('Au') or two ('A/B'), got {material_!r}")
        one, _, two = material_.partition("/")  # 'A/B' of two table rows: b may be given below
        first, second, pair_w = as_material(one.strip(), "material"), as_material(two.strip(), "material"), None
    else:
        m = as_material(material_, "material")
        first, second, pair_w = (m.bodies[0], m.bodies[1], m.w) if m.bodies else (m, None, None)
    if material2 is not None:
        if second is not None:
            raise ValueError(f"material {first.name}/{second.name} is already a pair: give the second body "
                             "either in material ('A/B') or as material2, not both")
        second = as_material(material2, "material2")  # its errors start with "material2: "
        if second.bodies:
            raise ValueError(f"material2 must be one body, got the pair {second.name!r}")
    return first, second, pair_w


def _body(base, E, nu, *, E_name, nu_name, label):
    """``base`` with E and nu replaced where given, or a new body from E and nu."""
    if base is None:
        if E is None and nu is None:
            return None
        if E is None or nu is None:
            missing = E_name if E is None else nu_name
            raise ValueError(f"{missing} is needed: a body that is not from the table needs both {E_name} "
                             f"(Young's modulus, Pa) and {nu_name} (Poisson's ratio)")
        return Material(label, E=E, nu=nu)
    return replace(base, E=base.E if E is None else E, nu=base.nu if nu is None else nu, bodies=(), components=())


def contact_material(material=None, *, E=None, nu=None, material2=None, E2=None, nu2=None,
                     b=None, w=None, h=None, sigma0=None) -> Material:
    r"""The body a contact computes: a table material or one's own values, with overrides.

    The first body is ``material`` (a table name, ``'A/B'``, or a :class:`Material`) with
    ``E`` and ``nu`` replacing its values, or, without ``material``, a body of its own
    from ``E`` and ``nu`` (both needed).  The second body is the rigid flat, unless
    ``material`` names a pair (``'Au/Au'``) or ``material2``, ``E2``, ``nu2`` give one (the
    same rules); two bodies become their equivalent body by :func:`pair`.  ``b``, ``w``,
    ``h`` and ``sigma0`` then replace the contact's values.  Every value is checked here,
    once, and errors name the parameter.

    Parameters
    ----------
    material : str or Material, optional
        The first body (``'Au'``: gold on a rigid flat) or a pair (``'Au/Au'``, or a
        :func:`pair`).
    E : float, pint.Quantity or str, optional
        Young's modulus of the first body (Pa), > 0.
    nu : float, optional
        Poisson's ratio of the first body, -1 < nu < 0.5.
    material2 : str or Material, optional
        The second body (one body; not with a pair in ``material``).
    E2 : float, pint.Quantity or str, optional
        Young's modulus of the second body (Pa), > 0.
    nu2 : float, optional
        Poisson's ratio of the second body, -1 < nu2 < 0.5.
    b : float, pint.Quantity or str, optional
        Burgers vector (m), > 0.  Default: the body's (a pair's common one).
    w : float, pint.Quantity or str, optional
        Work of adhesion of the interface (J/m^2), >= 0.  Default: the table's (for a
        pair of two different bodies none, unless the table lists the pair).
    h : float, pint.Quantity or str, optional
        Dugdale range (m), > 0; replaces a Dugdale stress of ``material``.
    sigma0 : float, pint.Quantity or str, optional
        Dugdale stress (Pa), > 0, an alternative to ``h`` (:math:`h = w/\sigma_0`).

    Returns
    -------
    Material
        One body (``bodies == ()``, on a rigid flat) or the equivalent body of a pair
        (``bodies`` holds the two, with their own ``E`` and ``nu``).

    Raises
    ------
    TypeError
        If ``material`` or ``material2`` is neither a Material nor a string.
    ValueError
        For an unknown name, a value out of range (the message names it), neither
        ``material`` nor ``E`` and ``nu``, a second body given twice, or a pair with
        different Burgers vectors and no ``b``.

    References
    ----------
    Johnson, *Contact Mechanics* (1985) §4.2 (two bodies); Adams et al., Eqs (2), (14)-(16).

    Examples
    --------
    >>> contact_material("Au", w=0.1).w
    0.1
    >>> m = contact_material(E=70e9, nu=0.2, b=2.5e-10, w=0.05)
    >>> round(m.E_star / 1e9, 3)
    72.917
    >>> contact_material("Au", material2="Au").E_star == contact_material("Au/Au").E_star
    True
    """
    E, E2 = (check_optional_positive(x, n, "Pa") for x, n in ((E, "E"), (E2, "E2")))
    nu, nu2 = (None if x is None else check_scalar_poisson(x, n) for x, n in ((nu, "nu"), (nu2, "nu2")))
    b, h = (check_optional_positive(x, n, "m") for x, n in ((b, "b"), (h, "h")))
    w = check_optional_positive(w, "w", "J/m^2", allow_zero=True)
    sigma0 = check_optional_positive(sigma0, "sigma0", "Pa")
    first, second, pair_w = _first_and_second(material, material2)
    one = _body(first, E, nu, E_name="E", nu_name="nu", label="body")
    if one is None:
        raise ValueError("give a material (a table name such as 'Au', or 'A/B') or a body of your own "
                         "with E and nu")
    two = _body(second, E2, nu2, E_name="E2", nu_name="nu2", label="body 2")
    body = one if two is None else pair(one, two, w=pair_w, b=b)
    if sigma0 is None and h is None:  # keep the body's Dugdale law (re-derived from sigma0 if w changes)
        h, sigma0 = (None, body.sigma0) if body.sigma0 is not None else (body.h, None)
    return replace(body, b=body.b if b is None else b, w=body.w if w is None else w, h=h, sigma0=sigma0)
