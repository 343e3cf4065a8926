"""Independent, slow, high-precision reference implementation of the model.

This package re-derives the multi-asperity contact / adhesion / friction model of
the paper ("A Nano-Scale Multi-Asperity Contact and Friction Model", section
*Development of the Model*, Eqs. 2-18 and 21) directly from the equations.  It
deliberately shares **no code** with the fast path of :mod:`asperity`; it
imports only :mod:`numpy`, :mod:`scipy`, :mod:`mpmath`, :mod:`math` and
:mod:`functools`.  Its purpose is to serve as an oracle against which the fast
(vectorised, tabulated / interpolated) implementation can be tested.

How it differs from the fast path
---------------------------------
* The Maugis-Dugdale (MD) relations (Eqs. 11-13) are evaluated with
  :mod:`mpmath` at an adaptive working precision (34 digits plus two digits per
  decade that ``t = sqrt(m**2 - 1)`` is away from 1), so the cancellation near
  ``m -> 1`` (where the first bracket of Eq. 11 is ``(4/3) t**3``) and near
  ``A_M -> 0`` is harmless.
* Every asperity is solved *individually*: for each penetration the stable
  displacement-controlled branch is found by a bracketed root solve in
  ``log t`` followed by Newton polishing in multiple precision.  Nothing is
  tabulated or interpolated.  Results are cached on the exact floating-point
  inputs only (no rounding of keys).
* The Greenwood-Williamson integrals (Eqs. 5, 6, 10, 18, 21) are computed with
  adaptive Gauss-Kronrod quadrature (:func:`scipy.integrate.quad`,
  ``epsabs=0``, ``epsrel=1e-11``) in the variable ``s`` with
  ``u = u_end + s**2``, which removes the square-root behaviour of the MD
  solution at the end of the stable branch, and with the integration range
  split at every kink: the Hurtado-Kim transition radii ``a_bar = a1, a2``
  and the sign change(s) of the per-asperity MD load.
* Load-controlled quantities (:func:`load_point`, :func:`pull_off`) are found
  by scanning and bracketing root solves / bounded minimisation on top of
  :func:`separation_point`, i.e. by brute force.

Conventions (all quantities per asperity, i.e. divided by ``N``)
----------------------------------------------------------------
* ``d`` is the separation in units of ``sigma``; asperity heights ``z`` have the
  standard normal density ``phi`` (Eq. 19); penetration ``u = z - d``.
* Hertz (``gamma == 0``): ``a_bar = beta*sqrt(u)`` (Eq. 8) and
  ``P_bar = (4/3) (2/(1-nu)) alpha beta**2 u**1.5`` (Eq. 6) for ``u > 0``.
* Adhesion (``gamma > 0``): Maugis-Dugdale with ``lambda`` from Eq. 15 and the
  conversions of Eq. 17, with the corrected load scale
  ``P_hat = (1-nu) alpha / (2 pi beta gamma)`` (the paper prints ``alpha**2``;
  see :func:`conversion_factors`).  Only the stable displacement-controlled
  branch (``dDelta_M/dA_M > 0``) carries load; asperities beyond its end carry
  nothing.
* Friction per asperity: ``F_f/(G b**2) = 2 pi tau_bar(a_bar) a_bar**2``
  (the integrand of Eq. 10) with the Hurtado-Kim law of Eq. 2.

Modules mirror the ones they check: :mod:`.maugis_dugdale`, :mod:`.maugis_dugdale_branch` and
:mod:`.maugis_dugdale_load` (mpmath), :mod:`.friction_stress`, :mod:`.groups` and
:mod:`.gw_moment` (``gw_moment``), :mod:`.multi_asperity` (``separation_point``, ``load_point``,
``pull_off``),
:mod:`.elastic_plastic` (the Jackson-Green asperity with the Nix-Gao size effect and its
integrals) and :mod:`.cycle` (``approach_point``, ``retract_point``, ``cycle_energy``,
``retract_pull_off``: loading-unloading cycles); :mod:`.common` holds mpmath and the input
checks.  This package re-exports their public names.
"""

from .cycle import approach_point, cycle_energy, retract_point, retract_pull_off
from .elastic_plastic import jg_asperity, jg_critical_penetration, jg_load_point, jg_separation_point
from .friction_stress import hk_tau
from .groups import conversion_factors
from .gw_moment import gw_moment
from .maugis_dugdale import md_curve, md_lambda_c
from .maugis_dugdale_branch import md_branch_end, md_point, md_pull_off
from .maugis_dugdale_load import md_load_point
from .multi_asperity import load_point, pull_off, separation_point

__all__ = [
    "approach_point",
    "conversion_factors",
    "cycle_energy",
    "gw_moment",
    "hk_tau",
    "jg_asperity",
    "jg_critical_penetration",
    "jg_load_point",
    "jg_separation_point",
    "load_point",
    "md_branch_end",
    "md_curve",
    "md_lambda_c",
    "md_load_point",
    "md_point",
    "md_pull_off",
    "pull_off",
    "retract_point",
    "retract_pull_off",
    "separation_point",
]
