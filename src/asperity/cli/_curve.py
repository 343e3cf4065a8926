"""What ``asperity load`` and ``asperity separation`` share: lists, the model or contact, output.

A curve command takes its points either dimensionless (``--P``, ``--d``, with
``--alpha``/``--beta``) or physical (``--load``, ``--separation``, with units and a
physical contact), asks the library for the curve, and writes it (and ``--plot``).
"""

from __future__ import annotations

import sys

from ._args import UsageError, contact_from_args, is_physical, model_from_args, parse_list, quantity_list, title
from ._output import curve_rows, format_rows, output_format, write_outputs

__all__ = ["run_curve"]

#: kind -> (dimensionless option, physical option, SI unit, log-spaced ranges)
KINDS = {
    "separation": ("d", "separation", "m", False),
    "load": ("P", "load", "N", True),
}


def run_curve(args, kind: str) -> None:
    """Compute the ``kind`` curve (``'load'`` or ``'separation'``) of ``args`` and write it."""
    dimless_opt, phys_opt, unit, log = KINDS[kind]
    physical = is_physical(args)
    names = (f"--{dimless_opt}", f"--{phys_opt}")
    dimless, phys = getattr(args, dimless_opt), getattr(args, phys_opt)
    text = phys if physical else dimless
    if text is None or (phys if not physical else dimless) is not None:
        want, other = (names[1], names[0]) if physical else names
        raise UsageError(f"give {want} LIST" + (f" (not {other}) with --material" if physical
                                               else f" (or --material ... with {names[1]})"))
    if physical:
        values = quantity_list(text, unit, log=log, name=names[1])
        curve = getattr(contact_from_args(args), f"{kind}_curve")(values)
    else:
        values = parse_list(text, log=log, name=names[0])
        curve = getattr(model_from_args(args), f"{kind}_curve")(values)

    def plot(path, fmt):
        from ._plot import plot_curve

        plot_curve(curve, path, fmt, x="d" if kind == "separation" else "P", title=title(args),
                   physical=physical)

    text = format_rows(curve_rows(curve), output_format(args))
    write_outputs(text, args, plot=plot)
    if physical:
        for warning in curve.validity_warnings():
            print(f"asperity: note: {warning}", file=sys.stderr)
