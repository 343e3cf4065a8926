r"""What a physical contact states about itself: the contact computed, as data and as text.

Every physical result of asperity says which contact it was computed for (issue #7: "gold on
gold" is one gold body on a rigid flat with ``'Au'`` and two gold bodies with ``'Au/Au'``,
1.6x apart).  :class:`ContactDescription` gives :class:`asperity.physical.PhysicalContact`
its :meth:`~ContactDescription.to_dict` (strict JSON, SI units, the registry's names) and
its six-line :meth:`~ContactDescription.describe` (printed as ``#`` lines at the top of
every command-line result): both bodies, :math:`E^*`, :math:`G^*`, :math:`w`, :math:`h`,
:math:`b`, the surface and :math:`N = \eta A_0`, the groups of Eqs (7), (15), (16) with
:math:`\lambda` and its adhesion regime, the friction law, the per-asperity law with the
hardness and plasticity index, and the asperity interaction.

References
----------
.. [1] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction model",
   Eqs (7), (14)-(16).
"""

from __future__ import annotations

from .friction_stress import ConstantShear, HurtadoKim
from .heights import GAUSSIAN
from .quantities import PHYSICAL_PARAMETERS
from .units import format_si

__all__ = ["ContactDescription"]


class ContactDescription:
    """The contact computed, as data (:meth:`to_dict`) and as text (:meth:`describe`).

    A base of :class:`asperity.physical.PhysicalContact`, which supplies the attributes read
    here (``material``, ``surface``, the moduli, the groups, the laws); not used on its own.
    """

    def to_dict(self) -> dict:
        r"""The contact computed, as plain data for strict JSON (SI units, names of the registry).

        Keys: ``material``; ``body1`` and ``body2`` (``{'name', 'E_Pa', 'nu', 'rigid'}``;
        ``body2`` is ``{'name': 'rigid flat', 'rigid': True, ...}`` for one body on a flat);
        ``E_star_Pa``, ``G_star_Pa``, ``G_Pa``, ``nu`` (effective), ``b_m``, ``w_J_m2``,
        ``h_m``; the surface ``sigma_s_m``, ``R_m``, ``eta_per_m2``, ``area_m2``,
        ``surface_source``, ``N``; the groups ``alpha``, ``beta``, ``gamma``, ``lambda``,
        ``h_over_b``, the adhesion ``regime``; ``friction`` (``{'law': 'Hurtado-Kim',
        'tau_f1', 'tau_f2', 'a1', 'a2'}`` or ``{'law': 'constant shear', 'tau', 'tau_Pa'}``);
        the units ``force_scale_N`` (:math:`NGb^2`) and ``area_scale_m2`` (:math:`N\pi b^2`);
        the asperity ``interaction`` (``'none'`` or ``'cgp2008'``); the per-asperity ``law``
        (``'elastic'`` or ``'jackson-green'``), the hardness ``H_Pa`` (:math:`H_0` with the size
        effect; None if unknown), the Nix-Gao ``h_star_m`` (0 without the size effect), the
        plasticity index ``psi`` and ``critical_interference_m`` :math:`\omega_c` (None without
        a hardness) and ``plastic_threshold`` (the yield check's share); the summit ``heights``
        distribution (its ``--heights`` spelling, e.g. ``'gaussian'``).
        """
        s, body = self.surface, self.material.to_dict()
        si = {name: PHYSICAL_PARAMETERS[name].si_name for name in PHYSICAL_PARAMETERS}
        return {"material": self.material.name, "body1": body["body1"], "body2": body["body2"],
                si["E_star"]: self.E_star, si["G_star"]: self.G_star, "G_Pa": self.G, "nu": self.nu,
                si["b"]: self.b, si["w"]: self.w, si["h"]: self.h, si["sigma_s"]: s.sigma_s, si["R"]: s.R,
                si["eta"]: s.eta, si["area"]: s.area, "surface_source": s.source, "N": self.N,
                "alpha": self.alpha, "beta": self.beta, "gamma": self.gamma, "lambda": self.lam,
                "h_over_b": self.h_over_b, "regime": self.regime, "friction": self._friction_dict(),
                "force_scale_N": self.force_scale, "area_scale_m2": self.area_scale,
                "interaction": self.interaction.name, "law": self.law, si["hardness"]: self.hardness,
                si["h_star"]: self.h_star, "psi": None if self.hardness is None else self.plasticity_index,
                "critical_interference_m": self.critical_interference, "plastic_threshold": self.plastic_threshold,
                "heights": self.heights.spec or repr(self.heights)}

    def parameters(self) -> dict:
        """Inputs, groups and scales (SI units): :meth:`to_dict`."""
        return self.to_dict()

    def _friction_dict(self) -> dict:
        law = HurtadoKim() if self.friction is None else self.friction
        if isinstance(law, HurtadoKim):
            return {"law": "Hurtado-Kim", "tau_f1": law.tau_f1, "tau_f2": law.tau_f2, "a1": law.a1, "a2": law.a2}
        if isinstance(law, ConstantShear):
            return {"law": "constant shear", "tau": law.tau, "tau_Pa": law.tau * self.G_star}
        return {"law": repr(law)}

    def describe(self) -> str:
        """The contact computed, in six lines: bodies; moduli and adhesion; surface; groups; friction;
        the per-asperity law with the hardness and plasticity index, and the asperity interaction.

        Command-line results print these lines at their top (as ``#`` comments).

        Examples
        --------
        >>> from asperity.physical import PhysicalContact, Surface
        >>> c = PhysicalContact("Au/Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
        >>> print(c.describe())  # doctest: +NORMALIZE_WHITESPACE
        contact: Au (E 78 GPa, nu 0.44) on Au (E 78 GPa, nu 0.44)
        E* = 48.36 GPa, G* = 27.08 GPa, w = 3.012 J/m^2, h = 288.5 pm, b = 288.5 pm
        surface: sigma_s = 2 nm, R = 1 um, eta = 1e+12 1/m^2, A0 = 1e-06 m^2, N = 1e+06 summits
        groups: alpha = 0.04472, beta = 155, gamma = 0.2159, lambda = 6.139 (JKR), h/b = 1
        friction: Hurtado-Kim, tau_f1 = 0.02326, tau_f2 = 0.0007752, a1 = 28, a2 = 8e+04 (stresses in G*)
        law: elastic, H = 188 MPa, psi = 11.5, omega_c = 14.82 pm (notes above 1 % of the contacts
        past omega_c); interaction: none
        """
        s, f = self.surface, self._friction_dict()
        plain = "Hertz" if self.law == "elastic" else "Jackson-Green"
        w = f"w = {format_si(self.w, 'J/m^2')}" if self.w > 0 else f"w = 0 (no adhesion: {plain})"
        surface = (f"surface: sigma_s = {format_si(s.sigma_s, 'm')}, R = {format_si(s.R, 'm')}, "
                   f"eta = {s.eta:.4g} 1/m^2, A0 = {s.area:.4g} m^2, N = {self.N:.4g} summits"
                   + (f", heights {self.heights.spec}" if self.heights is not GAUSSIAN and self.heights.spec else "")
                   + (f" [{s.source}]" if s.source else ""))
        if f["law"] == "Hurtado-Kim":
            constants = ", ".join(f"{k} = {f[k]:.4g}" for k in ("tau_f1", "tau_f2", "a1", "a2"))
            friction = f"friction: Hurtado-Kim, {constants} (stresses in G*)"
        elif f["law"] == "constant shear":
            friction = (f"friction: constant shear strength tau = {format_si(f['tau_Pa'], 'Pa')} "
                        f"(tau/G* = {f['tau']:.4g})")
        else:
            friction = f"friction: {f['law']}"
        return "\n".join([
            f"contact: {self.material.describe()}",
            f"E* = {format_si(self.E_star, 'Pa')}, G* = {format_si(self.G_star, 'Pa')}, {w}, "
            f"h = {format_si(self.h, 'm')}, b = {format_si(self.b, 'm')}",
            surface,
            f"groups: alpha = {self.alpha:.4g}, beta = {self.beta:.4g}, gamma = {self.gamma:.4g}, "
            f"lambda = {self.lam:.4g} ({self.regime if self.gamma else 'no adhesion: ' + plain}), "
            f"h/b = {self.h_over_b:.4g}",
            friction,
            self._describe_law(),
        ])

    def _describe_law(self) -> str:
        """The sixth line of :meth:`describe`: law, hardness, plasticity index, interaction."""
        law = f"law: {self.law}"
        if self.hardness is None:
            law += " (no hardness: no yield check)" if self.law == "elastic" else ""
        else:
            size = f" (H0), h* = {format_si(self.h_star, 'm')}" if self.h_star > 0 else ""
            law += f", H = {format_si(self.hardness, 'Pa')}{size}, psi = {self.plasticity_index:.4g}"
            if self.critical_interference is not None:
                law += f", omega_c = {format_si(self.critical_interference, 'm')}"
            if self.law == "elastic":
                law += (f" (notes above {100 * self.plastic_threshold:g} % of the contacts past omega_c)"
                        if self.critical_interference is not None else "")
        return f"{law}; interaction: {self.interaction.name}"
