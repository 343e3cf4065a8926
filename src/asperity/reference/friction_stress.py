"""Reference for :mod:`asperity.friction_stress`: the Hurtado-Kim friction stress (Eq 2), scalar."""

from __future__ import annotations

import math

__all__ = ["hk_tau"]


def hk_tau(a_bar, *, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4):
    """Hurtado-Kim dimensionless friction stress ``tau_bar(a_bar)`` (Eq. 2).

    ``tau_f1`` for ``a_bar <= a1``, ``tau_f2`` for ``a_bar >= a2`` and the straight
    line in log-log coordinates between ``(a1, tau_f1)`` and ``(a2, tau_f2)``
    (slope ``M`` of Eq. 3) in between.

    Parameters
    ----------
    a_bar : float
        Dimensionless contact radius ``a/b`` (>= 0).
    tau_f1, tau_f2, a1, a2 : float, optional
        Hurtado-Kim constants.

    Returns
    -------
    float
    """
    if a_bar <= a1:
        return float(tau_f1)
    if a_bar >= a2:
        return float(tau_f2)
    slope = math.log(tau_f2 / tau_f1) / math.log(a2 / a1)
    return float(tau_f1 * math.exp(slope * math.log(a_bar / a1)))
